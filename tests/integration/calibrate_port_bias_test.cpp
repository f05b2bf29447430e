// Depth bias of the dense stereo on rendered frames through a flat port, with and without the PinAx
// rectification, against the pinhole rig (no port) on the same views. Prints the figures quoted in
// vision/calib/README.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "tools/sim/render/flat_port.h"
#include "tools/sim/render/stereo_renderer.h"
#include "tools/sim/render/view_tick.h"
#include "tools/sim/scenario_loader.h"
#include "vision/calib/stereo_rectification.h"
#include "vision/markers/marker_detector.h"
#include "vision/stereo/elas_disparity.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

struct DepthErrors {
  std::vector<double> signed_m;
  std::vector<double> relative;
  void add(double estimate_m, double truth_m) {
    signed_m.push_back(estimate_m - truth_m);
    relative.push_back((estimate_m - truth_m) / truth_m);
  }
  static double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  }
  double medianBias_m() const { return median(signed_m); }
  double medianRelative() const { return median(relative); }
  double medianAbsRelative() const {
    std::vector<double> a(relative.size());
    std::transform(relative.begin(), relative.end(), a.begin(), [](double x) { return std::abs(x); });
    return median(a);
  }
};

FlatPort testPort() {
  FlatPort port;
  port.glass_thickness_m = 0.012;  // acrylic, the pinhole 8 mm behind it
  port.pinhole_to_glass_m = 0.008;
  return port;
}

class CalibratePortBias : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string error;
    ASSERT_TRUE(sim::loadScenario(deepnav::testing::sourceDir() + "/tools/sim/scenarios/default.yaml", &scenario_,
                                  &error))
        << error;
    camera_ = scenario_.camera;
    // The same scenario with camera.port: {model: flat, ...}: the renderer draws raw port images.
    sim::Scenario port_scenario = scenario_;
    port_scenario.camera.flat_port = true;
    port_scenario.camera.port = testPort();
    ASSERT_TRUE(plain_renderer_.init(scenario_, 1, 1, &error)) << error;
    ASSERT_TRUE(port_renderer_.init(port_scenario, 1, 1, &error)) << error;
    ElasParams params = ElasParams::dense();
    params.num_disparities = 256;
    ASSERT_TRUE(elas_.init(params, camera_.width_px, camera_.height_px));
    // The raw port cameras as an in-air calibration would give them: the scenario's pinhole pair.
    StereoCalibration calib;
    calib.image_size = cv::Size(camera_.width_px, camera_.height_px);
    calib.left.K = cv::Matx33d(camera_.fx_px, 0, camera_.cx_px, 0, camera_.fy_px, camera_.cy_px, 0, 0, 1);
    calib.right.K = calib.left.K;
    calib.T = cv::Vec3d(-camera_.baseline_m, 0.0, 0.0);
    RectificationOptions options;
    options.correction = PortCorrection::kPinax;
    options.pinax.port = testPort();
    options.pinax.reference_distance_m = 2.0;
    ASSERT_TRUE(computeStereoRectification(calib, options, &pinax_, &error)) << error;
    ASSERT_TRUE(rectifier_.init(pinax_, &error)) << error;
  }

  // Renders the views of a tick (default: the left camera `distance_m` in front of the grasping face).
  void renderViews(double distance_m, StereoFrame* plain, sim::RenderTruth* plain_truth, StereoFrame* port,
                   cv::Mat* port_depth_m) {
    renderTick(sim::tickFacingFace(scenario_, 1, distance_m, 0.1, 1.0, 0.0, 5.0), plain, plain_truth, port,
               port_depth_m);
  }
  void renderTick(const CameraTick& tick, StereoFrame* plain, sim::RenderTruth* plain_truth, StereoFrame* port,
                  cv::Mat* port_depth_m) {
    allocateStereoFrame(*plain, camera_.width_px, camera_.height_px, 1);
    plain_renderer_.allocateTruth(plain_truth);
    ASSERT_TRUE(plain_renderer_.render(tick, plain, plain_truth));
    sim::RenderTruth truth;
    port_renderer_.allocateTruth(&truth);
    allocateStereoFrame(*port, camera_.width_px, camera_.height_px, 1);
    ASSERT_TRUE(port_renderer_.render(tick, port, &truth));
    EXPECT_FALSE(port->rectified);
    *port_depth_m = truth.depth_m;
  }

  // Depth of every pixel with a disparity, against the truth, for a pinhole pair of focal f and baseline b.
  void pinholeErrors(const cv::Mat& left, const cv::Mat& right, const cv::Mat& truth_m, DepthErrors* e) {
    cv::Mat disparity;
    ASSERT_TRUE(elas_.compute(left, right, &disparity));
    // At 2.5 m and beyond the moderate water leaves ELAS too few support points to be a fair measure.
    EXPECT_GT(elas_.supportPointCount(), 50);
    const double fb = camera_.fx_px * camera_.baseline_m;
    for (int v = 0; v < disparity.rows; ++v)
      for (int u = 0; u < disparity.cols; ++u) {
        const float d = disparity.at<float>(v, u), z = truth_m.at<float>(v, u);
        if (d > 0.0f && z > 0.0f) e->add(fb / d, z);
      }
  }

  // The same through the PinAx rectification: depth in the virtual camera, back to the real one, against
  // the truth of the raw pixel the rectified pixel came from.
  void pinaxErrors(const StereoFrame& port, const cv::Mat& truth_m, DepthErrors* e) {
    cv::Mat left(port.left.size(), port.left.type()), right(port.right.size(), port.right.type());
    ASSERT_TRUE(rectifier_.rectify(port.left, port.right, left, right));
    cv::Mat disparity;
    ASSERT_TRUE(elas_.compute(left, right, &disparity));
    EXPECT_GT(elas_.supportPointCount(), 50);
    const PinholeIntrinsics& k = pinax_.rectified;
    const cv::Matx33d R_cam_rect = pinax_.R_rect_left.t();
    for (int v = 0; v < disparity.rows; ++v)
      for (int u = 0; u < disparity.cols; ++u) {
        const float d = disparity.at<float>(v, u);
        if (d <= 0.0f) continue;
        const cv::Vec2f raw = pinax_.left_raw_px.at<cv::Vec2f>(v, u);
        const int ru = static_cast<int>(std::lround(raw[0])), rv = static_cast<int>(std::lround(raw[1]));
        if (ru < 0 || rv < 0 || ru >= truth_m.cols || rv >= truth_m.rows) continue;
        const float z_true = truth_m.at<float>(rv, ru);
        if (z_true <= 0.0f) continue;
        const double z_virtual = k.fx_px * pinax_.baseline_m / d;
        const cv::Vec3d p_rect((u - k.cx_px) / k.fx_px * z_virtual, (v - k.cy_px) / k.fy_px * z_virtual, z_virtual);
        e->add((R_cam_rect * p_rect)[2] + pinax_.virtual_centre_z_m, z_true);
      }
  }

  // Marker positions (camera frame) found in an image by a detector with the given intrinsics, mapped by
  // to_camera into the real left camera frame; compared with the truth of the tick.
  template <typename ToCamera>
  void markerErrors(const cv::Mat& image, const PinholeIntrinsics& k, const CameraTick& tick, ToCamera to_camera,
                    std::vector<double>* range_errors_m, std::vector<double>* position_errors_m) {
    MarkerDetectorConfig config;
    config.camera = k;
    config.marker_size_m = plain_renderer_.panel().marker_size_m;
    MarkerDetector detector;
    std::string error;
    ASSERT_TRUE(detector.init(config, &error)) << error;
    MarkerObservations found;
    ASSERT_TRUE(detector.detect(image, &found));
    const sim::ViewPose view = plain_renderer_.leftView(tick);
    for (int i = 0; i < found.count; ++i) {
      const PanelMarker* m = plain_renderer_.panel().marker(found.items[i].id);
      ASSERT_NE(m, nullptr);
      const Eigen::Vector3d truth = view.R_panel_cam.cast<double>().transpose() *
                                    (m->p_marker_in_panel_m - view.p_cam_in_panel_m.cast<double>());
      const Eigen::Vector3d estimate = to_camera(found.items[i].p_marker_in_cam_m);
      range_errors_m->push_back(estimate.norm() - truth.norm());
      position_errors_m->push_back((estimate - truth).norm());
    }
  }

  sim::Scenario scenario_;
  sim::CameraConfig camera_;
  sim::StereoRenderer plain_renderer_;
  sim::StereoRenderer port_renderer_;
  ElasDisparity elas_;
  StereoRectification pinax_;
  StereoRectifier rectifier_;
};

TEST_F(CalibratePortBias, PinaxRemovesTheFlatPortDepthBias) {
  std::printf("flat port d1 = 12 mm acrylic, d0 = 8 mm; ELAS on 688x516 rendered pairs (default scenario water)\n");
  std::printf("%10s | %22s | %22s | %22s\n", "distance", "no port", "port, uncorrected", "port, PinAx");
  for (double distance_m : {1.2, 1.6, 2.0}) {
    StereoFrame plain, port;
    sim::RenderTruth plain_truth;
    cv::Mat port_depth;
    renderViews(distance_m, &plain, &plain_truth, &port, &port_depth);
    DepthErrors reference, uncorrected, corrected;
    pinholeErrors(plain.left, plain.right, plain_truth.depth_m, &reference);
    pinholeErrors(port.left, port.right, port_depth, &uncorrected);
    pinaxErrors(port, port_depth, &corrected);
    std::printf("%8.1f m | %+6.3f m %+6.2f %% (%4.2f) | %+6.3f m %+6.2f %% (%4.2f) | %+6.3f m %+6.2f %% (%4.2f)\n",
                distance_m, reference.medianBias_m(), 100 * reference.medianRelative(),
                100 * reference.medianAbsRelative(), uncorrected.medianBias_m(), 100 * uncorrected.medianRelative(),
                100 * uncorrected.medianAbsRelative(), corrected.medianBias_m(), 100 * corrected.medianRelative(),
                100 * corrected.medianAbsRelative());
    ASSERT_GT(reference.signed_m.size(), 10000u);
    ASSERT_GT(corrected.signed_m.size(), 10000u);
    // Uncorrected, the port's magnification (about n_water) makes everything look n_water times nearer...
    EXPECT_LT(uncorrected.medianRelative(), -0.2);
    // ... PinAx brings the bias down to the level of the stereo matcher itself.
    EXPECT_LT(std::abs(corrected.medianRelative()), 0.01);
    EXPECT_LT(std::abs(corrected.medianRelative() - reference.medianRelative()), 0.01);
  }
  std::printf("(median signed error, median relative error, and in brackets the median |relative error| in %%)\n");
}

TEST_F(CalibratePortBias, PinaxRemovesTheFlatPortMarkerRangeBias) {
  std::printf("marker positions (valves face, 4 markers per view), mean range error / mean position error\n");
  std::printf("%10s | %20s | %20s | %20s\n", "distance", "no port", "port, uncorrected", "port, PinAx");
  const PinholeIntrinsics raw{camera_.fx_px, camera_.fy_px, camera_.cx_px, camera_.cy_px};
  for (double distance_m : {1.8, 2.2, 2.6}) {
    const CameraTick tick = sim::tickFacingFace(scenario_, 0, distance_m, 0.0, 1.25);
    StereoFrame plain, port;
    sim::RenderTruth plain_truth;
    cv::Mat port_depth;
    renderTick(tick, &plain, &plain_truth, &port, &port_depth);
    cv::Mat left(port.left.size(), port.left.type()), right(port.right.size(), port.right.type());
    ASSERT_TRUE(rectifier_.rectify(port.left, port.right, left, right));
    std::vector<double> range[3], position[3];
    const auto same = [](const Eigen::Vector3d& p) { return p; };
    markerErrors(plain.left, raw, tick, same, &range[0], &position[0]);
    markerErrors(port.left, raw, tick, same, &range[1], &position[1]);
    const cv::Matx33d R_cam_rect = pinax_.R_rect_left.t();
    const double z_v = pinax_.virtual_centre_z_m;
    markerErrors(left, pinax_.rectified, tick, [&](const Eigen::Vector3d& p) {
      const cv::Vec3d c = R_cam_rect * cv::Vec3d(p.x(), p.y(), p.z());
      return Eigen::Vector3d(c[0], c[1], c[2] + z_v);
    }, &range[2], &position[2]);
    auto mean = [](const std::vector<double>& v) {
      double s = 0.0;
      for (double x : v) s += x;
      return v.empty() ? NAN : s / static_cast<double>(v.size());
    };
    std::printf("%8.1f m | %+7.3f m / %5.3f m | %+7.3f m / %5.3f m | %+7.3f m / %5.3f m\n", distance_m, mean(range[0]),
                mean(position[0]), mean(range[1]), mean(position[1]), mean(range[2]), mean(position[2]));
    for (int k = 0; k < 3; ++k) ASSERT_GE(range[k].size(), 2u) << "variant " << k;
    EXPECT_LT(mean(range[1]), -0.15 * distance_m);        // uncorrected: markers look ~n_water times nearer
    EXPECT_LT(std::abs(mean(range[2])), 0.01 * distance_m);  // PinAx: within 1 % of the range
    EXPECT_LT(mean(position[2]), std::max(0.015 * distance_m, mean(position[0]) + 0.01));  // as without a port
  }
}

}  // namespace
}  // namespace deepnav
