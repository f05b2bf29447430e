// GridOrbExtractor and SteeredBrief: features spread over the grid, the per-cell adaptive FAST
// threshold keeps low-contrast images usable, descriptors follow the corner's orientation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "tests/support/synthetic_plane_scene.h"
#include "vision/orbvo/grid_orb_extractor.h"

namespace deepnav {
namespace {

constexpr int kWidthPx = 688;
constexpr int kHeightPx = 516;

// The left image of the test scene at contrast 0.6 (usual) or 0.1 (dim), rendered once.
const cv::Mat& sceneImage(double contrast) {
  static const cv::Mat usual = renderOrbVoTestImage(11, 0.6, 3);
  static const cv::Mat dim = renderOrbVoTestImage(11, 0.1, 3);
  return contrast > 0.3 ? usual : dim;
}

TEST(OrbVoExtractor, SmoothsInFixedPointOnThisPlatform) {
  GridOrbExtractor extractor;
  ASSERT_TRUE(extractor.init(OrbExtractorConfig(), kWidthPx, kHeightPx));
  EXPECT_TRUE(extractor.smoothsInFixedPoint());  // else every pair pays cv::GaussianBlur again
}

// FastCornerMap against cv::FAST per cell: the same features and descriptors over a sequence in
// which the cells' thresholds move (usual, dim, usual again, and the same images mirrored).
TEST(OrbVoExtractor, CornerMapGivesTheFeaturesOfCvFastPerCell) {
  OrbExtractorConfig reference_config;
  reference_config.fast_corner_map = false;
  GridOrbExtractor corner_map_extractor, reference;
  ASSERT_TRUE(corner_map_extractor.init(OrbExtractorConfig(), kWidthPx, kHeightPx));
  ASSERT_TRUE(reference.init(reference_config, kWidthPx, kHeightPx));
  ASSERT_TRUE(corner_map_extractor.detectsWithCornerMap());
  EXPECT_FALSE(reference.detectsWithCornerMap());
  std::vector<cv::Mat> sequence = {sceneImage(0.6), sceneImage(0.1), sceneImage(0.6)};
  for (int i = 0; i < 3; ++i) {
    cv::Mat mirrored;
    cv::flip(sequence[i], mirrored, 1);
    sequence.push_back(mirrored);
  }
  std::vector<OrbFeature> f1, f2;
  std::vector<OrbDescriptor> d1, d2;
  for (std::size_t i = 0; i < sequence.size(); ++i) {
    const int n = corner_map_extractor.extract(sequence[i], &f1, &d1);
    ASSERT_EQ(n, reference.extract(sequence[i], &f2, &d2)) << "image " << i;
    ASSERT_GT(n, 100);
    for (int k = 0; k < n; ++k) {
      EXPECT_EQ(f1[k].u_px, f2[k].u_px) << "image " << i << " feature " << k;
      EXPECT_EQ(f1[k].v_px, f2[k].v_px) << "image " << i << " feature " << k;
      EXPECT_EQ(f1[k].level, f2[k].level);
      EXPECT_EQ(f1[k].response, f2[k].response);
      EXPECT_EQ(f1[k].angle_rad, f2[k].angle_rad);
      EXPECT_EQ(d1[k], d2[k]) << "image " << i << " feature " << k;
    }
  }
}

TEST(OrbVoExtractor, SpreadsFeaturesOverEveryCell) {
  GridOrbExtractor extractor;
  ASSERT_TRUE(extractor.init(OrbExtractorConfig(), kWidthPx, kHeightPx));
  std::vector<OrbFeature> features;
  std::vector<OrbDescriptor> descriptors;
  const cv::Mat& image = sceneImage(0.6);
  const int n = extractor.extract(image, &features, &descriptors);
  ASSERT_GT(n, 0);
  EXPECT_LE(n, extractor.capacity());
  EXPECT_EQ(descriptors.size(), features.size());
  // Every level-0 cell (8 x 6 over the image) holds features; none sits on the border.
  std::vector<int> per_cell(48, 0);
  int previous_level = 0;
  for (const OrbFeature& f : features) {
    EXPECT_GE(f.level, previous_level);  // sorted by level
    previous_level = f.level;
    EXPECT_GE(f.u_px, 15.0f);
    EXPECT_LE(f.u_px, kWidthPx - 16.0f);
    EXPECT_GE(f.v_px, 15.0f);
    EXPECT_LE(f.v_px, kHeightPx - 16.0f);
    if (f.level != 0) continue;
    const int col = std::min(7, static_cast<int>(f.u_px) * 8 / kWidthPx);
    const int row = std::min(5, static_cast<int>(f.v_px) * 6 / kHeightPx);
    ++per_cell[row * 8 + col];
  }
  const int max_cell = *std::max_element(per_cell.begin(), per_cell.end());
  const int min_cell = *std::min_element(per_cell.begin(), per_cell.end());
  EXPECT_GE(min_cell, 3);  // these test cells straddle the extractor's (which exclude the border)
  EXPECT_LE(max_cell, 2 * OrbExtractorConfig().max_features_per_cell);
}

TEST(OrbVoExtractor, AdaptiveThresholdKeepsLowContrastImagesUsable) {
  // GIVEN a dim, low-contrast view (texture stddev about 4 grey levels)
  const cv::Mat& image = sceneImage(0.1);
  OrbExtractorConfig fixed;
  fixed.fast_threshold_min = 20;  // ORB's usual fixed threshold
  fixed.fast_threshold_max = 20;
  GridOrbExtractor adaptive_extractor, fixed_extractor;
  ASSERT_TRUE(adaptive_extractor.init(OrbExtractorConfig(), kWidthPx, kHeightPx));
  ASSERT_TRUE(fixed_extractor.init(fixed, kWidthPx, kHeightPx));
  std::vector<OrbFeature> features;
  std::vector<OrbDescriptor> descriptors;
  // WHEN both extract (the adaptive one twice: its thresholds settle on the first image)
  adaptive_extractor.extract(image, &features, &descriptors);
  const int adaptive = adaptive_extractor.extract(image, &features, &descriptors);
  const int fixed_count = fixed_extractor.extract(image, &features, &descriptors);
  // THEN the adaptive thresholds fill most budgets where a fixed threshold finds almost nothing
  EXPECT_GT(adaptive, adaptive_extractor.capacity() * 7 / 10);
  EXPECT_LT(fixed_count, fixed_extractor.capacity() / 5);
  std::printf("low contrast: adaptive %d, fixed threshold 20: %d of %d\n", adaptive, fixed_count,
              fixed_extractor.capacity());
}

TEST(OrbVoExtractor, DescriptorsTurnWithTheImage) {
  // GIVEN an image and the same image turned by 90 degrees (an exact pixel permutation)
  const cv::Mat& image = sceneImage(0.6);
  cv::Mat turned;
  cv::rotate(image, turned, cv::ROTATE_90_CLOCKWISE);
  OrbExtractorConfig config;
  config.n_levels = 1;
  GridOrbExtractor a, b;
  ASSERT_TRUE(a.init(config, image.cols, image.rows));
  ASSERT_TRUE(b.init(config, turned.cols, turned.rows));
  std::vector<OrbFeature> fa, fb;
  std::vector<OrbDescriptor> da, db;
  a.extract(image, &fa, &da);
  b.extract(turned, &fb, &db);
  // WHEN a corner is found at the same place in both, THEN its descriptors nearly agree, while
  // unrelated corners differ by about half of the 256 bits.
  std::vector<int> same, other;
  for (std::size_t i = 0; i < fa.size(); ++i) {
    // Clockwise turn: (u, v) -> (rows - 1 - v, u).
    const float u_turned = static_cast<float>(image.rows - 1) - fa[i].v_px;
    const float v_turned = fa[i].u_px;
    for (std::size_t j = 0; j < fb.size(); ++j) {
      if (std::abs(fb[j].u_px - u_turned) < 0.5f && std::abs(fb[j].v_px - v_turned) < 0.5f) {
        same.push_back(hammingDistance(da[i], db[j]));
        other.push_back(hammingDistance(da[i], db[(j + fb.size() / 2) % fb.size()]));
      }
    }
  }
  ASSERT_GT(same.size(), 100u);
  std::nth_element(same.begin(), same.begin() + same.size() / 2, same.end());
  std::nth_element(other.begin(), other.begin() + other.size() / 2, other.end());
  EXPECT_LT(same[same.size() / 2], 20);
  EXPECT_GT(other[other.size() / 2], 60);
}

TEST(OrbVoExtractor, HammingDistanceCountsDifferingBits) {
  cv::RNG rng(8);
  for (int trial = 0; trial < 200; ++trial) {
    OrbDescriptor a, b;
    int expected = 0;
    for (int w = 0; w < 4; ++w) {
      a[w] = (static_cast<std::uint64_t>(rng.next()) << 32) | rng.next();
      b[w] = trial % 3 == 0 ? a[w] : (static_cast<std::uint64_t>(rng.next()) << 32) | rng.next();
      for (int bit = 0; bit < 64; ++bit) expected += ((a[w] ^ b[w]) >> bit) & 1u;
    }
    EXPECT_EQ(hammingDistance(a, b), expected);
  }
  OrbDescriptor zero{}, ones;
  ones.fill(~0ull);
  EXPECT_EQ(hammingDistance(zero, ones), 256);
}

TEST(OrbVoExtractor, RejectsBadConfigurationAndImages) {
  GridOrbExtractor extractor;
  OrbExtractorConfig config;
  config.n_levels = 0;
  EXPECT_FALSE(extractor.init(config, kWidthPx, kHeightPx));
  config = OrbExtractorConfig();
  config.fast_threshold_min = 30;
  config.fast_threshold_max = 20;
  EXPECT_FALSE(extractor.init(config, kWidthPx, kHeightPx));
  ASSERT_TRUE(extractor.init(OrbExtractorConfig(), kWidthPx, kHeightPx));
  std::vector<OrbFeature> features;
  std::vector<OrbDescriptor> descriptors;
  EXPECT_EQ(extractor.extract(cv::Mat(10, 10, CV_8UC1, cv::Scalar(0)), &features, &descriptors),
            -1);
  EXPECT_EQ(extractor.extract(cv::Mat(kHeightPx, kWidthPx, CV_8UC3, cv::Scalar(0)), &features,
                              &descriptors),
            -1);
  EXPECT_EQ(extractor.extract(cv::Mat(kHeightPx, kWidthPx, CV_8UC1, cv::Scalar(0)), &features,
                              &descriptors),
            0);
}

}  // namespace
}  // namespace deepnav
