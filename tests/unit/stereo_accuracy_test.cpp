#include "vision/stereo/stereo_accuracy.h"

#include <gtest/gtest.h>

#include <cmath>

#include "vision/stereo/disparity_estimator.h"

namespace deepnav {
namespace {

TEST(StereoAccuracy, CountsD1OneMissingAndBad1) {
  // GIVEN ground truth 40 px everywhere on a 10x10 map
  const cv::Mat truth(10, 10, CV_32F, cv::Scalar(40.0f));
  cv::Mat estimate = truth.clone();
  estimate.at<float>(0, 0) = 43.5f;              // 3.5 px = 8.75 %: a D1 outlier
  estimate.at<float>(0, 1) = 41.5f;              // 1.5 px: bad1 only
  estimate.at<float>(0, 2) = kInvalidDisparity;  // missing: wrong for both
  estimate.at<float>(0, 3) = std::nanf("");      // NaN: missing too
  estimate.at<float>(0, 4) = 40.9f;              // fine
  // WHEN evaluated over all pixels
  const StereoAccuracy acc = evaluateDisparity(estimate, truth, cv::Mat());
  // THEN
  EXPECT_EQ(acc.evaluated_px, 100);
  EXPECT_DOUBLE_EQ(acc.d1, 3.0 / 100.0);
  EXPECT_DOUBLE_EQ(acc.bad1, 4.0 / 100.0);
  EXPECT_DOUBLE_EQ(acc.coverage, 98.0 / 100.0);
  EXPECT_NEAR(acc.mean_abs_error_px, (3.5 + 1.5 + 0.9) / 98.0, 1e-6);
}

TEST(StereoAccuracy, D1NeedsBothAbsoluteAndRelativeError) {
  // 100 px truth: a 4 px error is > 3 px but only 4 % -> not a D1 outlier (KITTI definition)
  const cv::Mat truth(1, 2, CV_32F, cv::Scalar(100.0f));
  cv::Mat estimate = truth.clone();
  estimate.at<float>(0, 0) = 104.0f;
  estimate.at<float>(0, 1) = 106.0f;  // 6 %: outlier
  const StereoAccuracy acc = evaluateDisparity(estimate, truth, cv::Mat());
  EXPECT_DOUBLE_EQ(acc.d1, 0.5);
}

TEST(StereoAccuracy, MaskAndUnknownTruthAreSkipped) {
  cv::Mat truth(2, 2, CV_32F, cv::Scalar(10.0f));
  truth.at<float>(1, 1) = 0.0f;  // unknown
  const cv::Mat estimate(2, 2, CV_32F, cv::Scalar(kInvalidDisparity));
  cv::Mat mask(2, 2, CV_8UC1, cv::Scalar(255));
  mask.at<std::uint8_t>(0, 0) = 0;
  const StereoAccuracy acc = evaluateDisparity(estimate, truth, mask);
  EXPECT_EQ(acc.evaluated_px, 2);
  EXPECT_DOUBLE_EQ(acc.coverage, 0.0);
  EXPECT_DOUBLE_EQ(acc.d1, 1.0);
}

TEST(StereoAccuracy, MismatchedInputsEvaluateNothing) {
  const cv::Mat truth(4, 4, CV_32F, cv::Scalar(1.0f));
  EXPECT_EQ(evaluateDisparity(cv::Mat(4, 5, CV_32F), truth, cv::Mat()).evaluated_px, 0);
  EXPECT_EQ(evaluateDisparity(cv::Mat(4, 4, CV_16S), truth, cv::Mat()).evaluated_px, 0);
  EXPECT_EQ(evaluateDisparity(truth, truth, cv::Mat(3, 3, CV_8UC1)).evaluated_px, 0);
}

}  // namespace
}  // namespace deepnav
