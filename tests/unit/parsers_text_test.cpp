// Text protocols: NMEA 0183 heading sentences on real logs (../shared/data/nmea), PD6, Water Linked
// serial and JSON reports, and the line framer's resynchronisation.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "drivers/parsers/crc8.h"
#include "drivers/parsers/line_framer.h"
#include "drivers/parsers/nmea0183_heading.h"
#include "drivers/parsers/pd6_sentence.h"
#include "drivers/parsers/wl_dvl_protocol.h"
#include "tests/support/sensor_frames.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

std::filesystem::path nmeaData() { return deepnav::testing::sharedDataDir() / "nmea"; }

// Frames every line of `text` (fed in odd-sized chunks) and returns the lines and the errors.
std::vector<std::string> lines(LineFramer* framer, const std::string& text, std::vector<FrameError>* errors) {
  std::vector<std::string> out;
  size_t pos = 0;
  while (true) {
    RawFrame f;
    FrameError e;
    const FrameStatus st = framer->next(&f, &e);
    if (st == FrameStatus::kFrame) {
      out.emplace_back(reinterpret_cast<const char*>(f.data), f.size);
    } else if (st == FrameStatus::kBad) {
      errors->push_back(e);
    } else {
      if (pos == text.size()) break;
      pos += framer->push(reinterpret_cast<const uint8_t*>(text.data()) + pos, std::min<size_t>(13, text.size() - pos));
    }
  }
  return out;
}

TEST(Nmea0183Parser, RealLogsHeadingAndRateOfTurn) {
  const auto dir = nmeaData();
  if (dir.empty() || !std::filesystem::exists(dir / "saab-r4.log")) GTEST_SKIP() << "DEEPNAV_SHARED_DATA not set";
  int headings = 0, empty_headings = 0, rates = 0, sentences = 0;
  for (const char* name : {"saab-r4.log", "hemi.log"}) {
    std::ifstream in(dir / name);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    LineFramer framer;
    ASSERT_TRUE(framer.init("$!", 120));
    std::vector<FrameError> errors;
    for (const std::string& line : lines(&framer, text, &errors)) {
      Nmea0183Sentence s;
      const char* why = "";
      ASSERT_TRUE(parseNmea0183Sentence(line, true, &s, &why)) << line << ": " << why;
      ++sentences;
      Nmea0183HeadingRecord r;
      const NmeaDecode d = decodeNmea0183Heading(s, &r, &why);
      ASSERT_NE(d, NmeaDecode::kInvalid) << line << ": " << why;
      if (d != NmeaDecode::kDecoded) continue;
      // Independent reading of the first field.
      const std::string first = line.substr(7, line.find(',', 7) - 7);
      if (r.kind == Nmea0183HeadingRecord::Kind::kRot) {
        ASSERT_TRUE(r.has_rate);
        EXPECT_NEAR(r.rate_radps, std::stod(first) * M_PI / 180.0 / 60.0, 1e-12);
        EXPECT_TRUE(r.rate_valid);
        ++rates;
      } else if (first.empty()) {
        EXPECT_FALSE(r.has_heading);
        HeadingSample h;
        EXPECT_FALSE(headingSampleFromNmea(r, 0, &h));
        ++empty_headings;
      } else {
        HeadingSample h;
        ASSERT_TRUE(headingSampleFromNmea(r, 7, &h));
        EXPECT_NEAR(h.heading_rad, std::stod(first) * M_PI / 180.0, 1e-12);
        EXPECT_TRUE(h.is_true);
        ++headings;
      }
    }
    // Only the comment lines ('#') are skipped: 5 in saab-r4.log, 2 in hemi.log.
    for (const FrameError& e : errors) EXPECT_EQ(text[e.offset], '#') << name << " at byte " << e.offset;
  }
  EXPECT_EQ(sentences, 122 + 753);
  EXPECT_EQ(headings, 12 + 4);
  EXPECT_EQ(empty_headings, 211);
  EXPECT_EQ(rates, 12);
}

TEST(Nmea0183Parser, HdgHdmAndChecksums) {
  Nmea0183Sentence s;
  Nmea0183HeadingRecord r;
  HeadingSample h;
  const char* why = "";
  std::string line = test::nmeaSentence("HCHDG,101.1,2.0,W,3.5,E");
  line.resize(line.size() - 2);  // the framer strips CR LF
  ASSERT_TRUE(parseNmea0183Sentence(line, true, &s, &why)) << why;
  ASSERT_EQ(decodeNmea0183Heading(s, &r, &why), NmeaDecode::kDecoded);
  EXPECT_NEAR(r.deviation_rad, -2.0 * M_PI / 180, 1e-12);
  EXPECT_NEAR(r.variation_rad, 3.5 * M_PI / 180, 1e-12);
  ASSERT_TRUE(headingSampleFromNmea(r, 0, &h));
  EXPECT_NEAR(h.heading_rad, 99.1 * M_PI / 180, 1e-12);  // magnetic = sensor + deviation
  EXPECT_FALSE(h.is_true);
  line = test::nmeaSentence("HCHDM,359.9,M");
  line.resize(line.size() - 2);
  ASSERT_TRUE(parseNmea0183Sentence(line, true, &s, &why));
  ASSERT_EQ(decodeNmea0183Heading(s, &r, &why), NmeaDecode::kDecoded);
  EXPECT_EQ(r.kind, Nmea0183HeadingRecord::Kind::kHdm);
  line[7] = '8';  // one digit changed: checksum fails
  EXPECT_FALSE(parseNmea0183Sentence(line, true, &s, &why));
  EXPECT_STREQ(why, "NMEA checksum mismatch");
  EXPECT_FALSE(parseNmea0183Sentence("$HEHDT,4.0,T", true, &s, &why));  // checksum required
  ASSERT_TRUE(parseNmea0183Sentence("$HEHDT,400.0,T", false, &s, &why));
  EXPECT_EQ(decodeNmea0183Heading(s, &r, &why), NmeaDecode::kInvalid);  // out of range
  ASSERT_TRUE(parseNmea0183Sentence("$HEHDT,nan,T", false, &s, &why));
  EXPECT_EQ(decodeNmea0183Heading(s, &r, &why), NmeaDecode::kInvalid);
}

TEST(LineFramer, CutSentencesAndNoiseAreSkippedWithTheirOffsets) {
  LineFramer framer;
  ASSERT_TRUE(framer.init("$!", 82));
  const std::string good = test::nmeaSentence("HEHDT,4.0,T");
  const std::string text = "xx" + good + "$HEHD" + good + std::string(100, 'A') + "\n" + good;
  std::vector<FrameError> errors;
  const auto out = lines(&framer, text, &errors);
  ASSERT_EQ(out.size(), 3u);
  for (const auto& l : out) EXPECT_EQ(l + "\r\n", good);
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_EQ(errors[0].offset, 0u);                // noise
  EXPECT_EQ(errors[1].offset, 2 + good.size());   // the cut sentence
  EXPECT_EQ(errors[2].offset, 2 + 2 * good.size() + 5);  // 100 bytes of noise
}

TEST(Pd6Parser, EnsembleBecomesDvlSample) {
  const char* ensemble[] = {":SA, -2.31, +1.12,123.45", ":TS,21051012345612,35.0,+12.5,  12.0,1500.0,  0",
                            ":WI,  -120,  +450,   -10,    15,A", ":BI,  +100,  -500,   +20,     5,A",
                            ":BS,  -100,  +500,   -20,A", ":BE,  +300,  +400,   -20,A",
                            ":BD,     +12.30,     -4.50,      0.20,  8.25,  0.10"};
  Pd6DvlAssembler assembler;
  DvlSample s;
  int samples = 0;
  for (const char* line : ensemble) {
    Pd6Record r;
    const char* why = "";
    ASSERT_TRUE(parsePd6Line(line, &r, &why)) << line << ": " << why;
    if (assembler.add(r, 11, &s)) ++samples;
    if (r.kind == Pd6Record::Kind::kSA) {
      EXPECT_NEAR(r.value[2], 123.45 * M_PI / 180, 1e-12);
    }
    if (r.kind == Pd6Record::Kind::kTS) {
      EXPECT_EQ(r.time, "21051012345612");
      EXPECT_NEAR(r.value[3], 1500.0, 1e-12);
    }
  }
  ASSERT_EQ(samples, 1);
  EXPECT_TRUE(s.valid);
  EXPECT_NEAR(s.v_dvl_mps.x(), -0.5, 1e-12);  // Y (forward) -> x
  EXPECT_NEAR(s.v_dvl_mps.y(), -0.1, 1e-12);  // -X (starboard) -> y
  EXPECT_NEAR(s.v_dvl_mps.z(), 0.02, 1e-12);
  EXPECT_NEAR(s.altitude_m, 8.25, 1e-12);
  Pd6Record r;
  const char* why = "";
  EXPECT_FALSE(parsePd6Line(":BI,+100,-500,+20,A", &r, &why));  // missing error velocity
  EXPECT_FALSE(parsePd6Line(":BI,+100,-500,+20,5,X", &r, &why));
  EXPECT_FALSE(parsePd6Line(":XX,1", &r, &why));
  // Found by fuzzing: a built-in-test value that does not fit an int is a bad line, not undefined behaviour.
  EXPECT_FALSE(parsePd6Line(":TS,21051012345612,35.0,+12.5,12.0,1500.0,33333333345", &r, &why));
  ASSERT_TRUE(parsePd6Line(":BI,-32768,-32768,-32768,-32768,V", &r, &why));
  EXPECT_FALSE(r.value_valid[0]);
}

TEST(WaterLinkedParser, Crc8CheckValue) {
  const char* check = "123456789";
  EXPECT_EQ(crc8(reinterpret_cast<const uint8_t*>(check), 9), 0xF4);
}

TEST(WaterLinkedParser, SerialVelocityTransducerAndDeadReckoning) {
  WlDvlReport r;
  const char* why = "";
  std::string line = test::wlSentence(
      "wrz,0.120,-0.400,2.000,y,1.30,1.855,1e-07;0;1.4;0;1.2;0;0.2;0;1e+09,1664894633045000,1664894633085000,14.1,0");
  line.resize(line.size() - 2);
  ASSERT_EQ(parseWlDvlSerialLine(line, &r, &why), WlDecode::kDecoded) << why;
  EXPECT_EQ(r.kind, WlDvlReport::Kind::kVelocity);
  EXPECT_TRUE(r.velocity_valid);
  EXPECT_EQ(r.time_of_validity_us, 1664894633045000);
  EXPECT_NEAR(r.covariance_m2ps2[8], 1e9, 1);
  DvlSample s;
  ASSERT_TRUE(dvlSampleFromWlReport(r, 3, &s));
  EXPECT_NEAR(s.v_dvl_mps.x(), 0.12, 1e-12);
  EXPECT_NEAR(s.v_dvl_mps.y(), 0.4, 1e-12);   // y right -> left
  EXPECT_NEAR(s.v_dvl_mps.z(), -2.0, 1e-12);  // z down -> up
  EXPECT_NEAR(s.cov_v_dvl_mps2(0, 2), -1.4, 1e-12);
  line[5] = '2';  // corrupt one digit
  EXPECT_EQ(parseWlDvlSerialLine(line, &r, &why), WlDecode::kInvalid);
  EXPECT_STREQ(why, "Water Linked CRC-8 mismatch");
  line = test::wlSentence("wru,1,-0.7,15.3,-40.5,-95.2");
  line.resize(line.size() - 2);
  ASSERT_EQ(parseWlDvlSerialLine(line, &r, &why), WlDecode::kDecoded) << why;
  EXPECT_EQ(r.transducers[0].id, 1);
  EXPECT_NEAR(r.transducers[0].distance_m, 15.3, 1e-12);
  line = test::wlSentence("wrp,49056.809,12.43,64.23,1.34,0.4,20.42,-1.24,34.11,0");
  line.resize(line.size() - 2);
  ASSERT_EQ(parseWlDvlSerialLine(line, &r, &why), WlDecode::kDecoded) << why;
  EXPECT_NEAR(r.yaw_rad, 34.11 * M_PI / 180, 1e-12);
  line = test::wlSentence("wra");
  line.resize(line.size() - 2);
  EXPECT_EQ(parseWlDvlSerialLine(line, &r, &why), WlDecode::kOtherSentence);
  EXPECT_EQ(parseWlDvlSerialLine("wrz,0.1,0.1*00", &r, &why), WlDecode::kInvalid);
  line = test::wlSentence("wrp,49056.809,12.43,64.23,1.34,0.4,20.42,-1.24,34.11,3e10");  // status overflows an int
  line.resize(line.size() - 2);
  EXPECT_EQ(parseWlDvlSerialLine(line, &r, &why), WlDecode::kInvalid);
}

TEST(WaterLinkedParser, JsonVelocityAndPositionReports) {
  const std::string velocity =
      R"({"time": 106.39, "vx": -0.0370, "vy": 0.0570, "vz": 0.0249, "fom": 0.00168,)"
      R"( "covariance": [[2.8e-06, -1.1e-07, 3e-08], [-1.1e-07, 2.9e-06, -6e-09], [3e-08, -6e-09, 1.9e-07]],)"
      R"( "altitude": 0.49, "transducers": [{"id": 0, "velocity": 0.01, "distance": 0.57, "rssi": -30.5, "nsd": -88.9, "beam_valid": true},)"
      R"( {"id": 1, "velocity": 0.02, "distance": 0.56, "rssi": -31.0, "nsd": -89.0, "beam_valid": true},)"
      R"( {"id": 2, "velocity": 0.03, "distance": 0.0, "rssi": -31.0, "nsd": -89.0, "beam_valid": false},)"
      R"( {"id": 3, "velocity": 0.04, "distance": 0.58, "rssi": -30.0, "nsd": -88.0, "beam_valid": true}],)"
      R"( "velocity_valid": true, "status": 0, "time_of_validity": 1638191471563017,)"
      R"( "time_of_transmission": 1638191471752336, "format": "json_v3.1", "type": "velocity"})";
  WlDvlReport r;
  const char* why = "";
  ASSERT_EQ(parseWlDvlJson(velocity, &r, &why), WlDecode::kDecoded) << why;
  EXPECT_EQ(r.num_transducers, 4);
  EXPECT_TRUE(r.has_covariance);
  EXPECT_NEAR(r.covariance_m2ps2[4], 2.9e-06, 1e-15);
  DvlSample s;
  ASSERT_TRUE(dvlSampleFromWlReport(r, 0, &s));
  EXPECT_EQ(s.beam_valid_mask, 0b1011);
  EXPECT_NEAR(s.beam_range_m[3], 0.58, 1e-12);
  EXPECT_NEAR(s.v_dvl_mps.y(), -0.057, 1e-12);
  const std::string position =
      R"({"ts": 49056.809, "x": 12.43, "y": 64.23, "z": 1.34, "std": 0.4, "roll": 20.42, "pitch": -1.24,)"
      R"( "yaw": 34.11, "type": "position_local", "status": 0, "format": "json_v3.1"})";
  ASSERT_EQ(parseWlDvlJson(position, &r, &why), WlDecode::kDecoded) << why;
  EXPECT_NEAR(r.roll_rad, 20.42 * M_PI / 180, 1e-12);
  EXPECT_EQ(parseWlDvlJson(velocity.substr(0, velocity.size() - 1), &r, &why), WlDecode::kInvalid);
  EXPECT_EQ(parseWlDvlJson(R"({"type": "velocity", "vx": 1})", &r, &why), WlDecode::kInvalid);
  EXPECT_EQ(parseWlDvlJson(R"({"type": "response", "success": true})", &r, &why), WlDecode::kOtherSentence);
  EXPECT_EQ(parseWlDvlJson(std::string(100, '[') , &r, &why), WlDecode::kInvalid);
}

}  // namespace
}  // namespace deepnav
