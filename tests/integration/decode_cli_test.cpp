// `deepnav decode` as a user runs it: real captures from ../shared/data and generated captures for the
// formats without a public sample; one JSON object per message on stdout, bad frames on stderr with
// their byte offset.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "tests/support/sensor_frames.h"

namespace deepnav {
namespace {

struct DecodeRun {
  int status = -1;
  std::vector<std::string> out;
  std::string err;
};

DecodeRun decode(const std::string& format, const std::string& file) {
  const std::string dir = ::testing::TempDir();
  // ctest runs each test case in its own process, in parallel: names carry the process id and format.
  const std::string tag = std::to_string(::getpid()) + "_" + format;
  const std::string out = dir + "decode_out_" + tag + ".jsonl", err = dir + "decode_err_" + tag + ".txt";
  const std::string cmd = std::string(DEEPNAV_BIN_DIR) + "/deepnav decode " + format + " " + file + " > " + out + " 2> " + err;
  DecodeRun r;
  r.status = std::system(cmd.c_str());
  std::ifstream o(out);
  for (std::string line; std::getline(o, line);) r.out.push_back(line);
  std::stringstream e;
  e << std::ifstream(err).rdbuf();
  r.err = e.str();
  return r;
}

std::filesystem::path shared() {
  const char* env = std::getenv("DEEPNAV_SHARED_DATA");
  return env ? std::filesystem::path(env) : std::filesystem::path();
}

std::string writeTemp(const std::string& name, const std::string& bytes) {
  const std::string path = ::testing::TempDir() + std::to_string(::getpid()) + "_" + name;
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

}  // namespace
}  // namespace deepnav
