// The simulated recording's per-frame ground truth (/truth/frame, /truth/depth, /truth/disparity),
// read back through TruthFrameReader: geometry consistent with the board's camera, points seen in the
// left image land in the right image where the true poses put them, and same seed, same file.
#include "drivers/replay/truth_frame_reader.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "board/config/vehicle_setup.h"
#include "drivers/replay/recording_reader.h"
#include "tests/support/test_dive.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

struct Dive {
  std::string path;
  VehicleSetup setup;
};

Dive makeDive(const std::string& name, double duration_s, std::uint64_t seed = 7) {
  Dive d;
  d.path = testing::makeTestDive(name, duration_s, seed);
  std::string error;
  EXPECT_TRUE(loadVehicleSetup(deepnav::testing::sourceDir() + "/board/sim/board.yaml", &d.setup, &error)) << error;
  return d;
}

TEST(SimTruthRecording, EveryPairHasItsTruthAndDisparityIsFocalBaselineOverDepth) {
  const Dive dive = makeDive("truth_maps", 1.0);
  TruthFrameReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(dive.path, &error)) << error;
  ASSERT_TRUE(reader.hasMaps());
  const auto& cam = dive.setup.config.camera;
  const double fb = cam.fx_px * cam.baseline_m;
  const Eigen::Isometry3d T_robot_cam = robotFromCamera(dive.setup.config);
  int pairs = 0;
  ASSERT_TRUE(reader.forEach(
      [&](const StereoFrame* pair, const FrameTruth& t) {
        ++pairs;
        EXPECT_TRUE(pair != nullptr && pair->t_us == t.t_us && pair->sequence == t.sequence);
        EXPECT_EQ(t.depth_m.cols, cam.width_px);
        EXPECT_EQ(t.depth_m.rows, cam.height_px);
        // disparity = fx B / Z within the recorded 1/128 px step and the depth's 16-bit rounding; no surface
        // in one map = none in the other
        int surface = 0, worst = 0;
        for (int v = 0; v < t.depth_m.rows; ++v) {
          for (int u = 0; u < t.depth_m.cols; ++u) {
            const float z = t.depth_m.at<float>(v, u), d = t.disparity_px.at<float>(v, u);
            if (z <= 0.0f) {
              worst += d != 0.0f;
              continue;
            }
            ++surface;
            worst += std::abs(d - fb / z) > 0.5 / 128.0 + 2e-5 * d;  // disparity step, depth rounding
          }
        }
        EXPECT_GT(surface, 0);
        EXPECT_EQ(worst, 0);
        // the left camera sits on the robot as the board says; the right one baseline_m to its right
        Eigen::Isometry3d T_odom_robot = Eigen::Isometry3d::Identity();
        T_odom_robot.linear() = t.q_odom_robot.toRotationMatrix();
        T_odom_robot.translation() = t.p_robot_in_odom_m;
        const Eigen::Isometry3d T_odom_cam = T_odom_robot * T_robot_cam;
        EXPECT_LT((T_odom_cam.translation() - t.p_left_cam_in_odom_m).norm(), 1e-9);
        EXPECT_LT(Eigen::Quaterniond(T_odom_cam.linear()).angularDistance(t.q_odom_left_cam), 1e-9);
        const Eigen::Vector3d right = t.q_odom_left_cam.conjugate() * (t.p_right_cam_in_odom_m - t.p_left_cam_in_odom_m);
        EXPECT_LT((right - Eigen::Vector3d(cam.baseline_m, 0, 0)).norm(), 1e-9);
        EXPECT_TRUE(std::is_sorted(t.visible_marker_ids.begin(), t.visible_marker_ids.end()));
        return true;
      },
      &error))
      << error;
  EXPECT_EQ(pairs, 11);  // 0, 0.1, ..., 1.0 s
  EXPECT_EQ(reader.stats().pairs, 11u);
  EXPECT_EQ(reader.stats().bad_messages, 0u);
  EXPECT_EQ(reader.stats().unmatched, 0u);
}

// A surface point seen at left pixel (u, v) with true depth Z, taken to odom with the true left pose
// and projected with the true right pose, lands at (u - d, v): the recorded poses, depth and disparity
// agree. (That the right image shows there what the left one shows at (u, v) is checked on the
// renderer's own truth at close range: sim_render_image_test, DisparityIs...MatchesTheRightImage; from
// this dive's 8 m the texture is below the sensor noise.)
TEST(SimTruthRecording, RecordedPosesDepthAndDisparityAgreeOnEverySurfacePoint) {
  const Dive dive = makeDive("truth_projection", 1.0);
  TruthFrameReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(dive.path, &error)) << error;
  const auto& cam = dive.setup.config.camera;
  int checked = 0;
  ASSERT_TRUE(reader.forEach(
      [&](const StereoFrame*, const FrameTruth& t) {
        for (int v = 20; v < t.depth_m.rows - 20; v += 37) {
          for (int u = 20; u < t.depth_m.cols - 20; u += 41) {
            const double z = t.depth_m.at<float>(v, u);
            if (z <= 0.0 || z > 15.0) continue;
            const Eigen::Vector3d p_cam((u - cam.cx_px) * z / cam.fx_px, (v - cam.cy_px) * z / cam.fy_px, z);
            const Eigen::Vector3d p_odom = t.q_odom_left_cam * p_cam + t.p_left_cam_in_odom_m;
            const Eigen::Vector3d p_right = t.q_odom_right_cam.conjugate() * (p_odom - t.p_right_cam_in_odom_m);
            const double ur = cam.fx_px * p_right.x() / p_right.z() + cam.cx_px;
            const double vr = cam.fy_px * p_right.y() / p_right.z() + cam.cy_px;
            const double d = t.disparity_px.at<float>(v, u);
            EXPECT_NEAR(ur, u - d, 1.0 / 128.0);  // disparity step + depth rounding (< 0.004 px)
            EXPECT_NEAR(vr, v, 1e-6);
            EXPECT_NEAR(p_right.z(), z, 1e-6 * z);
            ++checked;
          }
        }
        return true;
      },
      &error))
      << error;
  EXPECT_GT(checked, 500);
}

std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(SimTruthRecording, SameSeedSameRecordingAndTheReplayIgnoresTheTruthTopics) {
  // The same name: the scenario's path is part of the recording's metadata.
  const std::string a = testing::makeTestDive("seed", 1.0, 11);
  const std::string bytes_a = fileBytes(a);
  ASSERT_GT(bytes_a.size(), 1000u);
  EXPECT_FALSE(bytes_a == fileBytes(testing::makeTestDive("seed", 1.0, 12)));
  EXPECT_TRUE(bytes_a == fileBytes(testing::makeTestDive("seed", 1.0, 11)));
  // The replay driver sees only loop inputs, frames and /truth/odometry: no bad or unknown messages.
  RecordingReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(a, &error)) << error;
  int frames = 0;
  ASSERT_TRUE(reader.forEach(false, [&](const ReplayEvent& e) {
    frames += e.kind == ReplayEvent::Kind::kFrame;
    return true;
  }, &error)) << error;
  EXPECT_EQ(frames, 11);
  EXPECT_EQ(reader.stats().bad_messages, 0u);
  EXPECT_EQ(reader.stats().unknown_topic, 0u);
  EXPECT_EQ(reader.count(Topic::kFrameTruth), 11u);
}

}  // namespace
}  // namespace deepnav
