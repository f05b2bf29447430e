#include <gtest/gtest.h>

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
