// SteeredBrief's fast paths (vectorised orientation moments, descriptor sample offsets precomputed
// per row step) give the same bits as the plain loops: the VO's poses must not move with them.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "vision/orbvo/steered_brief.h"

namespace deepnav {
namespace {

// Uniform noise, blurred a little so neighbouring pixels correlate as in a real image; a saturated
// patch pins the extremes (sums of 255s) the 16-bit lanes must carry.
cv::Mat testImage(int width_px, int height_px, std::uint64_t seed) {
  cv::Mat image(height_px, width_px, CV_8UC1);
  cv::RNG(seed).fill(image, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(image, image, cv::Size(3, 3), 0.8);
  image(cv::Rect(20, 20, 40, 40)).setTo(255);
  image(cv::Rect(60, 20, 40, 40)).setTo(0);
  return image;
}

TEST(OrbVoSteeredBrief, VectorisedOrientationEqualsPlainLoop) {
  const SteeredBrief brief;
  const int b = SteeredBrief::kBorderPx;
  for (const cv::Size size : {cv::Size(688, 516), cv::Size(573, 430), cv::Size(101, 77)}) {
    const cv::Mat image = testImage(size.width, size.height, 17 + size.width);
    int checked = 0;
    for (int y = b; y < image.rows - b; y += 3) {
      for (int x = b; x < image.cols - b; x += 2) {
        ASSERT_EQ(brief.orientationRad(image, x, y), brief.orientationRadScalar(image, x, y))
            << "at " << x << ", " << y << " in " << size;
        ++checked;
      }
    }
    // The last column and row a corner may take (the vector loads reach x + 16).
    const int x = image.cols - b - 1;
    const int y = image.rows - b - 1;
    EXPECT_EQ(brief.orientationRad(image, x, y), brief.orientationRadScalar(image, x, y));
    EXPECT_GT(checked, 100);
  }
}

TEST(OrbVoSteeredBrief, OffsetDescriptorEqualsPlainDescriptor) {
  const SteeredBrief brief;
  const int b = SteeredBrief::kBorderPx;
  for (const int width_px : {688, 478}) {
    const cv::Mat image = testImage(width_px, 300, 5 + width_px);
    SteeredBrief::Offsets offsets;
    brief.fillOffsets(static_cast<int>(image.step1()), &offsets);
    EXPECT_EQ(offsets.step, width_px);
    cv::RNG rng(9);
    int differing_bits = 0;
    for (int k = 0; k < 2000; ++k) {
      const int x = rng.uniform(b, image.cols - b);
      const int y = rng.uniform(b, image.rows - b);
      const float angle_rad = static_cast<float>(rng.uniform(-3.2, 3.2));
      OrbDescriptor plain{}, fast{};
      brief.describe(image, x, y, angle_rad, &plain);
      brief.describe(image, offsets, x, y, angle_rad, &fast);
      ASSERT_EQ(plain, fast) << "at " << x << ", " << y << ", angle " << angle_rad;
      differing_bits += __builtin_popcountll(plain[0] ^ plain[1]);
    }
    EXPECT_GT(differing_bits, 0);  // the descriptors are not trivially constant
  }
}

}  // namespace
}  // namespace deepnav
