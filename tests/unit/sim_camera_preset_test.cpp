// camera.preset: dexrov (the DexROV rig behind its flat ports) and the camera effect keys.
#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/aruco.hpp>

#include "tools/sim/render/marker_layout.h"
#include "tools/sim/render/stereo_renderer.h"
#include "tools/sim/render/view_tick.h"
#include "tools/sim/scenario_loader.h"

namespace deepnav::sim {
namespace {

Scenario parse(const std::string& yaml) {
  Scenario s;
  std::string error;
  EXPECT_TRUE(parseScenario(yaml, "test.yaml", &s, &error)) << error;
  return s;
}

std::string parseError(const std::string& yaml) {
  Scenario s;
  std::string error;
  EXPECT_FALSE(parseScenario(yaml, "test.yaml", &s, &error));
  return error;
}

TEST(SimCameraPreset, DexrovSetsThePublishedRigAndExplicitKeysOverrideIt) {
  const Scenario s = parse("camera: {preset: dexrov}\n");
  const CameraConfig& c = s.camera;
  EXPECT_EQ(c.width_px, 688);
  EXPECT_EQ(c.height_px, 516);
  EXPECT_EQ(c.fx_px, 580.0);
  EXPECT_EQ(c.fy_px, 580.0);
  EXPECT_EQ(c.cx_px, 344.0);
  EXPECT_EQ(c.cy_px, 258.0);
  EXPECT_EQ(c.baseline_m, 0.30);
  EXPECT_TRUE(c.flat_port);
  EXPECT_EQ(c.port.glass_thickness_m, 0.020);
  EXPECT_EQ(c.port.pinhole_to_glass_m, 0.0028);
  EXPECT_EQ(c.port.n_glass, 1.7751);
  EXPECT_EQ(c.port.n_air, 1.0);
  EXPECT_EQ(c.port.n_water, FlatPort{}.n_water);
  // Everything else stays the default.
  EXPECT_EQ(c.p_cam_in_robot_m, CameraConfig{}.p_cam_in_robot_m);
  EXPECT_FALSE(c.motion_blur);
  // Explicit keys win, whatever their order in the file.
  const Scenario o = parse("camera:\n  fx_px: 600.0\n  port: {n_water: 1.33}\n  preset: dexrov\n");
  EXPECT_EQ(o.camera.fx_px, 600.0);
  EXPECT_EQ(o.camera.fy_px, 580.0);
  EXPECT_EQ(o.camera.port.n_water, 1.33);
  EXPECT_EQ(o.camera.port.n_glass, 1.7751);
  // None is the default rig.
  EXPECT_EQ(parse("camera: {preset: none}\n").camera, CameraConfig{});
}

TEST(SimCameraPreset, EffectKeysAreReadAndBadValuesNamed) {
  const Scenario s = parse(
      "camera:\n  motion_blur: true\n  noise_model: emva1288\n  sensor: {exposure_max_ms: 10.0, full_well_e: 9000}\n"
      "  arm:\n    - {t_start_s: 10.0, t_end_s: 30.0, reach_m: 0.7}\n");
  EXPECT_TRUE(s.camera.motion_blur);
  EXPECT_EQ(s.camera.noise_model, SensorNoiseModel::kEmva1288);
  EXPECT_EQ(s.camera.sensor.exposure_max_ms, 10.0);
  EXPECT_EQ(s.camera.sensor.full_well_e, 9000.0);
  EXPECT_EQ(s.camera.sensor.dark_noise_e, CameraSensorConfig{}.dark_noise_e);
  ASSERT_EQ(s.camera.arm.size(), 1u);
  EXPECT_EQ(s.camera.arm[0].reach_m, 0.7);
  EXPECT_EQ(s.camera.arm[0].height_m, ArmWindow{}.height_m);
  EXPECT_NE(parseError("camera: {preset: orion}\n").find("camera.preset"), std::string::npos);
  EXPECT_NE(parseError("camera: {noise_model: poisson}\n").find("camera.noise_model"), std::string::npos);
  EXPECT_NE(parseError("camera: {sensor: {exposure_max_ms: 0}}\n").find("camera.sensor.exposure_max_ms"),
            std::string::npos);
  EXPECT_NE(parseError("camera: {arm: [{t_start_s: 1}]}\n").find("needs 't_start_s' and 't_end_s'"), std::string::npos);
  EXPECT_NE(parseError("camera: {arm: [{t_start_s: 1, t_end_s: 5}]}\n").find("camera.arm[0].t_end_s"),
            std::string::npos);
  EXPECT_NE(parseError("camera: {arm: [{t_start_s: 1, t_end_s: 20, reach_m: 3}]}\n").find("camera.arm[0].reach_m"),
            std::string::npos);
  EXPECT_NE(parseError("camera: {arm: [{t_start_s: 20, t_end_s: 40}, {t_start_s: 30, t_end_s: 50}]}\n")
                .find("camera.arm[1].t_start_s"),
            std::string::npos);
}

TEST(SimCameraPreset, DexrovRendersThroughThePort) {
  // GIVEN the DexROV rig 1.2 m in front of the valves face, level with its markers
  const Scenario s = parse("camera: {preset: dexrov}\n");
  StereoRenderer renderer;
  std::string error;
  ASSERT_TRUE(renderer.init(s, 1, 1, &error)) << error;
  StereoFrame frame;
  allocateStereoFrame(frame, 688, 516, 1);
  RenderTruth truth;
  renderer.allocateTruth(&truth);
  const CameraTick tick = tickFacingFace(s, 0, 1.2, -0.15, 1.27);
  ASSERT_TRUE(renderer.render(tick, &frame, &truth));
  // THEN the images are raw (refracted, not rectified) and OpenCV finds the markers where the exact
  // refractive projection (vision/calib/flat_port.h) puts their corners, not where a pinhole would
  EXPECT_FALSE(frame.rectified);
  auto params = cv::aruco::DetectorParameters::create();
  params->cornerRefinementMethod = cv::aruco::CORNER_REFINE_SUBPIX;
  std::vector<std::vector<cv::Point2f>> corners;
  std::vector<int> ids;
  cv::aruco::detectMarkers(frame.left, arucoDictionaryByName("DICT_4X4_50"), corners, ids, params);
  ASSERT_GE(ids.size(), 2u);
  const ViewPose left = renderer.leftView(tick);
  const Eigen::Matrix3d R_cam_panel = left.R_panel_cam.transpose().cast<double>();
  const double h = 0.5 * renderer.panel().marker_size_m;
  const Eigen::Vector3d corner_in_marker[4] = {{-h, h, 0}, {h, h, 0}, {h, -h, 0}, {-h, -h, 0}};
  double worst_port_px = 0.0, best_pinhole_px = 1e9;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const PanelMarker* m = renderer.panel().marker(ids[i]);
    ASSERT_NE(m, nullptr);
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector3d p_panel = m->p_marker_in_panel_m + m->q_panel_marker * corner_in_marker[k];
      const Eigen::Vector3d p_cam = R_cam_panel * (p_panel - left.p_cam_in_panel_m.cast<double>());
      Eigen::Vector2d xy;
      ASSERT_TRUE(projectThroughPort(s.camera.port, p_cam, &xy));
      const Eigen::Vector2d port_px(580.0 * xy.x() + 344.0, 580.0 * xy.y() + 258.0);
      const Eigen::Vector2d pinhole_px(580.0 * p_cam.x() / p_cam.z() + 344.0, 580.0 * p_cam.y() / p_cam.z() + 258.0);
      const Eigen::Vector2d seen(corners[i][static_cast<std::size_t>(k)].x, corners[i][static_cast<std::size_t>(k)].y);
      worst_port_px = std::max(worst_port_px, (seen - port_px).norm());
      best_pinhole_px = std::min(best_pinhole_px, (seen - pinhole_px).norm());
    }
  }
  EXPECT_LT(worst_port_px, 1.0);
  EXPECT_GT(best_pinhole_px, 5.0);
  // AND the truth depth at a marker's centre (on the face, a plane 1.2 m ahead) is 1.2 m along the axis
  const cv::Point2f centre = 0.25f * (corners[0][0] + corners[0][1] + corners[0][2] + corners[0][3]);
  EXPECT_NEAR(truth.depth_m.at<float>(cvRound(centre.y), cvRound(centre.x)), 1.2f, 0.002f);
}

}  // namespace
}  // namespace deepnav::sim
