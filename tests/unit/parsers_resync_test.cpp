// Resynchronisation of the framers after false headers, cut frames and junk (issue 21): a PD0 or Xbus
// length that points past the bytes held must not swallow the frames that follow, on a live line
// (later valid frames are preferred) or at the end of a file (the held bytes are rescanned); the text
// protocols recover after junk on the same line, a bare CR, NUL and non-ASCII bytes.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "drivers/parsers/candump_line.h"
#include "drivers/parsers/frame_pump.h"
#include "drivers/parsers/line_framer.h"
#include "drivers/parsers/nmea0183_sentence.h"
#include "drivers/parsers/pd0_framer.h"
#include "drivers/parsers/pd6_sentence.h"
#include "drivers/parsers/wl_dvl_protocol.h"
#include "drivers/parsers/xbus_framer.h"
#include "tests/support/sensor_frames.h"

namespace deepnav {
namespace {

using Bytes = std::vector<uint8_t>;

struct Frame {
  uint64_t offset = 0;
  Bytes bytes;
};

struct Framing {
  std::vector<Frame> frames;
  size_t live_frames = 0;  // frames returned before endOfInput()
  std::vector<FrameError> errors;
};

// Feeds `stream` in chunks of `chunk` bytes, then (when `end`) declares the end of the input.
template <typename Framer>
Framing frameStream(Framer* framer, const Bytes& stream, size_t chunk, bool end = true) {
  Framing r;
  size_t pos = 0;
  const auto feed = [&](Framer* fr) {
    if (pos == stream.size()) return false;
    pos += fr->push(stream.data() + pos, std::min(chunk, stream.size() - pos));
    return true;
  };
  const auto on_frame = [&](const RawFrame& f) { r.frames.push_back({f.offset, Bytes(f.data, f.data + f.size)}); };
  const auto on_bad = [&](const FrameError& e) { r.errors.push_back(e); };
  frameWhileFed(framer, feed, on_frame, on_bad);
  r.live_frames = r.frames.size();
  if (end) frameTheRest(framer, on_frame, on_bad);
  return r;
}

// Every intact frame (its offset and bytes) is among the framed ones.
int missing(const Framing& r, const std::vector<Frame>& intact) {
  int n = 0;
  for (const Frame& want : intact) {
    bool found = false;
    for (const Frame& got : r.frames) found = found || (got.offset == want.offset && got.bytes == want.bytes);
    n += !found;
  }
  return n;
}

Bytes pd0(uint16_t ensemble) {
  test::Pd0Spec s;
  s.ensemble = ensemble;
  s.heading_cdeg = uint16_t(100 * ensemble);
  return test::buildPd0(s);
}

Bytes xbus(uint16_t counter) {
  const float q[4] = {1, 0, 0, 0}, acc[3] = {0, 0, 9.81f}, gyr[3] = {0, 0, 0.01f * counter};
  return test::buildMtData2(counter, q, acc, gyr);
}

void append(Bytes* stream, const Bytes& b, std::vector<Frame>* intact = nullptr) {
  if (intact != nullptr) intact->push_back({stream->size(), b});
  stream->insert(stream->end(), b.begin(), b.end());
}

TEST(Pd0Resync, FalseHeaderBeforeTheStreamCostsNoEnsemble) {
  for (const uint16_t claimed : {uint16_t(0xFFFF), uint16_t(4000)}) {
    Bytes stream = {0x7F, 0x7F, uint8_t(claimed & 0xFF), uint8_t(claimed >> 8)};
    std::vector<Frame> intact;
    for (uint16_t i = 1; i <= 10; ++i) append(&stream, pd0(i), &intact);
    Pd0Framer framer;
    ASSERT_TRUE(framer.init(65535));
    const Framing r = frameStream(&framer, stream, 61);
    EXPECT_EQ(missing(r, intact), 0) << "claimed " << claimed;
    EXPECT_EQ(r.frames.size(), 10u);
    ASSERT_FALSE(r.errors.empty());
    EXPECT_EQ(r.errors[0].offset, 0u);
    EXPECT_EQ(r.errors[0].skipped, 4u);
    // Live: every ensemble is framed before the end of the input (the first once the header of the
    // second has arrived), not held back for the 4000 or 65535 bytes the header claims.
    EXPECT_EQ(r.live_frames, 10u) << "claimed " << claimed;
  }
}

TEST(Pd0Resync, LiveLineDoesNotWaitForTheFalseLength) {
  // The decoder's buffer (8192): a false header claiming 8000 bytes, then ensembles arriving slowly.
  Bytes stream = {0x7F, 0x7F, 0x40, 0x1F, 0x00, 0x03};
  std::vector<Frame> intact;
  for (uint16_t i = 1; i <= 20; ++i) append(&stream, pd0(i), &intact);
  Pd0Framer framer;
  ASSERT_TRUE(framer.init(8192));
  const Framing r = frameStream(&framer, stream, 13, false);
  EXPECT_EQ(r.frames.size(), 20u);
  EXPECT_EQ(missing(r, intact), 0);
}

// Ensembles where every fifth is damaged: its length field, a cut, junk with a false header, or a
// flipped byte; none of the intact ones may be lost.
Bytes mixedStream(const std::vector<Bytes>& frames, uint32_t seed, std::vector<Frame>* intact, uint8_t h0, uint8_t h1) {
  std::mt19937 rng(seed);
  Bytes stream;
  for (size_t i = 0; i < frames.size(); ++i) {
    Bytes f = frames[i];
    if (i % 5 != 2) {
      append(&stream, f, intact);
      continue;
    }
    switch ((i / 5) % 4) {
      case 0: f[2] = uint8_t(rng()), f[3] = uint8_t(rng() | 0x80); break;  // length beyond the data
      case 1: f.resize(f.size() / 2); break;                              // cut short
      case 2: f = {h0, h1, 0xF0, 0x7F, uint8_t(rng()), uint8_t(rng())}; break;
      default: f[f.size() / 3] ^= 0x10; break;
    }
    append(&stream, f);
  }
  return stream;
}

TEST(Pd0Resync, MixedIntactAndCorruptedEnsembles) {
  std::vector<Bytes> frames;
  for (uint16_t i = 1; i <= 107; ++i) frames.push_back(pd0(i));
  std::vector<Frame> intact;
  const Bytes stream = mixedStream(frames, 7, &intact, 0x7F, 0x7F);
  ASSERT_EQ(intact.size(), 86u);
  for (const size_t chunk : {size_t(65536), size_t(97), size_t(1)}) {
    Pd0Framer framer;
    ASSERT_TRUE(framer.init(65535));
    const Framing r = frameStream(&framer, stream, chunk);
    EXPECT_EQ(missing(r, intact), 0) << "chunk " << chunk;
    EXPECT_EQ(r.frames.size(), 86u);
    EXPECT_FALSE(r.errors.empty());
  }
}

std::vector<Bytes> realEnsembles(const Bytes& file) {
  std::vector<Bytes> out;
  for (size_t at = 0; at + 4 <= file.size();) {
    const size_t n = size_t(file[at + 2] | (file[at + 3] << 8)) + 2;
    out.emplace_back(file.begin() + long(at), file.begin() + long(std::min(at + n, file.size())));
    at += n;
  }
  return out;
}

TEST(Pd0Resync, RealCaptureBehindAFalseHeaderAndMixed) {
  const char* env = std::getenv("DEEPNAV_SHARED_DATA");
  const std::filesystem::path path = env ? std::filesystem::path(env) / "dvl" / "LA100204.PD0" : std::filesystem::path();
  if (path.empty() || !std::filesystem::exists(path)) GTEST_SKIP() << "DEEPNAV_SHARED_DATA not set";
  std::ifstream in(path, std::ios::binary);
  const Bytes file{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::vector<Bytes> frames = realEnsembles(file);
  ASSERT_EQ(frames.size(), 107u);
  Bytes stream = {0x7F, 0x7F, 0xFF, 0xFF};
  std::vector<Frame> intact;
  for (const Bytes& f : frames) append(&stream, f, &intact);
  Pd0Framer framer;
  ASSERT_TRUE(framer.init(65535));
  Framing r = frameStream(&framer, stream, 65536);
  EXPECT_EQ(missing(r, intact), 0);
  EXPECT_EQ(r.frames.size(), 107u);
  intact.clear();
  const Bytes mixed = mixedStream(frames, 11, &intact, 0x7F, 0x7F);
  ASSERT_EQ(intact.size(), 86u);
  ASSERT_TRUE(framer.init(65535));
  r = frameStream(&framer, mixed, 65536);
  EXPECT_EQ(missing(r, intact), 0);
}

TEST(XbusResync, FalseLengthAndMixedMessages) {
  Bytes stream = {0xFA, 0xFF, 0x36, 0xFF, 0x07, 0xD0};  // extended length 2000
  std::vector<Frame> intact;
  for (uint16_t i = 1; i <= 10; ++i) append(&stream, xbus(i), &intact);
  XbusFramer framer;
  ASSERT_TRUE(framer.init(2048));
  Framing r = frameStream(&framer, stream, 7);
  EXPECT_EQ(missing(r, intact), 0);
  EXPECT_EQ(r.frames.size(), 10u);
  EXPECT_EQ(r.live_frames, 10u);
  std::vector<Bytes> frames;
  for (uint16_t i = 1; i <= 107; ++i) frames.push_back(xbus(i));
  intact.clear();
  stream = mixedStream(frames, 3, &intact, 0xFA, 0xFF);
  for (const size_t chunk : {size_t(65536), size_t(5)}) {
    ASSERT_TRUE(framer.init(65535));
    r = frameStream(&framer, stream, chunk);
    EXPECT_EQ(missing(r, intact), 0) << "chunk " << chunk;
  }
}

// Found by fuzz_xsens: junk ending with a false preamble whose length runs into the first intact
// message and whose 8-bit checksum happens to hold (it swallowed that message), also behind a false
// preamble whose length runs past the end of the input, and after a chain of tiny messages that hold.
TEST(XbusResync, FalseMessageWhoseChecksumHoldsDoesNotSwallowTheNext) {
  const Bytes junks[] = {{0xfa, 0xff, 0x36, 0x0f, 0x10, 0x20, 0xfa, 0xff, 0x00, 0x41, 0x19, 0x00,
                          0x00, 0x04, 0x00, 0x00, 0x00, 0x0a, 0x01, 0x1c, 0xf5, 0xc0, 0xc3, 0x00},
                         {0xff, 0x20, 0xfa, 0xff, 0x24, 0x3d, 0xfa, 0xff, 0x20, 0xfa,
                          0xff, 0x24, 0x3d, 0xfa, 0xff, 0x00, 0x01, 0x00, 0x00, 0x10},
                         // a chain of 5-byte messages that hold, then one whose length runs into the third intact one
                         {0xfa, 0x14, 0x00, 0xff, 0xfa, 0x75, 0xfa, 0x19, 0xfa, 0xff, 0x00, 0x71,
                          0xfa, 0xff, 0x01, 0x00, 0x00, 0xfa, 0xff, 0x59, 0xfa, 0xff, 0x01, 0x00,
                          0x71, 0x3a, 0xfa, 0xff, 0x01, 0x00, 0x00, 0xfa, 0xff, 0x59, 0x00, 0xff,
                          0xfc, 0x3d, 0xff, 0x23, 0xfa, 0x3a, 0x00, 0xff, 0xfa, 0xff, 0x00, 0x57,
                          0x00, 0x00, 0x00, 0x00, 0x80, 0xbf, 0xfa, 0xff, 0x00, 0xfa, 0xff, 0x01,
                          0x00, 0x00, 0xfa, 0xff, 0x21, 0x59, 0x14, 0xfa, 0xff, 0x00, 0xfa, 0xff,
                          0x01, 0x00, 0x00, 0xfa, 0xff, 0x59, 0x00, 0xff, 0xf9, 0xff, 0xfa, 0xff,
                          0x00, 0xbf, 0xfa, 0xff, 0xf9, 0x28, 0x3d, 0x41, 0x80, 0x00, 0xfa, 0x4c,
                          0xfa, 0xff, 0xff, 0xff, 0xff, 0x71, 0x3a, 0xfa, 0xff, 0x01, 0x00, 0x00,
                          0xfa, 0xff, 0x59, 0x00, 0xff, 0xf9, 0x02, 0xfa, 0xfa, 0xfb, 0x00}};
  for (const Bytes& junk : junks) {
    Bytes stream = junk;
    std::vector<Frame> intact;
    const float q[4] = {1, 0, 0, 0}, acc[3] = {0, 0, 9.81f}, gyr[3] = {0.01f, 0, 0.5f};
    for (uint16_t i = 1; i <= 3; ++i) append(&stream, test::buildMtData2(i, q, acc, gyr), &intact);
    for (const size_t chunk : {size_t(65536), size_t(3)}) {
      XbusFramer framer;
      ASSERT_TRUE(framer.init(65535));
      framer.waitForCertainty();  // as deepnav decode reads a file
      const Framing r = frameStream(&framer, stream, chunk);
      EXPECT_EQ(missing(r, intact), 0) << "chunk " << chunk;
    }
  }
}

Bytes text(const std::string& s) { return Bytes(s.begin(), s.end()); }

std::vector<std::string> framedLines(LineFramer* framer, const std::string& s, size_t chunk) {
  std::vector<std::string> out;
  for (const Frame& f : frameStream(framer, text(s), chunk).frames) out.emplace_back(f.bytes.begin(), f.bytes.end());
  return out;
}

int nmeaValid(const std::vector<std::string>& lines) {
  int n = 0;
  for (const std::string& l : lines) {
    Nmea0183Sentence s;
    const char* why = "";
    n += parseNmea0183Sentence(l, true, &s, &why);
  }
  return n;
}

TEST(LineResync, NmeaAfterJunkBareCrNulAndNonAscii) {
  const std::string a = test::nmeaSentence("HEHDT,274.07,T"), b = test::nmeaSentence("HEHDT,12.5,T");
  const std::string bare_cr = a.substr(0, a.size() - 1);  // "...*hh\r" with no LF
  const std::string cases[] = {
      "junk" + a + b,
      "$GPGGA,12" + a + b,           // a cut sentence before
      bare_cr + b,                    // bare CR between sentences
      std::string("\x00\xff\x80", 3) + a + b,
      "$HEHDT,1\x00" "2,T*00\r\n" + a + b,
      "\xc3\xa9t\xc3\xa9 " + a + b,
      bare_cr + b.substr(0, b.size() - 2),  // the last line without a terminator
  };
  for (const std::string& c : cases) {
    for (const size_t chunk : {size_t(1), size_t(5), size_t(4096)}) {
      LineFramer framer;
      ASSERT_TRUE(framer.init("$!", 120));
      EXPECT_EQ(nmeaValid(framedLines(&framer, c, chunk)), 2) << c << " chunk " << chunk;
    }
  }
}

TEST(LineResync, Pd6AfterJunkAndBareCr) {
  const std::string bi = ":BI,  +100,  -500,   +20,     5,A", bd = ":BD,     +12.30,     -4.50,      0.20,  8.25,  0.10";
  for (const std::string& c : {"noise" + bi + "\r" + bd + "\r", ":B" + bi + "\r\n\x01" + bd, std::string("\xff", 1) + bi + "\n" + bd}) {
    LineFramer framer;
    ASSERT_TRUE(framer.init(":", 120));
    int ok = 0;
    for (const std::string& l : framedLines(&framer, c, 3)) {
      Pd6Record r;
      const char* why = "";
      ok += parsePd6Line(l, &r, &why);
    }
    EXPECT_EQ(ok, 2) << c;
  }
}

TEST(LineResync, WaterLinkedAfterJunkOnTheSameLineAndBareCr) {
  const std::string wrz = test::wlSentence("wrz,0.100,0.200,0.010,y,1.90,0.002,1e-06;0;0;0;1e-06;0;0;0;1e-06,1000,1040,250.0,0");
  const std::string json = R"({"ts": 1.5, "x": 1, "y": 2, "z": 3, "std": 0.4, "roll": 0, "pitch": 0, "yaw": 90, "type": "position_local", "status": 0})";
  const std::string wrz_cr = wrz.substr(0, wrz.size() - 1);
  const std::string cases[] = {
      "hello world " + wrz + wrz,   // junk holding a 'w' on the same line
      "ww" + wrz + wrz,
      wrz_cr + wrz_cr + "\n",        // bare CR
      "{\"cut\": " + wrz + wrz,      // a JSON object cut short
      "wrz,0.1,0.2" + json + "\n" + wrz,  // a cut sentence before a JSON report
      std::string("\x00\xfe", 2) + wrz + wrz,
  };
  for (const std::string& c : cases) {
    LineFramer framer;
    ASSERT_TRUE(framer.init("w{", 4096, true, "{"));
    int decoded = 0;
    for (const std::string& l : framedLines(&framer, c, 7)) {
      WlDvlReport r;
      const char* why = "";
      size_t junk = 0;
      decoded += parseWlDvlLine(l, &r, &why, &junk) == WlDecode::kDecoded;
    }
    EXPECT_EQ(decoded, 2) << c;
  }
}

TEST(CandumpResync, LineAfterAStrayByteOrJunkStillDecodes) {
  const std::string log = "(1436509052.249713) can0 09F8027F#00FCFFFF0000FFFF", dflt = "  can0  09F8027F   [8]  00 FC FF FF 00 00 FF FF";
  for (const std::string& base : {log, dflt}) {
    for (const std::string& junk : {std::string("\xff"), std::string("\x00", 1), std::string("(12"), std::string("x y z"),
                                    std::string("\x80\x81 can0 12 [1]")}) {
      CanFrame f;
      double t = 0;
      const char* why = "";
      size_t skipped = 0;
      ASSERT_EQ(parseCandumpLineAfterJunk(junk + base, &f, &t, &why, &skipped), CandumpLine::kFrame) << junk + base << ": " << why;
      EXPECT_EQ(f.id, 0x09F8027Fu);
      EXPECT_EQ(f.dlc, 8);
      EXPECT_EQ(f.data[1], 0xFC);
      EXPECT_GT(skipped, 0u);
    }
  }
  CanFrame f;
  double t = 0;
  const char* why = "";
  size_t skipped = 0;
  EXPECT_EQ(parseCandumpLineAfterJunk("garbage", &f, &t, &why, &skipped), CandumpLine::kInvalid);
}

}  // namespace
}  // namespace deepnav
