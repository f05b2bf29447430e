#include "vision/stereo/gt_disparity.h"

#include <gtest/gtest.h>

#include <limits>

#include "vision/stereo/stereo_accuracy.h"

namespace deepnav {
namespace {

TEST(GtDisparity, ServesTheTruthWithNoSurfaceAsInvalid) {
  // GIVEN a 4x3 truth with open water (0), a NaN and one disparity beyond the search range
  cv::Mat truth(3, 4, CV_32FC1, cv::Scalar(10.25f));
  truth.at<float>(0, 1) = 0.0f;
  truth.at<float>(1, 2) = std::numeric_limits<float>::quiet_NaN();
  truth.at<float>(2, 3) = 70.0f;
  const cv::Mat images(3, 4, CV_8UC1, cv::Scalar(0));
  GtDisparity gt;
  ASSERT_TRUE(gt.init(4, 3, 64));
  // WHEN it serves the pair
  ASSERT_TRUE(gt.setTruth(truth));
  cv::Mat d;
  ASSERT_TRUE(gt.compute(images, images, &d));
  // THEN every surface pixel is the truth and the rest is invalid
  ASSERT_EQ(d.type(), CV_32FC1);
  EXPECT_EQ(d.at<float>(0, 0), 10.25f);
  EXPECT_EQ(d.at<float>(0, 1), kInvalidDisparity);
  EXPECT_EQ(d.at<float>(1, 2), kInvalidDisparity);
  EXPECT_EQ(d.at<float>(2, 3), kInvalidDisparity);
  // and it scores perfectly against the truth it came from (within the search range)
  cv::Mat in_range = truth.clone();
  in_range.at<float>(2, 3) = 0.0f;
  in_range.at<float>(1, 2) = 0.0f;
  const StereoAccuracy acc = evaluateDisparity(d, in_range, cv::Mat());
  EXPECT_EQ(acc.evaluated_px, 9);  // 12 minus open water, the NaN and the out-of-range pixel
  EXPECT_EQ(acc.d1, 0.0);
  EXPECT_EQ(acc.coverage, 1.0);
}

TEST(GtDisparity, OneTruthServesOneFrame) {
  const cv::Mat truth(3, 4, CV_32FC1, cv::Scalar(5.0f));
  const cv::Mat images(3, 4, CV_8UC1, cv::Scalar(0));
  GtDisparity gt;
  ASSERT_TRUE(gt.init(4, 3));
  cv::Mat d;
  EXPECT_FALSE(gt.compute(images, images, &d));  // no truth yet
  ASSERT_TRUE(gt.setTruth(truth));
  EXPECT_TRUE(gt.compute(images, images, &d));
  EXPECT_FALSE(gt.compute(images, images, &d));  // stale truth is never served again
}

TEST(GtDisparity, RefusesMismatchedSizesAndTypes) {
  GtDisparity gt;
  ASSERT_TRUE(gt.init(4, 3));
  EXPECT_FALSE(gt.setTruth(cv::Mat(3, 5, CV_32FC1, cv::Scalar(1.0f))));
  EXPECT_FALSE(gt.setTruth(cv::Mat(3, 4, CV_16UC1, cv::Scalar(1))));
  ASSERT_TRUE(gt.setTruth(cv::Mat(3, 4, CV_32FC1, cv::Scalar(1.0f))));
  cv::Mat d;
  EXPECT_FALSE(gt.compute(cv::Mat(2, 4, CV_8UC1), cv::Mat(2, 4, CV_8UC1), &d));
  EXPECT_FALSE(gt.init(0, 3));
}

}  // namespace
}  // namespace deepnav
