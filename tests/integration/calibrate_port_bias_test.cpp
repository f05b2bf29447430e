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
#include "vision/stereo/elas_disparity.h"

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
    ASSERT_TRUE(sim::loadScenario(std::string(DEEPNAV_SOURCE_DIR) + "/tools/sim/scenarios/default.yaml", &scenario_,
                                  &error))
        << error;
    camera_ = scenario_.camera;
    ASSERT_TRUE(resampler_.init(camera_, testPort(), &error)) << error;
    sim::Scenario pinhole_scenario = scenario_;
    pinhole_scenario.camera = resampler_.pinhole();
    ASSERT_TRUE(plain_renderer_.init(scenario_, 1, 1, &error)) << error;
    ASSERT_TRUE(port_renderer_.init(pinhole_scenario, 1, 1, &error)) << error;
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

  // Renders the views the left camera has `distance_m` in front of the grasping face.
  void renderViews(double distance_m, StereoFrame* plain, sim::RenderTruth* plain_truth, StereoFrame* port,
                   cv::Mat* port_depth_m) {
    const CameraTick tick = sim::tickFacingFace(scenario_, 1, distance_m, 0.1, 1.0, 0.0, 5.0);
    allocateStereoFrame(*plain, camera_.width_px, camera_.height_px, 1);
    plain_renderer_.allocateTruth(plain_truth);
    ASSERT_TRUE(plain_renderer_.render(tick, plain, plain_truth));
    StereoFrame pinhole;
    allocateStereoFrame(pinhole, camera_.width_px, camera_.height_px, 1);
    sim::RenderTruth truth;
    port_renderer_.allocateTruth(&truth);
    ASSERT_TRUE(port_renderer_.render(tick, &pinhole, &truth));
    allocateStereoFrame(*port, camera_.width_px, camera_.height_px, 1);
    port_depth_m->create(camera_.height_px, camera_.width_px, CV_32F);
    cv::Mat right_depth(camera_.height_px, camera_.width_px, CV_32F);
    ASSERT_TRUE(resampler_.resample(pinhole.left, truth.depth_m, port->left, *port_depth_m));
    ASSERT_TRUE(resampler_.resample(pinhole.right, truth.right_depth_m, port->right, right_depth));
  }

  // Depth of every pixel with a disparity, against the truth, for a pinhole pair of focal f and baseline b.
  void pinholeErrors(const cv::Mat& left, const cv::Mat& right, const cv::Mat& truth_m, DepthErrors* e) {
    cv::Mat disparity;
    ASSERT_TRUE(elas_.compute(left, right, &disparity));
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

  sim::Scenario scenario_;
  sim::CameraConfig camera_;
  sim::FlatPortResampler resampler_;
  sim::StereoRenderer plain_renderer_;
  sim::StereoRenderer port_renderer_;
  ElasDisparity elas_;
  StereoRectification pinax_;
  StereoRectifier rectifier_;
};

TEST_F(CalibratePortBias, PinaxRemovesTheFlatPortDepthBias) {
  std::printf("flat port d1 = 12 mm acrylic, d0 = 8 mm; ELAS on 688x516 rendered pairs (default scenario water)\n");
  std::printf("%10s | %22s | %22s | %22s\n", "distance", "no port", "port, uncorrected", "port, PinAx");
  for (double distance_m : {1.5, 2.0, 2.5}) {
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

}  // namespace
}  // namespace deepnav
