// `deepnav decode` as a user runs it: real captures from ../shared/data and generated captures for the
// formats without a public sample; one JSON object per message on stdout, bad frames on stderr with
// their byte offset.
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "tests/support/sensor_frames.h"
#include "tests/support/source_paths.h"
#include "tests/support/temp_path.h"

namespace deepnav {
namespace {

struct DecodeRun {
  int status = -1;
  std::vector<std::string> out;
  std::string err;
};

DecodeRun decode(const std::string& format, const std::string& file) {
  // ctest runs each test case in its own process, in parallel: names are per process and format.
  const std::string out = deepnav::testing::tempPath("decode_out_" + format + ".jsonl");
  const std::string err = deepnav::testing::tempPath("decode_err_" + format + ".txt");
  const std::string cmd = deepnav::testing::binDir() + "/deepnav decode " + format + " " + file + " > " + out + " 2> " + err;
  DecodeRun r;
  r.status = std::system(cmd.c_str());
  std::ifstream o(out);
  for (std::string line; std::getline(o, line);) r.out.push_back(line);
  std::stringstream e;
  e << std::ifstream(err).rdbuf();
  r.err = e.str();
  return r;
}

std::filesystem::path shared() { return deepnav::testing::sharedDataDir(); }

std::string writeTemp(const std::string& name, const std::string& bytes) {
  const std::string path = deepnav::testing::tempPath(name);
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

TEST(DecodeCli, Pd0CaptureAndTheCorruptedOne) {
  if (shared().empty() || !std::filesystem::exists(shared() / "dvl")) GTEST_SKIP() << "DEEPNAV_SHARED_DATA not set";
  DecodeRun r = decode("pd0", (shared() / "dvl" / "LA100204.PD0").string());
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(r.out.size(), 107u);
  int with_bt = 0;
  for (const auto& line : r.out) {
    const YAML::Node j = YAML::Load(line);  // each line is one JSON object
    ASSERT_TRUE(j.IsMap()) << line;
    with_bt += bool(j["bt_velocity_mps"]);
  }
  EXPECT_EQ(with_bt, 52);
  r = decode("pd0", (shared() / "dvl" / "LB180210_3_corrupted.PD0").string());
  ASSERT_EQ(r.status, 0);
  EXPECT_NE(r.err.find("byte 446: PD0 checksum mismatch"), std::string::npos) << r.err;
}

TEST(DecodeCli, Nmea2000CaptureHasEveryHeadingMessage) {
  if (shared().empty() || !std::filesystem::exists(shared() / "can")) GTEST_SKIP() << "DEEPNAV_SHARED_DATA not set";
  const DecodeRun r = decode("n2k-candump", (shared() / "can" / "candumpSample2.txt").string());
  ASSERT_EQ(r.status, 0) << r.err;
  int heading = 0, rate = 0, attitude = 0;
  for (const auto& line : r.out) {
    const YAML::Node j = YAML::Load(line);
    const int pgn = j["pgn"].as<int>();
    heading += pgn == 127250, rate += pgn == 127251, attitude += pgn == 127257;
    if (pgn == 127250) {
      EXPECT_TRUE(j["heading_rad"].IsDefined());
    }
  }
  EXPECT_EQ(heading, 46);
  EXPECT_EQ(rate, 46);
  EXPECT_EQ(attitude, 5);
}

TEST(DecodeCli, GeneratedCapturesWithBadFrames) {
  // PD6 with one malformed line.
  const std::string pd6 = ":SA, -2.31, +1.12,123.45\r\n:BI,  +100,  -500,   +20,     5,A\r\n:BI,  +1x0,  -500\r\n"
                          ":BD,     +12.30,     -4.50,      0.20,  8.25,  0.10\r\n";
  DecodeRun r = decode("pd6", writeTemp("c.pd6", pd6));
  ASSERT_EQ(r.status, 0);
  EXPECT_EQ(r.out.size(), 3u);
  EXPECT_NE(r.err.find("byte 61: PD6"), std::string::npos) << r.err;
  // Water Linked: serial and JSON lines, one with a wrong CRC.
  std::string wl = test::wlSentence("wrz,0.100,0.200,0.010,y,1.90,0.002,1e-06;0;0;0;1e-06;0;0;0;1e-06,1000,1040,250.0,0");
  std::string bad = test::wlSentence("wru,0,0.1,2.0,-40,-90");
  bad[5] = '9';
  wl += bad + R"({"ts": 1.5, "x": 1, "y": 2, "z": 3, "std": 0.4, "roll": 0, "pitch": 0, "yaw": 90, "type": "position_local", "status": 0})" "\n";
  r = decode("wl-a50", writeTemp("c.wl", wl));
  ASSERT_EQ(r.status, 0);
  ASSERT_EQ(r.out.size(), 2u);
  EXPECT_NEAR(YAML::Load(r.out[1])["yaw_rad"].as<double>(), M_PI / 2, 1e-8);
  EXPECT_NE(r.err.find("CRC-8 mismatch"), std::string::npos) << r.err;
  // Xsens: three messages, the second damaged.
  const float q[4] = {1, 0, 0, 0}, acc[3] = {0, 0, 9.81f}, gyr[3] = {0, 0, 0.5f};
  std::string xs;
  for (uint16_t i = 0; i < 3; ++i) {
    auto m = test::buildMtData2(i, q, acc, gyr);
    if (i == 1) m[10] ^= 0x40;
    xs.append(m.begin(), m.end());
  }
  r = decode("xsens", writeTemp("c.xs", xs));
  ASSERT_EQ(r.status, 0);
  ASSERT_EQ(r.out.size(), 2u);
  EXPECT_EQ(YAML::Load(r.out[1])["packet_counter"].as<int>(), 2);
  EXPECT_NE(r.err.find("Xbus checksum mismatch"), std::string::npos) << r.err;
}

// Issue 21: frames after a false header, in a mix with damaged ones, after junk on the same line or a
// stray byte; every intact one decoded, at its own offset.
std::string bytesOf(const std::vector<uint8_t>& v) { return std::string(v.begin(), v.end()); }

std::vector<long> offsets(const DecodeRun& r) {
  std::vector<long> out;
  for (const auto& line : r.out) out.push_back(YAML::Load(line)["offset"].as<long>());
  return out;
}

std::string builtPd0(uint16_t ensemble) {
  test::Pd0Spec s;
  s.ensemble = ensemble;
  return bytesOf(test::buildPd0(s));
}

std::string builtXbus(uint16_t counter) {
  const float q[4] = {1, 0, 0, 0}, acc[3] = {0, 0, 9.81f}, gyr[3] = {0, 0, 0.5f};
  return bytesOf(test::buildMtData2(counter, q, acc, gyr));
}

// frames[i] with every fifth damaged in turn: its length field, cut in half, replaced by a false
// header; the intact frames' offsets are returned in *intact.
std::string mixed(const std::vector<std::string>& frames, std::vector<long>* intact, const std::string& false_header) {
  std::string out;
  for (size_t i = 0; i < frames.size(); ++i) {
    std::string f = frames[i];
    if (i % 5 == 2) {
      if ((i / 5) % 3 == 0) f[3] = char(0xF0);
      if ((i / 5) % 3 == 1) f.resize(f.size() / 2);
      if ((i / 5) % 3 == 2) f = false_header;
    } else {
      intact->push_back(long(out.size()));
    }
    out += f;
  }
  return out;
}

TEST(DecodeCli, Pd0FalseHeaderAndMixedEnsemblesLoseNothing) {
  std::vector<std::string> frames;
  for (uint16_t i = 1; i <= 107; ++i) frames.push_back(builtPd0(i));
  std::string file = "\x7f\x7f\xff\xff";
  for (const auto& f : frames) file += f;
  DecodeRun r = decode("pd0", writeTemp("false.pd0", file));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.size(), 107u);
  EXPECT_NE(r.err.find("byte 0: PD0"), std::string::npos) << r.err;  // the 4 bytes are reported
  EXPECT_NE(r.err.find(": 107 messages, "), std::string::npos) << r.err;
  std::vector<long> intact;
  r = decode("pd0", writeTemp("mixed.pd0", mixed(frames, &intact, std::string("\x7f\x7f\x00\xf0\x01\x02", 6))));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(intact.size(), 86u);
  EXPECT_EQ(offsets(r), intact) << r.err;
}

TEST(DecodeCli, Pd0RealCaptureBehindAFalseHeader) {
  if (shared().empty() || !std::filesystem::exists(shared() / "dvl")) GTEST_SKIP() << "DEEPNAV_SHARED_DATA not set";
  std::ifstream in(shared() / "dvl" / "LA100204.PD0", std::ios::binary);
  const std::string capture{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  DecodeRun r = decode("pd0", writeTemp("real_false.pd0", "\x7f\x7f\xff\xff" + capture));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.size(), 107u);
  EXPECT_NE(r.err.find("byte 0: PD0"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(": 107 messages, "), std::string::npos) << r.err;
  std::vector<std::string> frames;
  for (size_t at = 0; at + 4 <= capture.size();) {
    const size_t n = size_t(uint8_t(capture[at + 2]) | (uint8_t(capture[at + 3]) << 8)) + 2;
    frames.push_back(capture.substr(at, n));
    at += n;
  }
  ASSERT_EQ(frames.size(), 107u);
  std::vector<long> intact;
  r = decode("pd0", writeTemp("real_mixed.pd0", mixed(frames, &intact, std::string("\x7f\x7f\x00\xf0\x01\x02", 6))));
  EXPECT_EQ(intact.size(), 86u);
  EXPECT_EQ(offsets(r), intact) << r.err;
}

TEST(DecodeCli, XsensFalseLengthAndMixedMessagesLoseNothing) {
  std::vector<std::string> frames;
  for (uint16_t i = 1; i <= 50; ++i) frames.push_back(builtXbus(i));
  std::string file = "\xfa\xff\x36\xff\xf0\x00";
  for (const auto& f : frames) file += f;
  DecodeRun r = decode("xsens", writeTemp("false.xs", file));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.size(), 50u) << r.err;
  std::vector<long> intact;
  r = decode("xsens", writeTemp("mixed.xs", mixed(frames, &intact, "\xfa\xff\x36\xfe")));
  EXPECT_EQ(offsets(r), intact) << r.err;
}

TEST(DecodeCli, WaterLinkedAfterJunkAndBareCr) {
  const std::string wrz = test::wlSentence("wrz,0.100,0.200,0.010,y,1.90,0.002,1e-06;0;0;0;1e-06;0;0;0;1e-06,1000,1040,250.0,0");
  const std::string cr = wrz.substr(0, wrz.size() - 1);
  const std::string file = "hello world " + wrz + cr + cr + "{\"cut\": " + wrz + std::string("\x00\xff", 2) + wrz + "ww" + wrz;
  const DecodeRun r = decode("wl-a50", writeTemp("junk.wl", file));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.size(), 6u) << r.err;
}

TEST(DecodeCli, CandumpLinesAfterStrayBytes) {
  const std::string line = "(1436509052.249713) can0 09F1128F#FF4C2EFF7FFFFF7F\n";  // 127250 from source 143
  std::string file;
  for (const std::string& junk : {std::string(), std::string("\xff"), std::string("\x80\x81"), std::string("x"),
                                  std::string(1, '\0'), std::string("\r")}) {
    file += junk + line;
  }
  const DecodeRun r = decode("n2k-candump", writeTemp("junk.can", file));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.size(), 6u) << r.err;
}

TEST(DecodeCli, RealCandumpWithAStrayByteBeforeEveryThirdLine) {
  if (shared().empty() || !std::filesystem::exists(shared() / "can")) GTEST_SKIP() << "DEEPNAV_SHARED_DATA not set";
  std::ifstream in(shared() / "can" / "candumpSample2.txt");
  std::string file;
  int n = 0;
  for (std::string line; std::getline(in, line); ++n) file += (n % 3 == 1 ? "\xe9" : n % 3 == 2 ? "\r" : "") + line + "\n";
  const DecodeRun r = decode("n2k-candump", writeTemp("stray.can", file));
  ASSERT_EQ(r.status, 0) << r.err;
  int heading = 0;
  for (const auto& l : r.out) heading += YAML::Load(l)["pgn"].as<int>() == 127250;
  EXPECT_EQ(heading, 46) << r.err;
}

// A run of start characters (each one a frame cut short) gives a bounded stderr: the first bad frames
// one line each, then one line per byte range, and the exact count in the summary.
TEST(DecodeCli, TenMegabytesOfNoiseGiveABoundedReport) {
  const std::string path = deepnav::testing::tempPath("noise");
  for (const auto& [format, byte] : {std::pair{"nmea0183", '$'}, {"pd6", ':'}, {"pd0", '\x7f'}, {"xsens", '\xfa'}}) {
    std::ofstream(path, std::ios::binary) << std::string(10 << 20, byte);
    const DecodeRun r = decode(format, path);
    ASSERT_EQ(r.status, 0);
    EXPECT_LT(r.err.size(), 64u << 10) << format;
    EXPECT_TRUE(r.out.empty());
    EXPECT_NE(r.err.find("0 messages, "), std::string::npos) << format;
    EXPECT_NE(r.err.find("bad frames ("), std::string::npos) << format;  // the per-range lines
    if (byte == '$') {
      EXPECT_NE(r.err.find("0 messages, 10485760 bad frames skipped"), std::string::npos) << r.err.substr(r.err.size() - 300);
    }
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace deepnav
