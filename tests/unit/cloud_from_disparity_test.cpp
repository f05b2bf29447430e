#include "vision/cloud/cloud_from_disparity.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/synthetic_scene.h"
#include "vision/cloud/mixed_pixel_filter.h"
#include "vision/stereo/disparity_estimator.h"

namespace deepnav {
namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

StereoGeometry geometry() {
  StereoGeometry g;
  g.fx_px = 400.0;
  g.fy_px = 410.0;
  g.cx_px = 79.5;
  g.cy_px = 59.5;
  g.baseline_m = 0.1;
  return g;
}

// Disparity of the plane n . p = d (camera frame) at pixel (u, v): with the ray r = (x', y', 1),
// Z = d / (n . r) and disparity f B / Z.
cv::Mat planeDisparity(const Eigen::Vector3d& n, double d, const StereoGeometry& g) {
  cv::Mat disparity(kHeight, kWidth, CV_32FC1);
  for (int v = 0; v < kHeight; ++v) {
    for (int u = 0; u < kWidth; ++u) {
      const Eigen::Vector3d ray((u - g.cx_px) / g.fx_px, (v - g.cy_px) / g.fy_px, 1.0);
      disparity.at<float>(v, u) = static_cast<float>(g.focalBaseline() * n.dot(ray) / d);
    }
  }
  return disparity;
}

TEST(CloudFromDisparity, PointsOfAPlaneDisparityLieOnThePlane) {
  // GIVEN the exact disparity of a slanted plane 1.5 m away
  const StereoGeometry g = geometry();
  const Eigen::Vector3d n = Eigen::Vector3d(0.2, -0.3, 1.0).normalized();
  const double d = 1.5;
  const cv::Mat disparity = planeDisparity(n, d, g);
  CloudFromDisparity builder;
  ASSERT_TRUE(builder.init(g, CloudConfig{}, kWidth, kHeight));
  OrganizedCloud cloud;
  ASSERT_TRUE(builder.allocateCloud(&cloud));
  // WHEN converted
  ASSERT_TRUE(builder.compute(disparity, &cloud));
  // THEN every point is valid, on the plane and on its pixel's ray
  EXPECT_EQ(cloud.countValid(), kWidth * kHeight);
  for (int v = 0; v < kHeight; v += 7) {
    for (int u = 0; u < kWidth; u += 5) {
      const cv::Vec3f& p = cloud.row(v)[u];
      EXPECT_NEAR(n.dot(Eigen::Vector3d(p[0], p[1], p[2])), d, 1e-5);
      EXPECT_NEAR(g.fx_px * p[0] / p[2] + g.cx_px, u, 1e-3);
      EXPECT_NEAR(g.fy_px * p[1] / p[2] + g.cy_px, v, 1e-3);
    }
  }
}

TEST(CloudFromDisparity, InvalidDisparitiesAndRangeLimitsGiveNoPoint) {
  // GIVEN disparities: invalid, zero, too close (Z < min), too far (Z > max), fine
  const StereoGeometry g = geometry();  // f B = 40 px m
  CloudConfig config;
  config.min_range_m = 0.5;
  config.max_range_m = 4.0;
  CloudFromDisparity builder;
  ASSERT_TRUE(builder.init(g, config, kWidth, kHeight));
  cv::Mat disparity(kHeight, kWidth, CV_32FC1, cv::Scalar(20.0f));  // Z = 2 m
  disparity.at<float>(0, 0) = kInvalidDisparity;
  disparity.at<float>(0, 1) = 0.0f;
  disparity.at<float>(0, 2) = 100.0f;  // Z = 0.4 m
  disparity.at<float>(0, 3) = 8.0f;    // Z = 5 m
  OrganizedCloud cloud;
  ASSERT_TRUE(builder.allocateCloud(&cloud));
  // WHEN converted
  ASSERT_TRUE(builder.compute(disparity, &cloud));
  // THEN exactly those four have no point
  EXPECT_EQ(cloud.countValid(), kWidth * kHeight - 4);
  for (int u = 0; u < 4; ++u) EXPECT_FALSE(OrganizedCloud::isValid(cloud.row(0)[u]));
  EXPECT_FLOAT_EQ(cloud.row(0)[4][2], 2.0f);
}

TEST(CloudFromDisparity, StepSubsamplesThePixelGrid) {
  const StereoGeometry g = geometry();
  CloudConfig config;
  config.step_px = 2;
  CloudFromDisparity builder;
  ASSERT_TRUE(builder.init(g, config, kWidth, kHeight));
  EXPECT_EQ(builder.gridCols(), kWidth / 2);
  EXPECT_EQ(builder.gridRows(), kHeight / 2);
  OrganizedCloud cloud;
  ASSERT_TRUE(builder.allocateCloud(&cloud));
  const cv::Mat disparity(kHeight, kWidth, CV_32FC1, cv::Scalar(10.0f));
  ASSERT_TRUE(builder.compute(disparity, &cloud));
  // cell (3, 5) is pixel (10, 6)
  const cv::Vec3f& p = cloud.row(3)[5];
  EXPECT_NEAR(g.fx_px * p[0] / p[2] + g.cx_px, 10.0, 1e-3);
  EXPECT_NEAR(g.fy_px * p[1] / p[2] + g.cy_px, 6.0, 1e-3);
  // a mismatched disparity size is refused
  EXPECT_FALSE(builder.compute(cv::Mat(kHeight, kWidth + 1, CV_32FC1), &cloud));
}

TEST(MixedPixelFilter, RemovesStreakBetweenForegroundAndBackgroundKeepsSurfaces) {
  // GIVEN a wall at 3 m, a box face at 1.5 m in the middle columns, and 6-pixel streaks of
  // interpolated disparity on both sides of the box (mixed pixels)
  const StereoGeometry g = geometry();  // f B = 40
  const float d_box = 40.0f / 1.5f, d_wall = 40.0f / 3.0f;
  cv::Mat disparity(kHeight, kWidth, CV_32FC1, cv::Scalar(d_wall));
  disparity.colRange(60, 100).setTo(d_box);
  for (int k = 1; k <= 6; ++k) {
    const float a = static_cast<float>(k) / 7.0f;
    disparity.col(60 - k).setTo(d_box + a * (d_wall - d_box));
    disparity.col(99 + k).setTo(d_box + a * (d_wall - d_box));
  }
  CloudFromDisparity builder;
  ASSERT_TRUE(builder.init(g, CloudConfig{}, kWidth, kHeight));
  OrganizedCloud cloud;
  ASSERT_TRUE(builder.allocateCloud(&cloud));
  ASSERT_TRUE(builder.compute(disparity, &cloud));
  MixedPixelFilter filter;
  ASSERT_TRUE(filter.init(MixedPixelConfig{}, cloud.rows(), cloud.cols()));
  // WHEN filtered
  const int removed = filter.apply(&cloud);
  // THEN all streak pixels are gone; of the surfaces at most the pixel touching the streak
  for (int v = 0; v < kHeight; ++v) {
    for (int k = 1; k <= 6; ++k) {
      EXPECT_FALSE(OrganizedCloud::isValid(cloud.row(v)[60 - k])) << k;
      EXPECT_FALSE(OrganizedCloud::isValid(cloud.row(v)[99 + k])) << k;
    }
    for (int u : {52, 61, 98, 107}) EXPECT_TRUE(OrganizedCloud::isValid(cloud.row(v)[u])) << u;
  }
  EXPECT_GE(removed, kHeight * 12);
  EXPECT_LE(removed, kHeight * (12 + 4));
}

TEST(MixedPixelFilter, KeepsAFloorSeenAtGrazingIncidence) {
  // GIVEN a floor 0.5 m below the camera seen up to 4 m away (incidence up to ~83 deg)
  const StereoGeometry g = geometry();
  const cv::Mat disparity = planeDisparity(Eigen::Vector3d(0, -1, 0), -0.5, g);
  CloudConfig config;
  config.max_range_m = 4.0;
  CloudFromDisparity builder;
  ASSERT_TRUE(builder.init(g, config, kWidth, kHeight));
  OrganizedCloud cloud;
  ASSERT_TRUE(builder.allocateCloud(&cloud));
  ASSERT_TRUE(builder.compute(disparity, &cloud));
  const int valid = cloud.countValid();
  ASSERT_GT(valid, 1000);
  MixedPixelFilter filter;
  ASSERT_TRUE(filter.init(MixedPixelConfig{}, cloud.rows(), cloud.cols()));
  // WHEN filtered THEN nothing is removed
  EXPECT_EQ(filter.apply(&cloud), 0);
}

}  // namespace
}  // namespace deepnav
