// The stereo renderer's images against its own ground truth: marker corners where the true pose projects
// them, disparity = f B / Z and consistent with the right image, the visible-marker list, determinism and
// the effect of turbidity.
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include <gtest/gtest.h>
#include <opencv2/aruco.hpp>
#include <opencv2/imgproc.hpp>

#include "tools/sim/render/stereo_renderer.h"
#include "tools/sim/render/view_tick.h"
#include "tools/sim/sensor_simulator.h"

namespace deepnav::sim {
namespace {

struct Rendered {
  StereoFrame frame;
  RenderTruth truth;
};

// One renderer per (preset, seed, channels): init paints the textures, the slow part of a test.
StereoRenderer& rendererFor(WaterPreset preset, std::uint64_t seed, int channels = 1) {
  static std::map<std::tuple<int, std::uint64_t, int>, std::unique_ptr<StereoRenderer>> cache;
  auto& r = cache[{static_cast<int>(preset), seed, channels}];
  if (!r) {
    Scenario s;
    s.water.preset = preset;
    r = std::make_unique<StereoRenderer>();
    std::string error;
    EXPECT_TRUE(r->init(s, seed, channels, &error)) << error;
  }
  return *r;
}

Rendered render(StereoRenderer& renderer, const CameraTick& tick, int channels = 1) {
  Rendered out;
  const Scenario s;
  allocateStereoFrame(out.frame, s.camera.width_px, s.camera.height_px, channels);
  renderer.allocateTruth(&out.truth);
  EXPECT_TRUE(renderer.render(tick, &out.frame, &out.truth));
  return out;
}

// The dwell in front of the valves face, as the simulated dive flies it (disturbances included).
CameraTick dwellTick() {
  SensorSimulator sim;
  std::string error;
  EXPECT_TRUE(sim.init(Scenario{}, 1, &error)) << error;
  return sim.cameraAt(36'000'000);
}

Eigen::Vector2d project(const Scenario& s, const CameraTick& tick, const Eigen::Vector3d& p_in_odom) {
  const Eigen::Vector3d p = tick.q_odom_left_cam.conjugate() * (p_in_odom - tick.p_left_cam_in_odom_m);
  return {s.camera.fx_px * p.x() / p.z() + s.camera.cx_px, s.camera.fy_px * p.y() / p.z() + s.camera.cy_px};
}

// Detects the markers of the left image and returns the largest distance between a detected corner
// and the projection of the true corner; ids detected go to *ids (ascending).
double worstCornerErrorPx(StereoRenderer& renderer, const CameraTick& tick, std::vector<int>* ids_out) {
  const Scenario s;
  const Rendered r = render(renderer, tick);
  auto params = cv::aruco::DetectorParameters::create();
  params->cornerRefinementMethod = cv::aruco::CORNER_REFINE_SUBPIX;
  std::vector<std::vector<cv::Point2f>> corners;
  std::vector<int> ids;
  cv::aruco::detectMarkers(r.frame.left, arucoDictionaryByName("DICT_4X4_50"), corners, ids, params);
  EXPECT_EQ(r.truth.visible_marker_ids.size(), ids.size());
  const Eigen::Isometry3d T_odom_panel = panelPoseInOdom(s);
  const PanelDescription& panel = renderer.panel();
  const double h = 0.5 * panel.marker_size_m;
  const Eigen::Vector3d corner_in_marker[4] = {{-h, h, 0}, {h, h, 0}, {h, -h, 0}, {-h, -h, 0}};
  double worst_px = 0.0;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const PanelMarker* m = panel.marker(ids[i]);
    if (m == nullptr) {
      ADD_FAILURE() << "unknown id " << ids[i];
      continue;
    }
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector3d p_panel = m->p_marker_in_panel_m + m->q_panel_marker * corner_in_marker[k];
      const Eigen::Vector2d expected = project(s, tick, T_odom_panel * p_panel);
      worst_px = std::max(worst_px, (expected - Eigen::Vector2d(corners[i][k].x, corners[i][k].y)).norm());
    }
  }
  *ids_out = ids;
  std::sort(ids_out->begin(), ids_out->end());
  return worst_px;
}

TEST(SimRenderImage, MarkerCornersLandWhereTheTruePoseProjectsThem) {
  StereoRenderer& renderer = rendererFor(WaterPreset::kClear, 1);
  std::vector<int> ids;
  // GIVEN the left image of the dive's valves-face dwell (cameras 0.9 m from the face, disturbances
  // included) WHEN OpenCV detects the markers (subpixel corners) THEN the two markers of the left
  // column are found, each corner within 1 px of the projection of the true corner.
  const double dwell_error_px = worstCornerErrorPx(renderer, dwellTick(), &ids);
  EXPECT_LT(dwell_error_px, 1.0);
  RecordProperty("dwell_worst_corner_error_px", std::to_string(dwell_error_px));
  EXPECT_EQ(ids, (std::vector<int>{0, 2}));
  // The same from 1.5 m in front of the grasping face, where its four markers are in the image.
  const Scenario s;
  const double far_error_px = worstCornerErrorPx(renderer, tickFacingFace(s, 1, 1.5, 0.0, 1.3, -2.0, 2.0), &ids);
  EXPECT_LT(far_error_px, 1.0);
  RecordProperty("far_worst_corner_error_px", std::to_string(far_error_px));
  EXPECT_EQ(ids, (std::vector<int>{4, 5, 6, 7}));
}

TEST(SimRenderImage, DisparityIsFocalTimesBaselineOverDepthAndMatchesTheRightImage) {
  const Scenario s;
  StereoRenderer& renderer = rendererFor(WaterPreset::kClear, 1);
  const Rendered r = render(renderer, dwellTick());
  const double fb = s.camera.fx_px * s.camera.baseline_m;
  int checked = 0, consistent = 0, ncc_right = 0, ncc_checked = 0;
  for (int v = 20; v < s.camera.height_px - 20; v += 23) {
    for (int u = 80; u < s.camera.width_px - 20; u += 29) {
      const float z = r.truth.depth_m.at<float>(v, u), d = r.truth.disparity_px.at<float>(v, u);
      if (z <= 0.0f) {
        EXPECT_EQ(d, 0.0f);
        continue;
      }
      EXPECT_NEAR(d, fb / z, 1e-4 * d);
      // The same scene point in the right image: shifted left by the disparity, at the same depth.
      const double u_right = u - d;
      const int ur = static_cast<int>(std::lround(u_right));
      if (ur < 1 || ur >= s.camera.width_px - 1) continue;
      // Away from depth edges (the point may be occluded in the right view there).
      const float zl = r.truth.depth_m.at<float>(v, u - 1), zr = r.truth.depth_m.at<float>(v, u + 1);
      if (std::abs(zl - z) > 0.01f * z || std::abs(zr - z) > 0.01f * z) continue;
      ++checked;
      // Either the right camera sees the same point (same depth), or something nearer hides it.
      const float z_right = r.truth.right_depth_m.at<float>(v, ur);
      if (std::abs(z_right - z) < 0.01f * z) {
        ++consistent;
      } else {
        EXPECT_LT(z_right, z) << "right camera sees through a surface at (" << u << ", " << v << ")";
      }
      // And the image agrees: a textured patch on one surface (depth within 1 %) matches best at the
      // true disparity, within a pixel.
      if (ur < 19 || ur >= s.camera.width_px - 19 || u < 11 || u >= s.camera.width_px - 11) continue;
      const cv::Rect patch_l(u - 10, v - 10, 21, 21);
      double z_min = 0.0, z_max = 0.0;
      cv::minMaxLoc(r.truth.depth_m(patch_l), &z_min, &z_max);
      if (z_max - z_min > 0.01 * z) continue;
      cv::Scalar mean, std_dev;
      cv::meanStdDev(r.frame.left(patch_l), mean, std_dev);
      if (std_dev[0] < 8.0) continue;  // too little texture for the correlation to mean anything
      cv::Mat scores;
      cv::matchTemplate(r.frame.right(cv::Rect(ur - 18, v - 10, 37, 21)), r.frame.left(patch_l), scores,
                        cv::TM_CCOEFF_NORMED);
      cv::Point best;
      cv::minMaxLoc(scores, nullptr, nullptr, nullptr, &best);
      ++ncc_checked;
      if (std::abs(best.x - 8) <= 1) ++ncc_right;
    }
  }
  ASSERT_GT(checked, 100);
  EXPECT_GE(consistent, checked * 9 / 10) << consistent << " / " << checked;
  ASSERT_GT(ncc_checked, 50);
  EXPECT_GE(ncc_right, ncc_checked * 95 / 100) << ncc_right << " / " << ncc_checked;
}

TEST(SimRenderImage, VisibleMarkersFollowTheView) {
  const Scenario s;
  StereoRenderer& renderer = rendererFor(WaterPreset::kModerate, 1);
  // Facing each face at 1.5 m, camera 1.3 m above the seabed (the dwell poses without disturbances).
  // The left camera sits baseline/2 left of the face centre so the pair is centred on it.
  const double half_b = 0.5 * s.camera.baseline_m;
  EXPECT_EQ(render(renderer, tickFacingFace(s, 0, 1.5, -half_b, 1.3)).truth.visible_marker_ids,
            (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(render(renderer, tickFacingFace(s, 1, 1.5, -half_b, 1.3)).truth.visible_marker_ids,
            (std::vector<int>{4, 5, 6, 7}));
  EXPECT_EQ(render(renderer, tickFacingFace(s, 2, 1.5, -half_b, 1.3)).truth.visible_marker_ids,
            (std::vector<int>{8, 9}));
  // Close to the face and shifted right: only the right-hand markers are in the image.
  EXPECT_EQ(render(renderer, tickFacingFace(s, 0, 0.8, 0.45, 1.25)).truth.visible_marker_ids,
            (std::vector<int>{1, 3}));
  // Looking at the face from behind the panel (inside, open back): its markers are on the other side.
  const CameraTick behind = tickFacingFace(s, 0, -1.2, -half_b, 1.0, 180.0);
  EXPECT_TRUE(render(renderer, behind).truth.visible_marker_ids.empty());
  // Looking along the front face from beside the left face: the grasping-face markers are edge-on or
  // behind the corner, none visible.
  EXPECT_TRUE(render(renderer, tickFacingFace(s, 0, 1.5, 1.6, 1.0, 90.0)).truth.visible_marker_ids.empty());
}

TEST(SimRenderImage, PanelPlacedWhereTheScenarioPutsIt) {
  // GIVEN a panel moved off the odometry origin, yawed, on a seabed 2 m below the origin
  Scenario s;
  s.panel.centre_in_odom_m = {5.0, -3.0};
  s.panel.front_yaw_deg = 30.0;
  s.environment.odom_origin_depth_m = 998.0;
  s.trajectory.start_depth_m = 996.0;
  s.trajectory.circle_depth_m = 996.5;
  StereoRenderer renderer;
  std::string error;
  ASSERT_TRUE(renderer.init(s, 1, 1, &error)) << error;
  // WHEN the rig faces the grasping face from 1.5 m (ticks built in odom through panelPoseInOdom)
  // THEN its four markers are visible, and bare paint (between the left handle and the markers) is
  // 1.5 m away along the optical axis
  EXPECT_EQ(render(renderer, tickFacingFace(s, 1, 1.5, -0.15, 1.3)).truth.visible_marker_ids,
            (std::vector<int>{4, 5, 6, 7}));
  const Rendered r = render(renderer, tickFacingFace(s, 1, 1.5, -0.3, 1.25));
  EXPECT_NEAR(r.truth.depth_m.at<float>(258, 344), 1.5f, 1e-4f);
}

TEST(SimRenderImage, SameSeedSameImagesOtherSeedOtherTextures) {
  const Scenario s;
  const CameraTick tick = tickFacingFace(s, 0, 1.5, -0.15, 1.3, 0.0, 20.0);
  const Rendered a = render(rendererFor(WaterPreset::kModerate, 1), tick);
  const Rendered b = render(rendererFor(WaterPreset::kModerate, 1), tick);
  EXPECT_EQ(cv::norm(a.frame.left, b.frame.left, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(a.frame.right, b.frame.right, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(a.truth.depth_m, b.truth.depth_m, cv::NORM_INF), 0.0);
  const Rendered c = render(rendererFor(WaterPreset::kModerate, 2), tick);
  // Other seed: other paint, relief and noise (the panel itself does not move).
  cv::Mat diff;
  cv::absdiff(a.frame.left, c.frame.left, diff);
  EXPECT_GT(cv::mean(diff)[0], 4.0);
  // The panel's faces are where they were: depth agrees on the face (seabed relief differs).
  EXPECT_NEAR(a.truth.depth_m.at<float>(100, 344), c.truth.depth_m.at<float>(100, 344), 1e-5);
  EXPECT_EQ(a.frame.t_us, tick.t_us);
  EXPECT_TRUE(a.frame.rectified);
}

TEST(SimRenderImage, MurkyWaterHasLessContrastThanClear) {
  const Scenario s;
  const CameraTick tick = tickFacingFace(s, 0, 1.5, -0.15, 1.3);
  cv::Scalar mean_clear, std_clear, mean_murky, std_murky;
  cv::meanStdDev(render(rendererFor(WaterPreset::kClear, 1), tick).frame.left, mean_clear, std_clear);
  cv::meanStdDev(render(rendererFor(WaterPreset::kMurky, 1), tick).frame.left, mean_murky, std_murky);
  EXPECT_LT(std_murky[0], 0.6 * std_clear[0]) << std_murky[0] << " vs " << std_clear[0];
}

TEST(SimRenderImage, ColourFramesAndBadFramesRejected) {
  const Scenario s;
  StereoRenderer& renderer = rendererFor(WaterPreset::kClear, 1, 3);
  const Rendered r = render(renderer, tickFacingFace(s, 1, 1.5, -0.15, 1.3), 3);
  EXPECT_EQ(r.frame.left.type(), CV_8UC3);
  // Yellow paint: red above blue on the grasping face.
  const cv::Scalar m = cv::mean(r.frame.left(cv::Rect(300, 200, 80, 80)));
  EXPECT_GT(m[2], m[0] + 20.0);
  StereoFrame grey;
  allocateStereoFrame(grey, s.camera.width_px, s.camera.height_px, 1);
  EXPECT_FALSE(renderer.render(tickFacingFace(s, 1, 1.5, 0.0, 1.3), &grey, nullptr));
  StereoRenderer bad;
  std::string error;
  EXPECT_FALSE(bad.init(s, 1, 2, &error));
  EXPECT_NE(error.find("channels"), std::string::npos);
}

}  // namespace
}  // namespace deepnav::sim
