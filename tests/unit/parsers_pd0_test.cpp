// PD0 framing and decoding on real Teledyne RDI captures (../shared/data/dvl), compared with decodes
// made independently of the project, and the bottom-track -> DvlSample frame conventions.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "drivers/parsers/pd0_dvl_sample.h"
#include "drivers/parsers/pd0_ensemble.h"
#include "drivers/parsers/pd0_framer.h"
#include "tests/support/sensor_frames.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

std::filesystem::path dvlData() { return deepnav::testing::sharedDataDir() / "dvl"; }

std::vector<uint8_t> readAll(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Framed {
  std::vector<std::unique_ptr<Pd0Ensemble>> ensembles;
  std::vector<FrameError> errors;
  int decode_failures = 0;
};

// Feeds the bytes in chunks of `chunk` (a serial port hands out arbitrary pieces).
Framed frameAll(const std::vector<uint8_t>& bytes, size_t chunk = 97) {
  Framed out;
  Pd0Framer framer;
  EXPECT_TRUE(framer.init(4096));
  size_t pos = 0;
  while (true) {
    RawFrame frame;
    FrameError error;
    const FrameStatus st = framer.next(&frame, &error);
    if (st == FrameStatus::kFrame) {
      auto e = std::make_unique<Pd0Ensemble>();
      const char* why = "";
      if (decodePd0Ensemble(frame.data, frame.size, e.get(), &why)) {
        out.ensembles.push_back(std::move(e));
      } else {
        ++out.decode_failures;
      }
    } else if (st == FrameStatus::kBad) {
      out.errors.push_back(error);
    } else {
      if (pos == bytes.size()) break;
      const size_t n = std::min(chunk, bytes.size() - pos);
      pos += framer.push(bytes.data() + pos, n);
    }
  }
  return out;
}

TEST(Pd0Parser, BottomTrackMatchesTheIndependentDecode) {
  const auto dir = dvlData();
  if (dir.empty() || !std::filesystem::exists(dir / "LA100204.PD0")) GTEST_SKIP() << "DEEPNAV_SHARED_DATA not set";
  const Framed f = frameAll(readAll(dir / "LA100204.PD0"));
  EXPECT_TRUE(f.errors.empty());
  EXPECT_EQ(f.decode_failures, 0);
  ASSERT_EQ(f.ensembles.size(), 107u);
  std::map<uint32_t, const Pd0Ensemble*> with_bt;
  for (const auto& e : f.ensembles) {
    ASSERT_TRUE(e->has_fixed_leader && e->has_variable_leader);
    if (e->has_bottom_track) with_bt[e->variable.ensemble_number] = e.get();
  }
  EXPECT_EQ(with_bt.size(), 52u);
  std::ifstream ref(dir / "LA100204.bt.txt");
  std::string line;
  int compared = 0;
  while (std::getline(ref, line)) {
    std::istringstream in(line);
    long n, v[4], r[4], h, p, ro;
    if (!(in >> n >> v[0] >> v[1] >> v[2] >> v[3] >> r[0] >> r[1] >> r[2] >> r[3] >> h >> p >> ro)) continue;
    ASSERT_TRUE(with_bt.count(uint32_t(n))) << "ensemble " << n;
    const Pd0Ensemble& e = *with_bt[uint32_t(n)];
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(e.bottom_track.velocity_mmps[i], v[i]) << "ensemble " << n << " beam " << i;
      EXPECT_EQ(long(e.bottom_track.range_cm[i]), r[i]) << "ensemble " << n << " beam " << i;
    }
    EXPECT_EQ(e.variable.heading_cdeg, h);
    EXPECT_EQ(e.variable.pitch_cdeg, p);
    EXPECT_EQ(e.variable.roll_cdeg, ro);
    ++compared;
  }
  EXPECT_EQ(compared, 52);
  // Earth-frame ensembles become DVL-frame samples; a bottom lock gives a plausible glider speed.
  int valid = 0;
  for (const auto& [n, e] : with_bt) {
    DvlSample s;
    ASSERT_TRUE(pd0ToDvlSample(*e, 0, &s));
    if (!s.valid) continue;
    ++valid;
    EXPECT_LT(s.v_dvl_mps.norm(), 2.0) << "ensemble " << n;
    EXPECT_GT(s.altitude_m, 0.0);
    // Rotating back to earth gives the stored east/north/up (minus: PD0 gives the bottom's motion).
    const double h = e->variable.heading_cdeg * 0.01 * M_PI / 180, pt = e->variable.pitch_cdeg * 0.01 * M_PI / 180,
                 r = e->variable.roll_cdeg * 0.01 * M_PI / 180;
    Eigen::Matrix3d m;
    m << std::cos(h) * std::cos(r) + std::sin(h) * std::sin(pt) * std::sin(r), std::sin(h) * std::cos(pt),
        std::cos(h) * std::sin(r) - std::sin(h) * std::sin(pt) * std::cos(r),
        -std::sin(h) * std::cos(r) + std::cos(h) * std::sin(pt) * std::sin(r), std::cos(h) * std::cos(pt),
        -std::sin(h) * std::sin(r) - std::cos(h) * std::sin(pt) * std::cos(r), -std::cos(pt) * std::sin(r), std::sin(pt),
        std::cos(pt) * std::cos(r);
    const Eigen::Vector3d bottom_inst(s.v_dvl_mps.y(), -s.v_dvl_mps.x(), -s.v_dvl_mps.z());
    const Eigen::Vector3d earth_mmps = m * bottom_inst * 1000.0;
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(earth_mmps[i], e->bottom_track.velocity_mmps[i], 1e-6) << "ensemble " << n;
  }
  EXPECT_GT(valid, 10);
}

TEST(Pd0Parser, LeadersAndProfilesMatchTheIndependentDecode) {
  const auto dir = dvlData();
  if (dir.empty() || !std::filesystem::exists(dir / "LA101636_20.yml")) GTEST_SKIP() << "DEEPNAV_SHARED_DATA not set";
  const Framed f = frameAll(readAll(dir / "LA101636_20.PD0"), 1);
  EXPECT_TRUE(f.errors.empty());
  const YAML::Node ref = YAML::LoadFile((dir / "LA101636_20.yml").string())["data"];
  ASSERT_EQ(f.ensembles.size(), ref.size());
  for (size_t k = 0; k < ref.size(); ++k) {
    const YAML::Node r = ref[k];
    const Pd0Ensemble& e = *f.ensembles[k];
    SCOPED_TRACE("ensemble index " + std::to_string(k));
    EXPECT_EQ(e.fixed.firmware_version, r["firmware_version"].as<int>());
    EXPECT_EQ(e.fixed.firmware_revision, r["firmware_revision"].as<int>());
    EXPECT_EQ(e.fixed.num_beams, r["num_beams"].as<int>());
    EXPECT_EQ(e.fixed.num_cells, r["num_cells"].as<int>());
    EXPECT_EQ(e.fixed.pings_per_ensemble, r["pings_per_ensemble"].as<int>());
    EXPECT_EQ(e.fixed.cell_length_cm, r["cell_length"].as<int>());
    EXPECT_EQ(e.fixed.blank_after_transmit_cm, r["blank_after_transmit"].as<int>());
    EXPECT_EQ(e.fixed.low_corr_threshold, r["low_corr_threshold"].as<int>());
    EXPECT_EQ(e.fixed.code_repetitions, r["num_code_repetitions"].as<int>());
    EXPECT_EQ(e.fixed.error_velocity_max_mmps, r["error_vel_threshold"].as<int>());
    EXPECT_EQ(e.fixed.frame(), r["coord_transform_type"].as<int>());
    EXPECT_EQ(e.fixed.heading_alignment_cdeg, r["heading_alignment"].as<int>());
    EXPECT_EQ(e.fixed.bin1_distance_cm, r["bin_1_distance"].as<int>());
    EXPECT_EQ(e.fixed.transmit_pulse_length_cm, r["transmit_pulse_length"].as<int>());
    EXPECT_EQ(e.fixed.false_target_threshold, r["false_target_threshold"].as<int>());
    EXPECT_EQ(e.fixed.transmit_lag_distance_cm, r["transmit_lag_distance"].as<int>());
    EXPECT_EQ(int((e.fixed.system_config >> 8) & 3), r["sysconfig_beam_angle"].as<int>());
    EXPECT_EQ(e.fixed.serial_number, r["serial_number"].as<uint32_t>());
    EXPECT_EQ(e.variable.ensemble_number, r["ensemble_number"].as<uint32_t>());
    const YAML::Node rtc = r["real_time_clock"];
    for (int i = 0; i < 7; ++i) EXPECT_EQ(e.variable.rtc[i], rtc[i].as<int>());
    EXPECT_EQ(e.variable.speed_of_sound_mps, r["speed_of_sound"].as<int>());
    EXPECT_EQ(e.variable.transducer_depth_dm, r["transducer_depth"].as<int>());
    EXPECT_EQ(e.variable.heading_cdeg, r["heading"].as<int>());
    EXPECT_EQ(e.variable.pitch_cdeg, r["pitch"].as<int>());
    EXPECT_EQ(e.variable.roll_cdeg, r["roll"].as<int>());
    EXPECT_EQ(e.variable.salinity_ppt, r["salinity"].as<int>());
    EXPECT_EQ(e.variable.temperature_cdegc, r["temperature"].as<int>());
    EXPECT_EQ(e.variable.pitch_std_ddeg, r["pitch_stdev"].as<int>());
    EXPECT_EQ(e.variable.roll_std_ddeg, r["roll_stdev"].as<int>());
    ASSERT_TRUE(e.has_velocity && e.has_correlation && e.has_echo_intensity && e.has_percent_good);
    const char* vel[4] = {"water_velocity_east", "water_velocity_north", "water_velocity_up", "error_velocity"};
    const char* pg[4] = {"percent_good_3beam", "percent_transforms_reject", "percent_bad_beams", "percent_good_4beam"};
    for (int c = 0; c < e.num_cells; ++c) {
      for (int b = 0; b < 4; ++b) {
        EXPECT_EQ(e.velocity_mmps[c][b], r[vel[b]][c].as<int>()) << "cell " << c;
        EXPECT_EQ(e.correlation[c][b], r["correlation_magnitude_beam" + std::to_string(b + 1)][c].as<int>());
        EXPECT_EQ(e.echo_intensity[c][b], r["echo_intensity_beam" + std::to_string(b + 1)][c].as<int>());
        EXPECT_EQ(e.percent_good[c][b], r[pg[b]][c].as<int>());
      }
    }
  }
}

TEST(Pd0Parser, BadChecksumIsReportedAndTheNextEnsembleIsFound) {
  const auto dir = dvlData();
  if (dir.empty() || !std::filesystem::exists(dir / "LB180210_3_corrupted.PD0")) GTEST_SKIP() << "DEEPNAV_SHARED_DATA not set";
  const Framed good = frameAll(readAll(dir / "LB180210_3.PD0"));
  const Framed bad = frameAll(readAll(dir / "LB180210_3_corrupted.PD0"));
  ASSERT_TRUE(good.errors.empty());
  ASSERT_GE(good.ensembles.size(), 2u);
  EXPECT_EQ(bad.ensembles.size(), good.ensembles.size() - 1);
  ASSERT_FALSE(bad.errors.empty());
  EXPECT_STREQ(bad.errors.front().reason, "PD0 checksum mismatch");
  // Every accepted ensemble is one of the originals, in order, and the one after the bad one is there.
  size_t j = 0;
  for (const auto& e : bad.ensembles) {
    while (j < good.ensembles.size() && good.ensembles[j]->variable.ensemble_number != e->variable.ensemble_number) ++j;
    ASSERT_LT(j, good.ensembles.size());
    EXPECT_EQ(e->bottom_track.velocity_mmps, good.ensembles[j]->bottom_track.velocity_mmps);
  }
  EXPECT_EQ(bad.ensembles.back()->variable.ensemble_number, good.ensembles.back()->variable.ensemble_number);
}

// The ensemble `spec` describes, built, decoded and converted to a DVL sample stamped t_us.
void decodeToSample(const test::Pd0Spec& spec, TimeUs t_us, DvlSample* s) {
  const auto bytes = test::buildPd0(spec);
  Pd0Ensemble e;
  const char* why = "";
  ASSERT_TRUE(decodePd0Ensemble(bytes.data(), bytes.size(), &e, &why)) << why;
  ASSERT_TRUE(pd0ToDvlSample(e, t_us, s));
}

TEST(Pd0Parser, InstrumentFrameVelocityBecomesFluDvlMotion) {
  test::Pd0Spec spec;
  spec.frame = 1;
  spec.bt_velocity_mmps[0] = 100;   // bottom moves to starboard -> DVL moves to port (+y FLU)
  spec.bt_velocity_mmps[1] = -500;  // bottom moves aft -> DVL moves forward
  spec.bt_velocity_mmps[2] = 20;    // bottom moves up -> DVL moves down
  spec.bt_velocity_mmps[3] = 7;
  DvlSample s;
  ASSERT_NO_FATAL_FAILURE(decodeToSample(spec, 42, &s));
  EXPECT_TRUE(s.valid);
  EXPECT_EQ(s.t_us, 42);
  EXPECT_NEAR(s.v_dvl_mps.x(), 0.5, 1e-12);
  EXPECT_NEAR(s.v_dvl_mps.y(), 0.1, 1e-12);
  EXPECT_NEAR(s.v_dvl_mps.z(), -0.02, 1e-12);
  EXPECT_NEAR(s.fom_mps, 0.007, 1e-12);
  EXPECT_EQ(s.beam_valid_mask, 0xF);
  EXPECT_NEAR(s.altitude_m, 10.0 * std::cos(30.0 * M_PI / 180.0), 1e-9);
}

TEST(Pd0Parser, EarthFrameIsRotatedBackWithHeadingPitchRoll) {
  // Heading 90 deg (instrument Y points east), level: the bottom moving west (-E) means the DVL moves
  // forward.
  test::Pd0Spec spec;
  spec.frame = 3;
  spec.heading_cdeg = 9000;
  spec.bt_velocity_mmps[0] = -800;
  DvlSample s;
  ASSERT_NO_FATAL_FAILURE(decodeToSample(spec, 0, &s));
  EXPECT_NEAR(s.v_dvl_mps.x(), 0.8, 1e-9);
  EXPECT_NEAR(s.v_dvl_mps.y(), 0.0, 1e-9);
  EXPECT_NEAR(s.v_dvl_mps.z(), 0.0, 1e-9);
}

TEST(Pd0Parser, BeamVelocitiesUseTheJanusMatrix) {
  // A DVL moving forward at u over a flat bottom: beam 3 (forward) sees the bottom approach.
  // Bottom velocity along beam i (positive towards the transducer) is -u * sin(theta) for beam 3 ...
  const double u = 1.0, theta = 30.0 * M_PI / 180.0;
  test::Pd0Spec spec;
  spec.frame = 0;
  const int16_t along = int16_t(std::lround(1000 * u * std::sin(theta)));
  spec.bt_velocity_mmps[2] = along;  // beam 3 forward
  spec.bt_velocity_mmps[3] = int16_t(-along);
  DvlSample s;
  ASSERT_NO_FATAL_FAILURE(decodeToSample(spec, 0, &s));
  EXPECT_NEAR(s.v_dvl_mps.x(), u, 2e-3);
  EXPECT_NEAR(s.v_dvl_mps.y(), 0.0, 1e-9);
  EXPECT_NEAR(s.v_dvl_mps.z(), 0.0, 1e-9);
}

TEST(Pd0Parser, CorruptStructureIsRejectedNotRead) {
  auto bytes = test::buildPd0({});
  Pd0Ensemble e;
  const char* why = "";
  auto broken = bytes;
  broken[8] = 0xFF, broken[9] = 0xFF;  // second data type offset past the end
  EXPECT_FALSE(decodePd0Ensemble(broken.data(), broken.size(), &e, &why));
  EXPECT_FALSE(decodePd0Ensemble(bytes.data(), bytes.size() - 1, &e, &why));
  broken = bytes;
  broken[5] = 200;  // more data types than the ensemble can hold
  EXPECT_FALSE(decodePd0Ensemble(broken.data(), broken.size(), &e, &why));
}

}  // namespace
}  // namespace deepnav
