#include "vision/calib/pinax_model.h"

#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "vision/calib/stereo_rectification.h"

namespace deepnav {
namespace {

// A 688 x 516 rig like the simulated one, calibrated in air: mild barrel distortion, a 0.3 m
// baseline with a slight toe-in, both cameras behind the same acrylic port.
StereoCalibration airCalibration() {
  StereoCalibration c;
  c.image_size = cv::Size(688, 516);
  c.left.K = cv::Matx33d(520.0, 0.0, 340.2, 0.0, 521.0, 261.7, 0.0, 0.0, 1.0);
  c.left.dist = (cv::Mat_<double>(1, 5) << -0.08, 0.02, 0.0004, -0.0003, 0.0);
  c.right.K = cv::Matx33d(523.0, 0.0, 347.9, 0.0, 523.5, 255.1, 0.0, 0.0, 1.0);
  c.right.dist = (cv::Mat_<double>(1, 5) << -0.075, 0.018, -0.0002, 0.0001, 0.0);
  cv::Mat R;
  cv::Rodrigues(cv::Vec3d(0.004, -0.02, 0.003), R);
  c.R = cv::Matx33d(R);
  c.T = cv::Vec3d(-0.30, 0.002, 0.001);
  return c;
}

RectificationOptions pinaxOptions(double d0_m) {
  RectificationOptions o;
  o.correction = PortCorrection::kPinax;
  o.pinax.port.glass_thickness_m = 0.012;
  o.pinax.port.pinhole_to_glass_m = d0_m;
  o.pinax.reference_distance_m = 2.0;
  return o;
}

// Bilinear look-up of a CV_32FC2 map at a sub-pixel position.
cv::Point2d sampleMap(const cv::Mat& map, cv::Point2d p) {
  const int u0 = static_cast<int>(std::floor(p.x));
  const int v0 = static_cast<int>(std::floor(p.y));
  const double a = p.x - u0;
  const double b = p.y - v0;
  auto at = [&](int u, int v) { return cv::Point2d(map.at<cv::Vec2f>(v, u)[0], map.at<cv::Vec2f>(v, u)[1]); };
  return (1 - a) * (1 - b) * at(u0, v0) + a * (1 - b) * at(u0 + 1, v0) + (1 - a) * b * at(u0, v0 + 1) +
         a * b * at(u0 + 1, v0 + 1);
}

struct MappingError {
  double max_px = 0.0;
  int points = 0;
};

// For points spread over the rectified view at the given distances: the exact refracted raw pixel of
// each point versus the PinAx map evaluated where the rectified (virtual) camera sees the point.
MappingError mappingError(const StereoCalibration& calib, const StereoRectification& rect, const FlatPort& port,
                          bool right, const std::vector<double>& distances_m) {
  MappingError e;
  const CameraCalibration& cam = right ? calib.right : calib.left;
  const cv::Matx33d& R_rect = right ? rect.R_rect_right : rect.R_rect_left;
  const cv::Mat& map = right ? rect.right_raw_px : rect.left_raw_px;
  const PinholeIntrinsics& k = rect.rectified;
  const double z_v = rect.virtual_centre_z_m;
  for (double z_m : distances_m) {
    for (int gv = 0; gv <= 10; ++gv) {
      for (int gu = 0; gu <= 10; ++gu) {
        // A ray of the rectified camera through a grid pixel (1 px inside the border), out to distance z.
        const double u = 1.0 + gu * (rect.image_size.width - 3.0) / 10.0;
        const double v = 1.0 + gv * (rect.image_size.height - 3.0) / 10.0;
        const cv::Vec3d d_cam = R_rect.t() * cv::Vec3d((u - k.cx_px) / k.fx_px, (v - k.cy_px) / k.fy_px, 1.0);
        const cv::Vec3d p_cam = d_cam * ((z_m - z_v) / d_cam[2]) + cv::Vec3d(0, 0, z_v);
        Eigen::Vector2d xy;
        if (!projectThroughPort(port, Eigen::Vector3d(p_cam[0], p_cam[1], p_cam[2]), &xy)) continue;
        std::vector<cv::Point2d> raw;
        cv::projectPoints(std::vector<cv::Point3d>{{xy.x(), xy.y(), 1.0}}, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0),
                          cam.K, cam.dist, raw);
        const cv::Point2d mapped = sampleMap(map, {u, v});
        if (mapped.x < 0 || mapped.y < 0 || mapped.x > rect.image_size.width - 1 ||
            mapped.y > rect.image_size.height - 1)
          continue;
        e.max_px = std::max(e.max_px, cv::norm(mapped - raw[0]));
        ++e.points;
      }
    }
  }
  return e;
}

TEST(CalibPinax, MappingWithinATenthOfAPixelOfExactRefractionAtOneToThreeMetres) {
  // GIVEN an in-air stereo calibration and a 12 mm acrylic port with the pinhole at the PinAx-optimal
  // distance from the glass
  const StereoCalibration calib = airCalibration();
  FlatPort port;
  port.glass_thickness_m = 0.012;
  const double d0 = optimalPinholeToGlassM(port);
  const RectificationOptions options = pinaxOptions(d0);
  // WHEN the rectification maps are built
  StereoRectification rect;
  std::string error;
  ASSERT_TRUE(computeStereoRectification(calib, options, &rect, &error)) << error;
  // THEN every rectified pixel maps within 0.1 px of where exact refraction puts the point it sees,
  // anywhere between 1 and 3 m
  const std::vector<double> distances = {1.0, 1.5, 2.0, 2.5, 3.0};
  for (bool right : {false, true}) {
    const MappingError e = mappingError(calib, rect, options.pinax.port, right, distances);
    EXPECT_GT(e.points, 500);
    EXPECT_LT(e.max_px, 0.1) << (right ? "right" : "left") << " camera, d0 = " << d0;
    std::printf("PinAx d0 = %.2f mm (optimal), %s: max mapping error %.4f px over 1-3 m (%d points)\n", d0 * 1e3,
                right ? "right" : "left", e.max_px, e.points);
  }
  // The water makes the rectified focal length larger (narrower view) than the in-air one.
  EXPECT_GT(rect.rectified.fx_px, 1.3 * 520.0);
  EXPECT_NEAR(rect.baseline_m, 0.30, 0.01);
}

TEST(CalibPinax, MappingIsExactAtTheReferenceDistanceForAnyHousing) {
  const StereoCalibration calib = airCalibration();
  const RectificationOptions options = pinaxOptions(0.03);  // pinhole 3 cm behind the glass: far from optimal
  StereoRectification rect;
  std::string error;
  ASSERT_TRUE(computeStereoRectification(calib, options, &rect, &error)) << error;
  const MappingError at_ref = mappingError(calib, rect, options.pinax.port, false, {2.0});
  EXPECT_LT(at_ref.max_px, 0.01);
  const MappingError range = mappingError(calib, rect, options.pinax.port, false, {1.0, 3.0});
  std::printf("PinAx d0 = 30 mm: max mapping error %.3f px at 2 m, %.3f px over 1-3 m\n", at_ref.max_px,
              range.max_px);
  EXPECT_GT(range.max_px, 0.1);  // the test above would catch a non-optimal housing
  for (double d0_mm : {5.0, 10.0, 20.0}) {
    StereoRectification r;
    ASSERT_TRUE(computeStereoRectification(calib, pinaxOptions(d0_mm * 1e-3), &r, &error)) << error;
    const MappingError e = mappingError(calib, r, pinaxOptions(d0_mm * 1e-3).pinax.port, false, {1.0, 1.5, 2.5, 3.0});
    std::printf("PinAx d0 = %.0f mm: max mapping error %.3f px over 1-3 m\n", d0_mm, e.max_px);
  }
}

TEST(CalibPinax, VirtualCentreAndFocalScaleFollowThePhysics) {
  FlatPort port;
  port.glass_thickness_m = 0.012;
  port.pinhole_to_glass_m = optimalPinholeToGlassM(port);
  // Paraxially the water ray crosses the axis at z = d0 (1 - n_w) + d1 (1 - n_w / n_g): the air gap
  // moves the virtual pinhole back, the glass moves it forward. Over a 34 deg field (0.6 rad) the
  // fourth-order terms move the mid-range crossing by some 20 um.
  const double expected = port.pinhole_to_glass_m * (1 - 1.34) + 0.012 * (1 - 1.34 / 1.49);
  EXPECT_NEAR(paraxialAxisCrossingZ(port), expected, 1e-15);
  EXPECT_NEAR(pinaxVirtualCentreZ(port, 0.6), expected, 5e-5);
  PinaxConfig config;
  config.port = port;
  // Focal scale slightly above n_w / n_a (flat ports magnify, more so towards the corners).
  const double scale = pinaxFocalScale(config, pinaxVirtualCentreZ(port, 0.6), 0.6);
  EXPECT_GT(scale, 1.34);
  EXPECT_LT(scale, 1.5);
}

TEST(CalibPinax, PlainRectificationMatchesOpenCv) {
  const StereoCalibration calib = airCalibration();
  StereoRectification rect;
  std::string error;
  ASSERT_TRUE(computeStereoRectification(calib, RectificationOptions{}, &rect, &error)) << error;
  EXPECT_EQ(rect.virtual_centre_z_m, 0.0);
  EXPECT_NEAR(rect.baseline_m, cv::norm(calib.T), 1e-9);
  // A point projects to the same rectified row in both cameras.
  const cv::Vec3d p_left(0.2, -0.1, 1.7);
  const cv::Vec3d p_right = calib.R * p_left + calib.T;
  const cv::Vec3d l = rect.R_rect_left * p_left;
  const cv::Vec3d r = rect.R_rect_right * p_right;
  EXPECT_NEAR(l[1] / l[2], r[1] / r[2], 1e-12);
  EXPECT_NEAR(rect.rectified.fx_px * (l[0] / l[2] - r[0] / r[2]), rect.rectified.fx_px * rect.baseline_m / l[2], 1e-9);
}

TEST(CalibPinax, BadPortOrCalibrationIsRefusedWithAReason) {
  StereoCalibration calib = airCalibration();
  RectificationOptions options = pinaxOptions(0.005);
  options.pinax.port.n_glass = 0.5;
  StereoRectification rect;
  std::string error;
  EXPECT_FALSE(computeStereoRectification(calib, options, &rect, &error));
  EXPECT_NE(error.find("n_glass"), std::string::npos) << error;
  calib.left.K(0, 0) = -1.0;
  EXPECT_FALSE(computeStereoRectification(calib, RectificationOptions{}, &rect, &error));
  EXPECT_NE(error.find("left camera matrix"), std::string::npos) << error;
}

TEST(CalibPinax, RectifierRemapsIntoPreallocatedImages) {
  const StereoCalibration calib = airCalibration();
  StereoRectification rect;
  std::string error;
  ASSERT_TRUE(computeStereoRectification(calib, pinaxOptions(0.005), &rect, &error)) << error;
  StereoRectifier rectifier;
  ASSERT_TRUE(rectifier.init(rect, &error)) << error;
  cv::Mat raw_l(calib.image_size, CV_8UC1), raw_r(calib.image_size, CV_8UC1);
  cv::randu(raw_l, 0, 255);
  cv::randu(raw_r, 0, 255);
  cv::Mat out_l(calib.image_size, CV_8UC1), out_r(calib.image_size, CV_8UC1);
  const uchar* before = out_l.data;
  ASSERT_TRUE(rectifier.rectify(raw_l, raw_r, out_l, out_r));
  EXPECT_EQ(out_l.data, before);  // written in place, not reallocated
  // The rectified centre pixel shows the raw pixel the map names.
  const cv::Vec2f src = rect.left_raw_px.at<cv::Vec2f>(258, 344);
  cv::Mat expected;
  cv::getRectSubPix(raw_l, {1, 1}, cv::Point2f(src[0], src[1]), expected);
  EXPECT_NEAR(out_l.at<uchar>(258, 344), expected.at<uchar>(0, 0), 2);
  cv::Mat wrong(100, 100, CV_8UC1);
  EXPECT_FALSE(rectifier.rectify(raw_l, raw_r, wrong, out_r));
}

}  // namespace
}  // namespace deepnav
