#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "vision/stereo/elas_disparity.h"
#include "vision/stereo/stereo_accuracy.h"

namespace deepnav {
namespace {

// A rectified pair of a low-contrast textured scene (grey levels ~60..190): a slanted background
// plane (disparity 8 -> 20 px across the image) and a fronto-parallel box at 30 px in front.
struct SyntheticPair {
  cv::Mat left, right, truth_px;
};

float backgroundDisparity(float u, int width) {
  return 8.0f + 12.0f * u / static_cast<float>(width);
}

SyntheticPair makePair(int width, int height) {
  cv::Mat texture(height, width + 64, CV_8UC1), box_texture(height, width + 64, CV_8UC1);
  cv::RNG rng(11);
  rng.fill(texture, cv::RNG::UNIFORM, 0, 256);
  rng.fill(box_texture, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(texture, texture, cv::Size(0, 0), 1.2);
  cv::GaussianBlur(box_texture, box_texture, cv::Size(0, 0), 1.2);
  const cv::Rect box(width / 3, height / 3, width / 3, height / 3);
  constexpr float kBoxDisparity = 30.0f;
  SyntheticPair pair{cv::Mat(height, width, CV_8UC1), cv::Mat(height, width, CV_8UC1),
                     cv::Mat(height, width, CV_32F)};
  auto sample = [](const cv::Mat& tex, int v, float x) {  // linear interpolation along the row
    const int x0 = std::clamp(static_cast<int>(x), 0, tex.cols - 2);
    const float a = x - static_cast<float>(x0);
    return (1.0f - a) * tex.at<std::uint8_t>(v, x0) + a * tex.at<std::uint8_t>(v, x0 + 1);
  };
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      const bool in_box = box.contains(cv::Point(u, v));
      pair.truth_px.at<float>(v, u) = in_box ? kBoxDisparity : backgroundDisparity(u, width);
      pair.left.at<std::uint8_t>(v, u) =
          in_box ? box_texture.at<std::uint8_t>(v, u) : texture.at<std::uint8_t>(v, u + 32);
      // right pixel ur sees the box if ur + 30 is in the box, else the background point
      // u_left with u_left - d(u_left) = ur
      const int u_box = u + static_cast<int>(kBoxDisparity);
      float value;
      if (box.contains(cv::Point(u_box, v))) {
        value = box_texture.at<std::uint8_t>(v, u_box);
      } else {
        const float u_left =
            (static_cast<float>(u) + 8.0f) / (1.0f - 12.0f / static_cast<float>(width));
        value = sample(texture, v, u_left + 32.0f);
      }
      pair.right.at<std::uint8_t>(v, u) = cv::saturate_cast<std::uint8_t>(value);
    }
  }
  // squeeze the contrast: underwater-like
  pair.left.convertTo(pair.left, CV_8U, 0.5, 64);
  pair.right.convertTo(pair.right, CV_8U, 0.5, 64);
  return pair;
}

TEST(ElasDisparity, RecoversSlantedPlaneAndBoxOnLowContrastTexture) {
  // GIVEN a synthetic low-contrast pair with known disparity
  const SyntheticPair pair = makePair(320, 240);
  ElasDisparity elas;
  ASSERT_TRUE(elas.init(ElasParams::dense(), 320, 240));
  // WHEN matched
  cv::Mat disparity_px;
  ASSERT_TRUE(elas.compute(pair.left, pair.right, &disparity_px));
  // THEN, away from the left border where the background is not visible in the right image,
  // almost every pixel is within the D1 tolerance and sub-pixel accuracy holds on the plane
  cv::Mat mask(240, 320, CV_8UC1, cv::Scalar(255));
  mask.colRange(0, 32).setTo(0);
  const StereoAccuracy acc = evaluateDisparity(disparity_px, pair.truth_px, mask);
  EXPECT_GT(elas.supportPointCount(), 500);
  EXPECT_LT(acc.d1, 0.01);
  EXPECT_LT(acc.mean_abs_error_px, 0.3);
}

TEST(ElasDisparity, RoboticsPresetLeavesUnmatchedPixelsInvalid) {
  // GIVEN a pair whose left half is textureless
  SyntheticPair pair = makePair(320, 240);
  pair.left.colRange(0, 160).setTo(100);
  pair.right.colRange(0, 160).setTo(100);
  ElasDisparity elas;
  ASSERT_TRUE(elas.init(ElasParams::robotics(), 320, 240));
  cv::Mat disparity_px;
  ASSERT_TRUE(elas.compute(pair.left, pair.right, &disparity_px));
  // THEN the flat part has (almost) no disparity and the textured part is matched
  const double flat_valid = cv::countNonZero(disparity_px(cv::Rect(20, 20, 100, 200)) >= 0.0f);
  const double textured_valid = cv::countNonZero(disparity_px(cv::Rect(200, 20, 100, 200)) >= 0.0f);
  EXPECT_LT(flat_valid / 20000.0, 0.05);
  EXPECT_GT(textured_valid / 20000.0, 0.9);
}

TEST(ElasDisparity, FlatImagesGiveNoDisparityAndNoCrash) {
  const cv::Mat flat(120, 160, CV_8UC1, cv::Scalar(80));
  ElasDisparity elas;
  ASSERT_TRUE(elas.init(ElasParams::dense(), 160, 120));
  cv::Mat disparity_px;
  ASSERT_TRUE(elas.compute(flat, flat, &disparity_px));
  EXPECT_EQ(cv::countNonZero(disparity_px >= 0.0f), 0);
}

TEST(ElasDisparity, RefusesWrongSizesTypesAndBadParameters) {
  ElasDisparity elas;
  cv::Mat disparity_px;
  const cv::Mat image(120, 160, CV_8UC1, cv::Scalar(0));
  EXPECT_FALSE(elas.compute(image, image, &disparity_px));  // not initialised
  ElasParams bad;
  bad.num_disparities = 300;
  EXPECT_FALSE(elas.init(bad, 160, 120));
  EXPECT_FALSE(elas.init(ElasParams{}, 8, 8));
  ASSERT_TRUE(elas.init(ElasParams{}, 160, 120));
  EXPECT_FALSE(elas.compute(cv::Mat(100, 160, CV_8UC1), image, &disparity_px));
  EXPECT_FALSE(elas.compute(cv::Mat(120, 160, CV_16UC1), image, &disparity_px));
  EXPECT_FALSE(elas.compute(image, image, nullptr));
}

TEST(ElasDisparity, ReusesTheCallersBuffer) {
  const SyntheticPair pair = makePair(320, 240);
  ElasDisparity elas;
  ASSERT_TRUE(elas.init(ElasParams{}, 320, 240));
  cv::Mat disparity_px(240, 320, CV_32F);
  const float* data = disparity_px.ptr<float>(0);
  ASSERT_TRUE(elas.compute(pair.left, pair.right, &disparity_px));
  EXPECT_EQ(disparity_px.ptr<float>(0), data);
}

}  // namespace
}  // namespace deepnav
