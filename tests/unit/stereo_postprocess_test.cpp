#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "vision/stereo/disparity_edge_refiner.h"
#include "vision/stereo/disparity_estimator.h"
#include "vision/stereo/disparity_gap_fill.h"
#include "vision/stereo/disparity_lr_check.h"
#include "vision/stereo/disparity_speckle_filter.h"

namespace deepnav {
namespace {

TEST(DisparityLeftRight, KeepsConsistentAndDropsInconsistent) {
  // GIVEN a left map of 4 px and a right map agreeing except at one place
  cv::Mat left(1, 20, CV_32F, cv::Scalar(4.0f));
  cv::Mat right(1, 20, CV_32F, cv::Scalar(4.0f));
  right.at<float>(0, 6) = 9.0f;  // left u = 10 maps to right u = 6
  // WHEN checked with a 1 px threshold
  checkLeftRight(right, 1.0f, &left);
  // THEN u = 10 and the pixels that fall off the right image (u < 4) are invalid
  EXPECT_LT(left.at<float>(0, 10), 0.0f);
  EXPECT_LT(left.at<float>(0, 3), 0.0f);
  EXPECT_FLOAT_EQ(left.at<float>(0, 4), 4.0f);
  EXPECT_FLOAT_EQ(left.at<float>(0, 11), 4.0f);
}

TEST(DisparitySpeckle, RemovesSmallSegmentsOnly) {
  cv::Mat d(20, 20, CV_32F, cv::Scalar(10.0f));
  d(cv::Rect(2, 2, 3, 3)).setTo(30.0f);    // 9 px island
  d(cv::Rect(10, 10, 8, 8)).setTo(20.0f);  // 64 px segment
  DisparitySpeckleFilter filter;
  ASSERT_TRUE(filter.allocate(20, 20));
  filter.apply(50, 1.0f, &d);
  EXPECT_LT(d.at<float>(3, 3), 0.0f);
  EXPECT_FLOAT_EQ(d.at<float>(12, 12), 20.0f);
  EXPECT_FLOAT_EQ(d.at<float>(0, 0), 10.0f);
}

// The definition, written as a plain flood fill: 4-connected segments of valid pixels whose
// neighbours differ by at most sim_px; those under min_size_px pixels become invalid. A NaN is not
// below 0, so it starts a segment, but joins nothing: a segment of one.
cv::Mat floodFillSpeckles(const cv::Mat& in, int min_size_px, float sim_px) {
  cv::Mat out = in.clone();
  cv::Mat seen(in.size(), CV_8U, cv::Scalar(0));
  const int du[4] = {-1, 1, 0, 0};
  const int dv[4] = {0, 0, -1, 1};
  for (int v0 = 0; v0 < in.rows; ++v0) {
    for (int u0 = 0; u0 < in.cols; ++u0) {
      if (seen.at<std::uint8_t>(v0, u0) || in.at<float>(v0, u0) < 0.0f) continue;
      std::vector<cv::Point> segment{{u0, v0}};
      seen.at<std::uint8_t>(v0, u0) = 1;
      for (std::size_t k = 0; k < segment.size(); ++k) {
        const cv::Point p = segment[k];
        for (int n = 0; n < 4; ++n) {
          const cv::Point q(p.x + du[n], p.y + dv[n]);
          if (q.x < 0 || q.y < 0 || q.x >= in.cols || q.y >= in.rows) continue;
          const float dq = in.at<float>(q), dp = in.at<float>(p);
          const bool joins = dq >= 0.0f && std::fabs(dq - dp) <= sim_px;  // false with a NaN
          if (seen.at<std::uint8_t>(q) || !joins) continue;
          seen.at<std::uint8_t>(q) = 1;
          segment.push_back(q);
        }
      }
      if (static_cast<int>(segment.size()) >= min_size_px) continue;
      for (const cv::Point& p : segment) out.at<float>(p) = kInvalidDisparity;
    }
  }
  return out;
}

// Pixels whose values differ, a NaN equal only to a NaN (cv::norm would skip NaNs).
int differingPixels(const cv::Mat& a, const cv::Mat& b) {
  int n = 0;
  for (int v = 0; v < a.rows; ++v) {
    for (int u = 0; u < a.cols; ++u) {
      const float x = a.at<float>(v, u), y = b.at<float>(v, u);
      n += !(x == y || (std::isnan(x) && std::isnan(y)));
    }
  }
  return n;
}

TEST(DisparitySpeckle, RemovesWhatAFloodFillRemovesOnNoisyMaps) {
  // GIVEN noisy maps: few disparity levels, so that segments meander, merge below U shapes and
  // enclose one another, with holes of invalid pixels and a few NaNs
  std::mt19937 rng(7);
  int removed = 0, kept = 0;
  for (const float invalid_share : {0.0f, 0.2f, 0.5f}) {
    for (const int levels : {3, 6, 20}) {
      cv::Mat d(57, 83, CV_32F);
      std::uniform_int_distribution<int> level(0, levels - 1);
      std::uniform_real_distribution<float> unit(0.0f, 1.0f);
      for (int v = 0; v < d.rows; ++v) {
        for (int u = 0; u < d.cols; ++u) {
          d.at<float>(v, u) = unit(rng) < invalid_share ? kInvalidDisparity : 2.0f * level(rng);
          if (unit(rng) < 0.002f) d.at<float>(v, u) = std::nanf("");  // never joins anything
        }
      }
      const cv::Mat input = d.clone();
      // WHEN filtered
      const cv::Mat expected = floodFillSpeckles(d, 12, 2.0f);
      DisparitySpeckleFilter filter;
      ASSERT_TRUE(filter.allocate(d.cols, d.rows));
      filter.apply(12, 2.0f, &d);
      // THEN the same pixels remain, with the same values
      EXPECT_EQ(differingPixels(d, expected), 0) << invalid_share << " " << levels;
      removed += cv::countNonZero((expected < 0.0f) & (input >= 0.0f));
      kept += cv::countNonZero(expected >= 0.0f);
    }
  }
  // AND the maps had both kinds of segments
  EXPECT_GT(removed, 1000);
  EXPECT_GT(kept, 1000);
}

TEST(DisparityGapFill, InterpolatesOneSurfaceAndTakesBackgroundBetweenTwo) {
  cv::Mat d(1, 12, CV_32F, cv::Scalar(kInvalidDisparity));
  d.at<float>(0, 0) = 10.0f;
  d.at<float>(0, 4) = 12.0f;  // gap 1..3 on one surface: linear
  d.at<float>(0, 6) = 30.0f;  // gap 5 between 12 and 30: background (12)
  // 7..11 open to the border
  fillDisparityGaps(3, false, &d);
  EXPECT_FLOAT_EQ(d.at<float>(0, 2), 11.0f);
  EXPECT_FLOAT_EQ(d.at<float>(0, 5), 12.0f);
  EXPECT_LT(d.at<float>(0, 9), 0.0f);  // border run not filled without fill_borders
  fillDisparityGaps(3, true, &d);
  EXPECT_LT(d.at<float>(0, 9), 0.0f);  // 5 px > max gap
  fillDisparityGaps(100, true, &d);
  EXPECT_FLOAT_EQ(d.at<float>(0, 9), 30.0f);
}

TEST(DisparityEdgeRefiner, HandsFattenedPixelsBackToTheSurfaceTheyLookLike) {
  // GIVEN an image with a bright square on a dark background and a disparity map in which the
  // square's disparity spills 3 px beyond its right edge (window-matching fattening)
  cv::Mat image(40, 40, CV_8UC1, cv::Scalar(40));
  image(cv::Rect(10, 10, 15, 20)).setTo(200);
  cv::Mat d(40, 40, CV_32F, cv::Scalar(5.0f));
  d(cv::Rect(10, 10, 18, 20)).setTo(20.0f);
  DisparityEdgeRefiner refiner;
  ASSERT_TRUE(refiner.allocate(40, 40, 32));
  // WHEN refined
  EdgeRefineParams params;
  params.budget = 1e9f;
  refiner.apply(image, params, &d);
  // THEN the dark pixels take the background disparity and the square keeps its own
  EXPECT_FLOAT_EQ(d.at<float>(20, 26), 5.0f);
  EXPECT_FLOAT_EQ(d.at<float>(20, 25), 5.0f);
  EXPECT_FLOAT_EQ(d.at<float>(20, 24), 20.0f);
  EXPECT_FLOAT_EQ(d.at<float>(20, 11), 20.0f);
}

}  // namespace
}  // namespace deepnav
