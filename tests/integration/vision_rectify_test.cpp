// Rectification inside the vision pipeline (issue 10): a board naming a calibration and a flat port makes
// the pipeline remap every raw pair into its own preallocated images (no allocation per pair), and the
// markers and the ORB VO then measure the rendered flat-port scene as it is; the same pairs with the
// port ignored (camera.port.model: none) are ~26 % short.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "board/config/board_overrides.h"
#include "board/config/vehicle_setup.h"
#include "tests/support/alloc_counter.h"
#include "tools/sim/port_calibration.h"
#include "tools/sim/render/stereo_renderer.h"
#include "tools/sim/render/view_tick.h"
#include "tools/sim/scenario_loader.h"
#include "vision/iqa/mdm.h"
#include "vision/pipeline/vision_pipeline.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

Eigen::Isometry3d poseOf(const sim::ViewPose& v) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = v.R_panel_cam.cast<double>();
  T.translation() = v.p_cam_in_panel_m.cast<double>();
  return T;
}

class VisionRectify : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string error;
    ASSERT_TRUE(sim::loadScenario(deepnav::testing::sourceDir() + "/tools/sim/scenarios/flat-port.yaml", &scenario_,
                                  &error))
        << error;
    ASSERT_TRUE(scenario_.camera.flat_port);
    // The board the simulator stores with a flat-port dive, and the same with the port ignored.
    for (VehicleSetup* setup : {&pinax_, &plain_}) {
      ASSERT_TRUE(loadVehicleSetup(deepnav::testing::sourceDir() + "/board/sim/board.yaml", setup, &error)) << error;
      bool described = false;
      ASSERT_TRUE(sim::describeSimulatedPort(scenario_, setup, &described, &error)) << error;
      ASSERT_TRUE(described);
      ASSERT_TRUE(setup->rectify);
    }
    ASSERT_TRUE(applyBoardOverrides({"camera.port.model=none"}, &plain_, &error)) << error;
    ASSERT_TRUE(plain_.rectify);
    ASSERT_TRUE(renderer_.init(scenario_, 1, 1, &error)) << error;
  }

  void render(const CameraTick& tick, StereoFrame* frame) {
    ASSERT_TRUE(allocateStereoFrame(*frame, scenario_.camera.width_px, scenario_.camera.height_px, 1));
    sim::RenderTruth truth;
    renderer_.allocateTruth(&truth);
    ASSERT_TRUE(renderer_.render(tick, frame, &truth));
    ASSERT_FALSE(frame->rectified);
  }

  // The rectified left camera in the raw left camera (identity but for the rectification and PinAx's z_v).
  static Eigen::Isometry3d camFromRect(const VehicleSetup& s) {
    return robotFromCamera(s.config).inverse() * robotFromCamera(s);
  }

  sim::Scenario scenario_;
  VehicleSetup pinax_, plain_;
  sim::StereoRenderer renderer_;
};

// The remap step of the pipeline: raw pairs in, no heap allocation per pair once initialised; and the
// pipeline really measures the remapped pair (its MDM is that of the images remapped by hand).
TEST_F(VisionRectify, RemapAllocatesNothingPerPair) {
  for (int channels : {1, 3}) {
    VisionPipelineConfig config = visionConfig(pinax_);
    config.channels = channels;
    config.run_orb = false;
    config.detect_markers = false;
    VisionPipeline vision;
    std::string error;
    ASSERT_TRUE(vision.init(config, &error)) << error;
    StereoFrame frame;
    ASSERT_TRUE(allocateStereoFrame(frame, config.width_px, config.height_px, channels));
    cv::randu(frame.left, 0, 255);
    cv::randu(frame.right, 0, 255);
    frame.rectified = false;
    const VisionContext context;
    VisionResult result;
    vision.process(frame, context, &result);
    long allocations = 0;
    {
      Counting counting;
      for (int i = 0; i < 10; ++i) vision.process(frame, context, &result);
      allocations = counting.count();
    }
    EXPECT_EQ(allocations, 0) << channels << " channel(s)";
    ASSERT_TRUE(result.frame_ok);
    StereoRectifier rectifier;
    ASSERT_TRUE(rectifier.init(pinax_.rectification, &error)) << error;
    cv::Mat left(frame.left.size(), frame.left.type()), right(frame.right.size(), frame.right.type());
    ASSERT_TRUE(rectifier.rectify(frame.left, frame.right, left, right));
    MdmScore by_hand, raw;
    MdmWorkspace ws;
    ASSERT_TRUE(computeMdm(left, &by_hand, &ws));
    ASSERT_TRUE(computeMdm(frame.left, &raw, &ws));
    EXPECT_DOUBLE_EQ(result.mdm_f1, by_hand.f1);
    EXPECT_DOUBLE_EQ(result.mdm_f2, by_hand.f2);
    EXPECT_NE(result.mdm_f2, raw.f2);  // the remap changed the image
  }
}

// The rectifier's own bilinear loop is cv::remap INTER_LINEAR on the same fixed-point maps (to one grey
// level), border included; and it refuses what it cannot write without allocating.
TEST_F(VisionRectify, RectifierMatchesCvRemap) {
  const StereoRectification& maps = pinax_.rectification;
  StereoRectifier rectifier;
  std::string error;
  ASSERT_TRUE(rectifier.init(maps, &error)) << error;
  for (int type : {CV_8UC1, CV_8UC3}) {
    cv::Mat raw_left(maps.image_size, type), raw_right(maps.image_size, type);
    cv::randu(raw_left, 0, 256);
    cv::randu(raw_right, 0, 256);
    cv::Mat left(maps.image_size, type), right(maps.image_size, type), cv_left, cv_right;
    ASSERT_TRUE(rectifier.rectify(raw_left, raw_right, left, right));
    cv::remap(raw_left, cv_left, maps.left_map_xy, maps.left_map_frac, cv::INTER_LINEAR, cv::BORDER_CONSTANT);
    cv::remap(raw_right, cv_right, maps.right_map_xy, maps.right_map_frac, cv::INTER_LINEAR, cv::BORDER_CONSTANT);
    EXPECT_LE(cv::norm(left, cv_left, cv::NORM_INF), 1.0);
    EXPECT_LE(cv::norm(right, cv_right, cv::NORM_INF), 1.0);
    cv::Mat small(maps.image_size.height / 2, maps.image_size.width, type);
    EXPECT_FALSE(rectifier.rectify(raw_left, raw_right, small, right));
  }
  cv::Mat f32(maps.image_size, CV_32FC1), out(maps.image_size, CV_32FC1);
  EXPECT_FALSE(rectifier.rectify(f32, f32, out, out));
}

TEST_F(VisionRectify, RectifiedIntrinsicsReplaceTheBoardsAndTheCameraFrameFollows) {
  const VisionPipelineConfig v = visionConfig(pinax_);
  EXPECT_TRUE(v.rectify);
  // Water magnifies the view: the virtual pinhole's focal length is about n_water times the in-air one.
  EXPECT_GT(v.rig.fx_px, 1.25 * scenario_.camera.fx_px);
  EXPECT_LT(v.rig.fx_px, 1.5 * scenario_.camera.fx_px);
  EXPECT_EQ(v.markers.camera.fx_px, v.rig.fx_px);
  EXPECT_NEAR(v.rig.baseline_m, scenario_.camera.baseline_m, 1e-3);
  const Eigen::Isometry3d T = camFromRect(pinax_);
  EXPECT_NEAR(T.translation().z(), pinax_.rectification.virtual_centre_z_m, 1e-12);
  EXPECT_NE(pinax_.rectification.virtual_centre_z_m, 0.0);
  const VisionPipelineConfig p = visionConfig(plain_);
  EXPECT_NEAR(p.rig.fx_px, scenario_.camera.fx_px, 1.0);  // ideal in-air pair: rectification changes nothing
  EXPECT_TRUE(camFromRect(plain_).isApprox(Eigen::Isometry3d::Identity(), 1e-9));
}

// Markers and ORB on rendered flat-port pairs through the pipeline, with PinAx and with the port ignored.
TEST_F(VisionRectify, MarkersAndOrbMatchTheTruthWithPinax) {
  // Two pairs 1.6 m and 1.5 m in front of the valves face, 8 cm apart sideways, turned 2 deg.
  const CameraTick a = sim::tickFacingFace(scenario_, 0, 1.6, 0.0, 1.2, 0.0, 0.0, 0);
  const CameraTick b = sim::tickFacingFace(scenario_, 0, 1.5, 0.08, 1.2, 2.0, 0.0, 100000);
  StereoFrame frame_a, frame_b;
  render(a, &frame_a);
  render(b, &frame_b);
  const Eigen::Isometry3d T_panel_a = poseOf(renderer_.leftView(a));
  const Eigen::Isometry3d T_panel_b = poseOf(renderer_.leftView(b));
  std::printf("%-12s | %8s | %10s | %10s | %9s\n", "", "markers", "range err", "ORB |t|", "ORB rot");
  for (const VehicleSetup* setup : {&pinax_, &plain_}) {
    const bool corrected = setup == &pinax_;
    VisionPipelineConfig config = visionConfig(*setup);
    config.modality.mode = VoMode::kOrb;
    config.clock_us = nullptr;
    VisionPipeline vision;
    std::string error;
    ASSERT_TRUE(vision.init(config, &error)) << error;
    VisionContext context;
    context.stage = NavStage::kOptimised;
    VisionResult result_a, result_b;
    vision.process(frame_a, context, &result_a);
    vision.process(frame_b, context, &result_b);
    ASSERT_TRUE(result_a.frame_ok && result_b.frame_ok);
    // Truth in the pipeline's (rectified) camera frame.
    const Eigen::Isometry3d T_cam_rect = camFromRect(*setup);
    double range_error = 0.0;
    for (int i = 0; i < result_a.marker_count; ++i) {
      const MarkerObservation& m = result_a.markers[static_cast<std::size_t>(i)];
      const PanelMarker* known = renderer_.panel().marker(m.id);
      ASSERT_NE(known, nullptr);
      const Eigen::Vector3d truth = (T_panel_a * T_cam_rect).inverse() * known->p_marker_in_panel_m;
      range_error += (m.p_marker_in_cam_m.norm() - truth.norm()) / truth.norm() / result_a.marker_count;
      if (corrected) {
        EXPECT_LT((m.p_marker_in_cam_m - truth).norm(), 0.03) << "marker " << m.id;
      }
    }
    ASSERT_GE(result_a.marker_count, 2);
    if (!corrected && !result_b.vo_orb.valid) {
      std::printf("%-12s | %8d | %+9.1f%% | ORB lost\n", "uncorrected", result_a.marker_count, 100.0 * range_error);
      EXPECT_LT(range_error, -0.15);
      continue;
    }
    ASSERT_TRUE(result_b.vo_orb.valid) << (corrected ? "PinAx" : "uncorrected");
    const Eigen::Isometry3d T_a_b = T_cam_rect.inverse() * T_panel_a.inverse() * T_panel_b * T_cam_rect;
    const double t_ratio = result_b.vo_orb.p_camb_in_cama_m.norm() / T_a_b.translation().norm();
    const double direction_deg =
        std::acos(std::clamp(result_b.vo_orb.p_camb_in_cama_m.normalized().dot(T_a_b.translation().normalized()),
                             -1.0, 1.0)) * 180.0 / M_PI;
    const double rot_err_deg =
        Eigen::AngleAxisd(result_b.vo_orb.q_cama_camb.inverse() * Eigen::Quaterniond(T_a_b.linear())).angle() *
        180.0 / M_PI;
    std::printf("%-12s | %8d | %+9.1f%% | %9.3fx | %7.2f deg  (translation direction %.1f deg off)\n",
                corrected ? "PinAx" : "uncorrected", result_a.marker_count, 100.0 * range_error, t_ratio, rot_err_deg,
                direction_deg);
    if (corrected) {
      EXPECT_LT(std::abs(range_error), 0.01);
      EXPECT_NEAR(t_ratio, 1.0, 0.05);
      EXPECT_LT(direction_deg, 5.0);
      EXPECT_LT(rot_err_deg, 0.5);
    } else {
      EXPECT_LT(range_error, -0.15);  // ~n_water times nearer
      EXPECT_LT(t_ratio, 0.9);
    }
  }
}

}  // namespace
}  // namespace deepnav
