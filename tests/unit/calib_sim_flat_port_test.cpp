#include "tools/sim/render/flat_port.h"
#include "tools/sim/render/stereo_renderer.h"
#include "tools/sim/render/view_tick.h"
#include "tools/sim/scenario_loader.h"

#include <cmath>

#include <gtest/gtest.h>

namespace deepnav {
namespace {

// A textured plane z = z0 + slope * x (camera frame), rendered analytically by a pinhole camera.
struct Plane {
  double z0_m = 1.5;
  double slope = 0.0;
  double albedo(double x, double y) const { return 0.5 + 0.25 * std::sin(40.0 * x) + 0.25 * std::cos(30.0 * y); }
  // Where the ray o + t d meets the plane.
  Eigen::Vector3d hit(const Eigen::Vector3d& o, const Eigen::Vector3d& d) const {
    const double t = (z0_m + slope * o.x() - o.z()) / (d.z() - slope * d.x());
    return o + t * d;
  }
};

void renderPinhole(const sim::CameraConfig& cam, const Plane& plane, cv::Mat* image, cv::Mat* depth) {
  image->create(cam.height_px, cam.width_px, CV_32F);
  depth->create(cam.height_px, cam.width_px, CV_32F);
  for (int v = 0; v < cam.height_px; ++v) {
    for (int u = 0; u < cam.width_px; ++u) {
      const Eigen::Vector3d d((u - cam.cx_px) / cam.fx_px, (v - cam.cy_px) / cam.fy_px, 1.0);
      const Eigen::Vector3d p = plane.hit(Eigen::Vector3d::Zero(), d);
      image->at<float>(v, u) = static_cast<float>(plane.albedo(p.x(), p.y()));
      depth->at<float>(v, u) = static_cast<float>(p.z());
    }
  }
}

class CalibSimFlatPort : public ::testing::TestWithParam<double> {};

TEST_P(CalibSimFlatPort, PortImageShowsWhatTheRefractedRaySees) {
  // GIVEN a 688 x 516 camera behind a 12 mm acrylic port, 8 mm from the glass, facing a textured plane
  sim::CameraConfig cam;
  FlatPort port;
  port.glass_thickness_m = 0.012;
  port.pinhole_to_glass_m = 0.008;
  Plane plane;
  plane.slope = GetParam();
  sim::FlatPortResampler resampler;
  std::string error;
  ASSERT_TRUE(resampler.init(cam, port, &error)) << error;
  cv::Mat pinhole_image, pinhole_depth;
  renderPinhole(resampler.pinhole(), plane, &pinhole_image, &pinhole_depth);
  // WHEN the port image is resampled from the pinhole render
  cv::Mat port_image(cam.height_px, cam.width_px, CV_32F), port_depth(cam.height_px, cam.width_px, CV_32F);
  ASSERT_TRUE(resampler.resample(pinhole_image, pinhole_depth, port_image, port_depth));
  // THEN each port pixel holds the albedo and depth of the point its Snell-traced ray meets
  double worst_albedo = 0.0, worst_depth = 0.0;
  for (int v = 0; v < cam.height_px; v += 7) {
    for (int u = 0; u < cam.width_px; u += 7) {
      PortRay ray;
      ASSERT_TRUE(traceThroughPort(port, {(u - cam.cx_px) / cam.fx_px, (v - cam.cy_px) / cam.fy_px, 1.0}, &ray));
      const Eigen::Vector3d p = plane.hit(ray.origin_m, ray.dir);
      worst_albedo = std::max(worst_albedo, std::abs(port_image.at<float>(v, u) - plane.albedo(p.x(), p.y())));
      worst_depth = std::max(worst_depth, std::abs(port_depth.at<float>(v, u) - p.z()));
    }
  }
  EXPECT_LT(worst_albedo, 2e-3);   // bilinear sampling of the texture (0.5 +- 0.5)
  EXPECT_LT(worst_depth, 5e-4);    // nearest depth sample on a sloped plane
  // The port magnifies: the image centre sees a narrower patch than a pinhole of the same focal length.
  EXPECT_NEAR(resampler.pinhole().fx_px, cam.fx_px * 1.34, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(FlatAndSloped, CalibSimFlatPort, ::testing::Values(0.0, 0.4));

TEST(CalibSimFlatPortApi, SizeMismatchIsRefused) {
  sim::CameraConfig cam;
  sim::FlatPortResampler resampler;
  std::string error;
  FlatPort port;
  port.glass_thickness_m = 0.01;
  ASSERT_TRUE(resampler.init(cam, port, &error)) << error;
  cv::Mat image(cam.height_px, cam.width_px, CV_8UC1), depth(cam.height_px, cam.width_px, CV_32F);
  cv::Mat out(10, 10, CV_8UC1), out_depth(cam.height_px, cam.width_px, CV_32F);
  EXPECT_FALSE(resampler.resample(image, depth, out, out_depth));
  port.n_glass = 0.2;
  EXPECT_FALSE(resampler.init(cam, port, &error));
  EXPECT_NE(error.find("n_glass"), std::string::npos) << error;
}

TEST(CalibSimFlatPortScenario, CameraPortKeysRenderRawPortImages) {
  // GIVEN a scenario with camera.port: {model: flat, ...}
  sim::Scenario scenario;
  std::string error;
  ASSERT_TRUE(sim::parseScenario("camera:\n  port:\n    model: flat\n    pinhole_to_glass_m: 0.008\n"
                                 "    glass_thickness_m: 0.012\n    n_glass: 1.52\n",
                                 "port.yaml", &scenario, &error))
      << error;
  EXPECT_TRUE(scenario.camera.flat_port);
  EXPECT_EQ(scenario.camera.port.glass_thickness_m, 0.012);
  EXPECT_EQ(scenario.camera.port.n_glass, 1.52);
  EXPECT_EQ(scenario.camera.port.n_water, FlatPort{}.n_water);
  // WHEN a pair is rendered facing the grasping face from 1.5 m
  sim::StereoRenderer renderer;
  ASSERT_TRUE(renderer.init(scenario, 1, 1, &error)) << error;
  StereoFrame frame;
  allocateStereoFrame(frame, scenario.camera.width_px, scenario.camera.height_px, 1);
  sim::RenderTruth truth;
  renderer.allocateTruth(&truth);
  ASSERT_TRUE(renderer.render(sim::tickFacingFace(scenario, 1, 1.5, 0.0, 1.0), &frame, &truth));
  // THEN the images are raw (not rectified), the depth at the centre is the face's, and the disparity
  // truth is unknown (0) throughout
  EXPECT_FALSE(frame.rectified);
  EXPECT_NEAR(truth.depth_m.at<float>(258, 344), 1.5f, 0.05f);
  EXPECT_EQ(cv::countNonZero(truth.disparity_px), 0);
  // A bad port key is named.
  EXPECT_FALSE(sim::parseScenario("camera:\n  port:\n    model: dome\n", "bad.yaml", &scenario, &error));
  EXPECT_NE(error.find("camera.port.model"), std::string::npos) << error;
  EXPECT_FALSE(sim::parseScenario("camera:\n  port:\n    glass_thikness_m: 0.01\n", "bad.yaml", &scenario, &error));
  EXPECT_NE(error.find("glass_thikness_m"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav
