// camera.arm: the manipulator in front of the cameras (render/manipulator_arm.h) hides markers in its
// windows only, and the renderer's truth (depth, visible ids) includes it.
#include <cmath>

#include <gtest/gtest.h>

#include "tools/sim/render/manipulator_arm.h"
#include "tools/sim/render/stereo_renderer.h"
#include "tools/sim/render/view_tick.h"

namespace deepnav::sim {
namespace {

ArmWindow window() {
  ArmWindow w;
  w.t_start_s = 10.0;
  w.t_end_s = 30.0;
  w.reach_m = 0.6;
  w.height_m = 0.3;
  w.lateral_m = 0.3;
  return w;
}

TEST(SimRenderCameraArm, DeploysInsideItsWindowAndReachesItsTarget) {
  ManipulatorArm arm;
  arm.init({window()});
  EXPECT_EQ(arm.deployment(5.0), 0.0);
  EXPECT_EQ(arm.deployment(10.0), 0.0);
  EXPECT_NEAR(arm.deployment(12.0), 0.5, 1e-12);  // halfway through the 4 s unfolding
  EXPECT_EQ(arm.deployment(20.0), 1.0);
  EXPECT_NEAR(arm.deployment(29.0), 0.103515625, 1e-12);  // smootherstep(1/4) while folding
  EXPECT_EQ(arm.deployment(31.0), 0.0);
  // Deployed, the wrist is at the target within the sway (4 cm); stowed, it is under the base.
  const Eigen::Vector3f base = ManipulatorArm::kBase_in_robot_m;
  const Eigen::Vector3f wrist = arm.wristAt(20.0) - base;
  EXPECT_NEAR(wrist.x(), 0.6f, 0.041f);
  EXPECT_NEAR(wrist.y(), 0.3f, 1e-4f);
  EXPECT_NEAR(wrist.z(), 0.3f, 0.021f);
  EXPECT_LT((arm.wristAt(5.0) - base).z(), -0.15f);
  // It moves slowly: under 5 cm/s at the wrist while held.
  EXPECT_LT((arm.wristAt(20.1) - arm.wristAt(20.0)).norm(), 0.005f);
}

struct View {
  StereoFrame frame;
  RenderTruth truth;
};

View renderAt(StereoRenderer& renderer, const Scenario& s, TimeUs t_us) {
  View v;
  allocateStereoFrame(v.frame, 688, 516, 1);
  renderer.allocateTruth(&v.truth);
  EXPECT_TRUE(renderer.render(tickFacingFace(s, 0, 0.9, -0.15, 1.3, 0.0, 0.0, t_us), &v.frame, &v.truth));
  return v;
}

int pixelsNearerThan(const cv::Mat& depth_m, float limit_m) {
  return cv::countNonZero((depth_m > 0.0f) & (depth_m < limit_m));
}

TEST(SimRenderCameraArm, HidesMarkersInItsWindowOnlyAndIsInTheTruth) {
  // GIVEN the dwell view of the valves face (0.9 m; its valves come to 0.78 m) with and without an arm window over [10, 30] s
  Scenario plain;
  Scenario armed;
  armed.camera.arm = {window()};
  StereoRenderer r_plain, r_arm;
  std::string error;
  ASSERT_TRUE(r_plain.init(plain, 1, 1, &error)) << error;
  ASSERT_TRUE(r_arm.init(armed, 1, 1, &error)) << error;
  for (double t_s : {5.0, 40.0}) {
    // WHEN the arm is stowed THEN the pair and its truth are those without an arm, bit for bit
    const auto t_us = static_cast<TimeUs>(t_s * 1e6);
    const View a = renderAt(r_plain, plain, t_us), b = renderAt(r_arm, armed, t_us);
    EXPECT_EQ(cv::norm(a.frame.left, b.frame.left, cv::NORM_INF), 0.0) << t_s;
    EXPECT_EQ(cv::norm(a.frame.right, b.frame.right, cv::NORM_INF), 0.0) << t_s;
    EXPECT_EQ(cv::norm(a.truth.depth_m, b.truth.depth_m, cv::NORM_INF), 0.0) << t_s;
    EXPECT_EQ(a.truth.visible_marker_ids, b.truth.visible_marker_ids) << t_s;
    EXPECT_EQ(pixelsNearerThan(b.truth.depth_m, 0.7f), 0) << t_s;
  }
  const View a = renderAt(r_plain, plain, 20'000'000), b = renderAt(r_arm, armed, 20'000'000);
  // WHEN it is deployed THEN it covers part of both images, in the truth depth too (nearer than the face and its valves)
  ASSERT_EQ(a.truth.visible_marker_ids.size(), 2u);
  const int arm_pixels = pixelsNearerThan(b.truth.depth_m, 0.7f);
  EXPECT_GT(arm_pixels, 688 * 516 / 50);
  EXPECT_LT(arm_pixels, 688 * 516 / 2);
  // (the right camera, 0.3 m further right, sees less of it: the arm reaches to the left, lateral_m 0.3)
  EXPECT_LT(pixelsNearerThan(b.truth.right_depth_m, 0.7f), arm_pixels);
  // AND it hides at least one of the two markers, which the list of visible ids then lacks
  EXPECT_LT(b.truth.visible_marker_ids.size(), a.truth.visible_marker_ids.size());
  for (int id : b.truth.visible_marker_ids)
    EXPECT_NE(std::find(a.truth.visible_marker_ids.begin(), a.truth.visible_marker_ids.end(), id),
              a.truth.visible_marker_ids.end());
  std::printf("[arm] visible without %zu, with %zu; arm pixels left %d (%.1f %%)\n", a.truth.visible_marker_ids.size(),
              b.truth.visible_marker_ids.size(), arm_pixels, 100.0 * arm_pixels / (688 * 516));
}

}  // namespace
}  // namespace deepnav::sim
