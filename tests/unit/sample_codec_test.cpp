#include "drivers/recording/sample_codec.h"

#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "drivers/recording/topics.h"
#include "nav/types/loop_stats.h"

namespace deepnav {
namespace {

std::vector<std::uint8_t> buffer(std::size_t n = 4096) { return std::vector<std::uint8_t>(n); }

template <typename T>
T roundTrip(const T& sample) {
  auto buf = buffer();
  const InputSample in = sample;
  const std::size_t n = encodeInput(in, buf.data(), buf.size());
  EXPECT_GT(n, 0u);
  InputSample out;
  EXPECT_TRUE(decodeInput(inputTopic(in), buf.data(), n, &out));
  EXPECT_EQ(inputKind(out), inputKind(in));
  return std::get<T>(out);
}

TEST(SampleCodec, ImuSurvivesBitForBit) {
  ImuSample s;
  s.t_us = 1234567891234;
  s.w_imu_radps = {0.1, -0.2, 1.0 / 3.0};
  s.f_imu_mps2 = {0.01, 0.02, 9.80665};
  const ImuSample a = roundTrip(s);
  EXPECT_EQ(a.t_us, s.t_us);
  EXPECT_EQ(std::memcmp(a.w_imu_radps.data(), s.w_imu_radps.data(), 24), 0);
  EXPECT_EQ(std::memcmp(a.f_imu_mps2.data(), s.f_imu_mps2.data(), 24), 0);
  EXPECT_FALSE(a.has_orientation);
  s.has_orientation = true;
  s.orientation_sigma_rad = 0.0123;
  s.q_odom_imu = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  const ImuSample b = roundTrip(s);
  EXPECT_TRUE(b.has_orientation);
  EXPECT_EQ(b.orientation_sigma_rad, s.orientation_sigma_rad);
  EXPECT_EQ(b.q_odom_imu.coeffs(), s.q_odom_imu.coeffs());
}

TEST(SampleCodec, DvlDepthHeadingAttitudeVisionSurvive) {
  DvlSample d;
  d.t_us = 42;
  d.v_dvl_mps = {0.3, -0.05, 0.001};
  d.beam_range_m = {2.1, 2.2, 2.3, 2.4};
  d.beam_valid_mask = 0b1011;
  d.valid = true;
  d.fom_mps = 0.004;
  d.altitude_m = 1.9;
  d.cov_v_dvl_mps2 << 1, 2, 3, 4, 5, 6, 7, 8, 9;
  const DvlSample d2 = roundTrip(d);
  EXPECT_EQ(d2.v_dvl_mps, d.v_dvl_mps);
  EXPECT_EQ(d2.cov_v_dvl_mps2, d.cov_v_dvl_mps2);
  EXPECT_EQ(d2.beam_range_m, d.beam_range_m);
  EXPECT_EQ(d2.beam_valid_mask, d.beam_valid_mask);
  EXPECT_EQ(d2.altitude_m, d.altitude_m);

  DepthSample p{99, 1.0e7, 998.5, 0.02};
  const DepthSample p2 = roundTrip(p);
  EXPECT_EQ(p2.depth_m, p.depth_m);
  EXPECT_EQ(p2.pressure_pa, p.pressure_pa);

  HeadingSample h{-5, 6.1, true, 0.03};  // negative times survive (floor division of the stamp)
  const HeadingSample h2 = roundTrip(h);
  EXPECT_EQ(h2.t_us, -5);
  EXPECT_EQ(h2.heading_rad, 6.1);
  EXPECT_TRUE(h2.is_true);

  AttitudeSample at{7, 0.01, -0.02, 0.001};
  EXPECT_EQ(roundTrip(at).pitch_rad, -0.02);

  VisionResult v;
  v.t_us = 100000;
  v.sequence = 17;
  v.frame_ok = true;
  v.mdm_f1 = 0.4;
  v.image_quality = 0.55;
  v.marker_count = 2;
  v.markers[1].id = 33;
  v.markers[1].corners_px[3] = {100.25, 200.5};
  v.markers[1].p_marker_in_cam_m = {0.1, -0.2, 1.5};
  v.markers[1].ambiguous = true;
  v.markers[1].obliqueness_rad = 0.3;
  const VisionResult v2 = roundTrip(v);
  EXPECT_EQ(v2.sequence, 17u);
  EXPECT_EQ(v2.image_quality, 0.55);
  ASSERT_EQ(v2.marker_count, 2);
  EXPECT_EQ(v2.markers[1].id, 33);
  EXPECT_EQ(v2.markers[1].corners_px[3], Eigen::Vector2d(100.25, 200.5));
  EXPECT_EQ(v2.markers[1].p_marker_in_cam_m, v.markers[1].p_marker_in_cam_m);
  EXPECT_TRUE(v2.markers[1].ambiguous);
  EXPECT_EQ(v2.markers[1].obliqueness_rad, 0.3);
}

TEST(SampleCodec, NavSolutionSurvivesBitForBit) {
  NavSolution s;
  s.t_us = 5'000'000;
  s.p_robot_in_odom_m = {1.0 / 7.0, -2.5, -998.25};
  s.q_odom_robot = Eigen::Quaterniond(Eigen::AngleAxisd(1.1, Eigen::Vector3d::UnitZ()));
  s.v_robot_in_odom_mps = {0.1, 0.2, -0.0};
  s.cov_pose = Eigen::Matrix<double, 6, 6>::Random();
  s.cov_v_mps2 = Eigen::Matrix3d::Random();
  s.stage = NavStage::kOptimised;
  s.status = 0x2f;
  s.faults = rejectBit(kSrcDvl) | staleBit(kSrcMarkers);
  s.image_quality = 0.61;
  s.rejected_total = 3;
  auto buf = buffer();
  const std::size_t n = encodeSolution(s, buf.data(), buf.size());
  ASSERT_GT(n, 0u);
  NavSolution out;
  ASSERT_TRUE(decodeSolution(buf.data(), n, &out));
  EXPECT_TRUE(sameBits(out, s));
  out.v_robot_in_odom_mps.z() = 0.0;  // +0 differs from -0 in its bits
  EXPECT_FALSE(sameBits(out, s));
}

TEST(SampleCodec, TruthRoundTripsThroughOdometry) {
  TruthSample t;
  t.t_us = 77;
  t.p_robot_in_odom_m = {1, 2, 3};
  t.q_odom_robot = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.1, 0.2, 1).normalized()));
  t.v_robot_in_odom_mps = {0.5, -0.1, 0.02};
  auto buf = buffer();
  const std::size_t n = encodeTruth(t, buf.data(), buf.size());
  TruthSample out;
  ASSERT_TRUE(decodeTruth(buf.data(), n, &out));
  EXPECT_EQ(out.p_robot_in_odom_m, t.p_robot_in_odom_m);
  EXPECT_NEAR((out.v_robot_in_odom_mps - t.v_robot_in_odom_mps).norm(), 0.0, 1e-15);
}

TEST(SampleCodec, StereoImagesRoundTripIntoPreallocatedFrames) {
  StereoFrame f;
  ASSERT_TRUE(allocateStereoFrame(f, 40, 30, 1));
  cv::randu(f.left, 0, 255);
  cv::randu(f.right, 0, 255);
  f.t_us = 123;
  f.exposure_us = 4000;
  f.sequence = 9;
  auto buf = buffer(40 * 30 + 256);
  StereoFrame g;
  ASSERT_TRUE(allocateStereoFrame(g, 40, 30, 1));
  std::size_t n = encodeStereoInfo(f, buf.data(), buf.size());
  ASSERT_TRUE(decodeStereoInfo(buf.data(), n, &g));
  EXPECT_EQ(g.exposure_us, 4000u);
  n = encodeImage(f, true, buf.data(), buf.size());
  ASSERT_TRUE(decodeImageInto(buf.data(), n, true, &g));
  n = encodeImage(f, false, buf.data(), buf.size());
  ASSERT_TRUE(decodeImageInto(buf.data(), n, false, &g));
  EXPECT_EQ(cv::norm(f.left, g.left, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(f.right, g.right, cv::NORM_INF), 0.0);
  StereoFrame wrong;
  ASSERT_TRUE(allocateStereoFrame(wrong, 41, 30, 1));
  EXPECT_FALSE(decodeImageInto(buf.data(), n, false, &wrong));
  EXPECT_EQ(encodeImage(f, true, buf.data(), 100), 0u);  // too small a buffer: refused, not overrun
}

TEST(SampleCodec, MalformedMessagesAreRejected) {
  auto buf = buffer();
  const InputSample in = DvlSample{};
  const std::size_t n = encodeInput(in, buf.data(), buf.size());
  InputSample out;
  for (std::size_t cut = 0; cut < n; ++cut) EXPECT_FALSE(decodeInput(Topic::kDvlBottomTrack, buf.data(), cut, &out));
  NavSolution s;
  EXPECT_FALSE(decodeSolution(buf.data(), 3, &s));
}

TEST(SampleCodec, EveryTopicHasASchema) {
  for (std::size_t i = 0; i < kTopicCount; ++i) {
    const auto topic = static_cast<Topic>(i);
    EXPECT_FALSE(topicSchema(topic).empty()) << topicInfo(topic).name;
    EXPECT_EQ(topicByName(topicInfo(topic).name), topic);
  }
  EXPECT_NE(topicSchema(Topic::kNavSolution).find("MSG: geometry_msgs/Point"), std::string::npos);
  LoopStats st;
  st.task_count = 1;
  st.names[0] = "nav";
  auto buf = buffer();
  EXPECT_GT(encodeLoopStats(1, st, buf.data(), buf.size()), 0u);
}

}  // namespace
}  // namespace deepnav
