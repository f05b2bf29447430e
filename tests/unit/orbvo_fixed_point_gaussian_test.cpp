// FixedPointGaussian: cv::GaussianBlur's 8-bit result bit for bit, on this platform's OpenCV (x86_64 here,
// aarch64 under qemu in CI), for the ORB pyramid's sizes and for odd sizes and other sigmas.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "vision/orbvo/fixed_point_gaussian.h"

namespace deepnav {
namespace {

cv::Mat randomImage(cv::Size size, std::uint64_t seed) {
  cv::Mat image(size, CV_8UC1);
  cv::RNG(seed).fill(image, cv::RNG::UNIFORM, 0, 256);
  return image;
}

// Smooth gradients and hard edges: the texture the blur sees in a dive image.
cv::Mat sceneImage(cv::Size size) {
  cv::Mat image(size, CV_8UC1);
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      const int ramp = (x * 255) / size.width;
      image.at<std::uint8_t>(y, x) = static_cast<std::uint8_t>(((x / 7 + y / 5) % 2) ? ramp : 255 - ramp);
    }
  }
  return image;
}

void expectSameAsOpenCv(double sigma_px, int kernel_px, const std::vector<cv::Size>& sizes) {
  FixedPointGaussian blur;
  ASSERT_TRUE(blur.init(sigma_px, kernel_px, sizes)) << "sigma " << sigma_px << ", kernel " << kernel_px;
  for (const cv::Size& size : sizes) {
    for (const cv::Mat& image : {randomImage(size, 7), sceneImage(size)}) {
      cv::Mat expected, got;
      cv::GaussianBlur(image, expected, cv::Size(kernel_px, kernel_px), sigma_px);
      blur.apply(image, &got);
      ASSERT_EQ(got.size(), size);
      EXPECT_EQ(cv::norm(expected, got, cv::NORM_INF), 0.0)
          << "sigma " << sigma_px << ", kernel " << kernel_px << ", " << size.width << "x" << size.height;
    }
  }
}

TEST(FixedPointGaussian, ReproducesOpenCvOnTheOrbPyramidSizes) {
  // 688x516 and its levels at scale 1.2 (the ORB extractor's defaults), sigma 2 px: OpenCV's own 13 taps
  // (the extractor's default) and 7 (OpenCV's ORB and ORB-SLAM, extractor.smoothing_kernel_px = 7).
  for (int kernel_px : {7, 0}) expectSameAsOpenCv(2.0, kernel_px, {{688, 516}, {573, 430}, {478, 358}});
}

TEST(FixedPointGaussian, ReproducesOpenCvForOddSizesAndOtherSigmas) {
  // Widths that leave a scalar tail after the 16-pixel vectors, and kernels of 5 to 19 taps.
  for (double sigma_px : {0.8, 1.2, 2.0, 3.0}) expectSameAsOpenCv(sigma_px, 0, {{37, 29}, {101, 64}, {255, 17}});
  for (int kernel_px : {3, 5, 9}) expectSameAsOpenCv(2.0, kernel_px, {{37, 29}, {101, 64}});
}

TEST(FixedPointGaussian, ReadsOpenCvsWeights) {
  FixedPointGaussian blur;
  ASSERT_TRUE(blur.init(2.0, 0, {{64, 64}}));
  EXPECT_EQ(blur.radiusPx(), 6);  // OpenCV: ksize = round(2 * 3 * sigma + 1) | 1 = 13 for 8-bit images
  ASSERT_TRUE(blur.init(2.0, 7, {{64, 64}}));
  EXPECT_EQ(blur.radiusPx(), 3);
}

TEST(FixedPointGaussian, RefusesWhatItCannotReproduce) {
  FixedPointGaussian blur;
  EXPECT_FALSE(blur.init(0.0, 0, {{64, 64}}));
  EXPECT_FALSE(blur.init(-1.0, 0, {{64, 64}}));
  EXPECT_FALSE(blur.init(5.0, 0, {{256, 256}}));  // 31 taps: wider than kMaxRadiusPx
  EXPECT_FALSE(blur.init(2.0, 0, {{12, 64}}));     // narrower than the kernel: reflection not handled
  EXPECT_FALSE(blur.init(2.0, 6, {{64, 64}}));     // an even kernel
  EXPECT_FALSE(blur.init(2.0, 1, {{64, 64}}));     // one tap: no smoothing to reproduce
}

TEST(FixedPointGaussian, DoesNotReallocateAnImageOfTheSameSize) {
  FixedPointGaussian blur;
  ASSERT_TRUE(blur.init(2.0, 7, {{96, 80}}));
  cv::Mat dst(80, 96, CV_8UC1);
  const std::uint8_t* before = dst.data;
  blur.apply(randomImage({96, 80}, 1), &dst);
  EXPECT_EQ(dst.data, before);
}

}  // namespace
}  // namespace deepnav
