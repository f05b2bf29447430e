// NMEA 2000 decoding of a real bus capture (../shared/data/can/candumpSample2.txt) against canboat's
// reference decode of the same file: every 127250/127251/127257 message, every field.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <vector>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "drivers/parsers/can_field_mapping.h"
#include "drivers/parsers/candump_line.h"
#include "drivers/parsers/n2k_assembler.h"
#include "drivers/parsers/n2k_heading_pgns.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

std::filesystem::path canData() { return deepnav::testing::sharedDataDir() / "can"; }

std::vector<N2kMessage> decodeCapture(const std::filesystem::path& path, int* bad_lines, int* errors,
                                      std::map<uint32_t, int>* fast_sizes) {
  std::ifstream in(path);
  std::string line;
  N2kAssembler assembler;
  std::vector<N2kMessage> out;
  while (std::getline(in, line)) {
    CanFrame frame;
    double t_s = 0;
    const char* why = "";
    const CandumpLine r = parseCandumpLine(line, &frame, &t_s, &why);
    if (r == CandumpLine::kInvalid) ++*bad_lines;
    if (r != CandumpLine::kFrame) continue;
    N2kMessage m;
    const auto res = assembler.add(frame, &m, &why);
    if (res == N2kAssembler::Result::kError) ++*errors;
    if (res != N2kAssembler::Result::kMessage) continue;
    if (assembler.isFastPacket(m.pgn)) (*fast_sizes)[m.pgn] = int(m.size);
    out.push_back(m);
  }
  return out;
}

TEST(N2kParser, HeadingRateAndAttitudeMatchCanboat) {
  const auto dir = canData();
  if (dir.empty() || !std::filesystem::exists(dir / "candumpSample2.txt")) GTEST_SKIP() << "DEEPNAV_SHARED_DATA not set";
  int bad_lines = 0, errors = 0;
  std::map<uint32_t, int> fast_sizes;
  const auto messages = decodeCapture(dir / "candumpSample2.txt", &bad_lines, &errors, &fast_sizes);
  EXPECT_EQ(bad_lines, 0);
  std::vector<const N2kMessage*> ours;
  for (const auto& m : messages) {
    if (m.pgn == kPgnVesselHeading || m.pgn == kPgnRateOfTurn || m.pgn == kPgnAttitude) ours.push_back(&m);
  }
  std::ifstream ref(dir / "candumpSample2.expected.jsonl");
  std::string line;
  size_t k = 0;
  int fields_compared = 0;
  const char* ref_names[] = {"True", "Magnetic", "Error", "Null"};
  while (std::getline(ref, line)) {
    if (line.empty()) continue;
    const YAML::Node r = YAML::Load(line);
    ASSERT_LT(k, ours.size());
    const N2kMessage& m = *ours[k++];
    SCOPED_TRACE(line);
    ASSERT_EQ(m.pgn, r["pgn"].as<uint32_t>());
    EXPECT_EQ(m.priority, r["prio"].as<int>());
    EXPECT_EQ(m.source, r["src"].as<int>());
    EXPECT_EQ(m.destination, r["dst"].as<int>());
    const YAML::Node f = r["fields"];
    const char* why = "";
    const auto angle = [&](const char* key, bool has, double value) {
      ASSERT_EQ(has, bool(f[key])) << key;
      if (has) {
        EXPECT_NEAR(value, f[key].as<double>(), 0.5e-4) << key;
        ++fields_compared;
      }
    };
    if (m.pgn == kPgnVesselHeading) {
      N2kVesselHeading h;
      ASSERT_TRUE(decodeN2kVesselHeading(m, &h, &why)) << why;
      EXPECT_EQ(h.sid, f["SID"].as<int>());
      angle("Heading", h.has_heading, h.heading_rad);
      angle("Deviation", h.has_deviation, h.deviation_rad);
      angle("Variation", h.has_variation, h.variation_rad);
      EXPECT_EQ(ref_names[h.reference], f["Reference"].as<std::string>());
      fields_compared += 2;
    } else if (m.pgn == kPgnRateOfTurn) {
      N2kRateOfTurn t;
      ASSERT_TRUE(decodeN2kRateOfTurn(m, &t, &why)) << why;
      EXPECT_EQ(t.sid, f["SID"].as<int>());
      ASSERT_TRUE(t.has_rate);
      EXPECT_NEAR(t.rate_radps, f["Rate"].as<double>(), 1e-8);
      char reserved[16];
      std::snprintf(reserved, sizeof reserved, "%02X %02X %02X", t.reserved[0], t.reserved[1], t.reserved[2]);
      EXPECT_EQ(reserved, f["Reserved"].as<std::string>());
      fields_compared += 3;
    } else {
      N2kAttitude a;
      ASSERT_TRUE(decodeN2kAttitude(m, &a, &why)) << why;
      EXPECT_EQ(a.sid, f["SID"].as<int>());
      angle("Yaw", a.has_yaw, a.yaw_rad);
      angle("Pitch", a.has_pitch, a.pitch_rad);
      angle("Roll", a.has_roll, a.roll_rad);
      ++fields_compared;
    }
  }
  EXPECT_EQ(k, ours.size());
  EXPECT_EQ(k, 97u);
  EXPECT_GE(fields_compared, 97 * 3);
  // The capture's fast-packet PGNs reassemble to their specified sizes: 129029 GNSS position is 43 bytes.
  EXPECT_EQ(fast_sizes[129029], 43);
  EXPECT_GT(fast_sizes[129540], 0);
}

TEST(N2kParser, IdentifierFieldsPdu1AndPdu2) {
  N2kMessage m;
  splitN2kId(0x09F11280, &m);  // PDU2 broadcast
  EXPECT_EQ(m.priority, 2);
  EXPECT_EQ(m.pgn, 127250u);
  EXPECT_EQ(m.source, 0x80);
  EXPECT_EQ(m.destination, 255);
  splitN2kId(0x18EA2301, &m);  // PDU1: ISO request to address 0x23
  EXPECT_EQ(m.pgn, 59904u);
  EXPECT_EQ(m.destination, 0x23);
  EXPECT_EQ(m.source, 0x01);
}

CanFrame frame(uint32_t id, std::initializer_list<uint8_t> bytes) {
  CanFrame f;
  f.id = id;
  f.extended = true;
  f.dlc = uint8_t(bytes.size());
  std::copy(bytes.begin(), bytes.end(), f.data.begin());
  return f;
}

TEST(N2kParser, FastPacketAttitudeIsReassembledAndOutOfOrderFramesDropped) {
  // A device that sends 127257 as fast packet (8 bytes: SID, yaw, pitch, roll, reserved).
  N2kAssembler a;
  const uint32_t pgns[] = {kPgnAttitude};
  ASSERT_TRUE(a.setFastPacketPgns(pgns, 1));
  const uint32_t id = (3u << 26) | (0x1F119u << 8) | 0x10;
  N2kMessage m;
  const char* why = "";
  EXPECT_EQ(a.add(frame(id, {0x40, 8, 7, 0x10, 0x27, 0x9F, 0x00, 0xF9}), &m, &why), N2kAssembler::Result::kNone);
  ASSERT_EQ(a.add(frame(id, {0x41, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF}), &m, &why), N2kAssembler::Result::kMessage);
  ASSERT_EQ(m.size, 8u);
  N2kAttitude att;
  ASSERT_TRUE(decodeN2kAttitude(m, &att, &why));
  EXPECT_EQ(att.sid, 7);
  EXPECT_NEAR(att.yaw_rad, 1.0, 1e-12);
  EXPECT_NEAR(att.pitch_rad, 0.0159, 1e-12);
  EXPECT_NEAR(att.roll_rad, (int16_t)0xFFF9 * 1e-4, 1e-12);
  AttitudeSample s;
  ASSERT_TRUE(attitudeSampleFromN2k(att, 5, &s));
  EXPECT_NEAR(s.pitch_rad, -0.0159, 1e-12);  // FLU: nose up is negative pitch
  // Counter 2 after counter 0: out of order, dropped and reported.
  EXPECT_EQ(a.add(frame(id, {0x60, 8, 7, 0, 0, 0, 0, 0}), &m, &why), N2kAssembler::Result::kNone);
  EXPECT_EQ(a.add(frame(id, {0x62, 0, 0, 0, 0, 0, 0, 0}), &m, &why), N2kAssembler::Result::kError);
  EXPECT_EQ(a.add(frame(id, {0x61, 0, 0, 0, 0, 0, 0, 0}), &m, &why), N2kAssembler::Result::kError);
}

TEST(N2kParser, HeadingSampleAppliesDeviationToMagneticHeading) {
  N2kMessage m;
  m.size = 8;
  const uint8_t bytes[8] = {1, 0x10, 0x27, 0xE8, 0x03, 0xFF, 0x7F, 0xFD};  // 1.0 rad, dev 0.1, magnetic
  std::copy(bytes, bytes + 8, m.data.begin());
  N2kVesselHeading h;
  const char* why = "";
  ASSERT_TRUE(decodeN2kVesselHeading(m, &h, &why));
  EXPECT_FALSE(h.has_variation);
  HeadingSample s;
  ASSERT_TRUE(headingSampleFromN2k(h, 9, &s));
  EXPECT_NEAR(s.heading_rad, 1.1, 1e-12);
  EXPECT_FALSE(s.is_true);
}

TEST(CanFieldMapping, ProprietaryImuFramesBecomeSamples) {
  CanFieldMapping map;
  std::string error;
  ASSERT_TRUE(map.parse("0x100:0:i16le:0.001:gyro_x; 0x100:2:i16le:0.001:gyro_y; 0x100:4:i16le:0.001:gyro_z;"
                        "0x101:0:i16be:0.01:accel_x; 0x101:2:i16be:0.01:accel_y; 0x101:4:i16be:0.01:accel_z;"
                        "0x102:0:u16le:0.0001:heading",
                        &error))
      << error;
  EXPECT_EQ(map.numFields(), 7);
  CanFieldMapping::Output out;
  CanFrame g;
  g.id = 0x100, g.dlc = 6, g.data = {0xE8, 0x03, 0x18, 0xFC, 0, 0, 0, 0};  // 1000, -1000, 0
  ASSERT_TRUE(map.apply(g, 1, &out));
  EXPECT_FALSE(out.has_imu);  // accelerations not seen yet
  CanFrame a;
  a.id = 0x101, a.dlc = 6, a.data = {0x03, 0xD4, 0, 0, 0, 0, 0, 0};  // 980 -> 9.80
  ASSERT_TRUE(map.apply(a, 2, &out));
  ASSERT_TRUE(out.has_imu);
  EXPECT_NEAR(out.imu.w_imu_radps.x(), 1.0, 1e-12);
  EXPECT_NEAR(out.imu.w_imu_radps.y(), -1.0, 1e-12);
  EXPECT_NEAR(out.imu.f_imu_mps2.x(), 9.8, 1e-12);
  ASSERT_TRUE(map.apply(a, 3, &out));
  EXPECT_FALSE(out.has_imu);  // gyro not refreshed since
  CanFrame h;
  h.id = 0x102, h.dlc = 2, h.data = {0x10, 0x27};
  ASSERT_TRUE(map.apply(h, 4, &out));
  ASSERT_TRUE(out.has_heading);
  EXPECT_NEAR(out.heading.heading_rad, 1.0, 1e-12);
  h.dlc = 1;  // short frame: dropped
  EXPECT_FALSE(map.apply(h, 5, &out));
  EXPECT_FALSE(map.parse("0x100:7:i16le:1:gyro_x", &error));
  EXPECT_NE(error.find("entry 1"), std::string::npos);
  EXPECT_FALSE(map.parse("0x100:0:i16le:1:speed", &error));
  EXPECT_FALSE(map.parse("zz:0:i16le:1:gyro_x", &error));
}

TEST(CandumpLine, BothCandumpFormats) {
  CanFrame f;
  double t = 0;
  const char* why = "";
  ASSERT_EQ(parseCandumpLine("  can0  09F8027F   [8]  00 FC FF FF 00 00 FF FF", &f, &t, &why), CandumpLine::kFrame);
  EXPECT_TRUE(f.extended);
  EXPECT_EQ(f.id, 0x09F8027Fu);
  EXPECT_EQ(f.dlc, 8);
  EXPECT_EQ(f.data[1], 0xFC);
  ASSERT_EQ(parseCandumpLine("(1436509052.249713) vcan0 123#DEADBEEF", &f, &t, &why), CandumpLine::kFrame);
  EXPECT_FALSE(f.extended);
  EXPECT_EQ(f.dlc, 4);
  EXPECT_NEAR(t, 1436509052.249713, 1e-6);
  EXPECT_EQ(parseCandumpLine("# comment", &f, &t, &why), CandumpLine::kSkip);
  EXPECT_EQ(parseCandumpLine("  can0  09F8027F   [8]  00 FC", &f, &t, &why), CandumpLine::kInvalid);
  EXPECT_EQ(parseCandumpLine("  can0  09F8027F   [9]  00", &f, &t, &why), CandumpLine::kInvalid);
  EXPECT_EQ(parseCandumpLine("  can0  GG   [1]  00", &f, &t, &why), CandumpLine::kInvalid);
}

}  // namespace
}  // namespace deepnav
