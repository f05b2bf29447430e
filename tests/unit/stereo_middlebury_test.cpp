// Accuracy of the disparity backends on real data: Middlebury 2001 tsukuba and venus
// (Scharstein & Szeliski 2002), evaluated on the non-occluded pixels with the KITTI D1 rate.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "vision/stereo/elas_disparity.h"
#include "vision/stereo/sgbm_disparity.h"
#include "vision/stereo/stereo_accuracy.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

using deepnav::testing::sharedDataDir;

struct MiddleburyPair {
  cv::Mat left, right;  // BGR
  cv::Mat truth_px;     // CV_32F, 0 = unknown
  cv::Mat nonocc;       // CV_8UC1, 255 = evaluated
  int range_px = 0;     // disparity range declared by the data set
};

// info.txt: ground-truth scale, then disparity range.
bool loadPair(const std::string& name, MiddleburyPair* pair) {
  const std::filesystem::path dir = sharedDataDir() / "stereo" / ("middlebury-" + name);
  std::ifstream info(dir / "info.txt");
  double scale = 0.0;
  if (!(info >> scale >> pair->range_px) || scale <= 0.0) return false;
  pair->left = cv::imread((dir / "imL.png").string(), cv::IMREAD_COLOR);
  pair->right = cv::imread((dir / "imR.png").string(), cv::IMREAD_COLOR);
  const cv::Mat truth = cv::imread((dir / "groundtruth.png").string(), cv::IMREAD_GRAYSCALE);
  pair->nonocc = cv::imread((dir / "nonocc.png").string(), cv::IMREAD_GRAYSCALE);
  if (pair->left.empty() || pair->right.empty() || truth.empty() || pair->nonocc.empty())
    return false;
  truth.convertTo(pair->truth_px, CV_32F, 1.0 / scale);
  return true;
}

void report(const std::string& what, const StereoAccuracy& acc) {
  std::cout << "[ metrics  ] " << what << ": D1 " << 100.0 * acc.d1 << " %, >1px "
            << 100.0 * acc.bad1 << " %, coverage " << 100.0 * acc.coverage << " %, MAE "
            << acc.mean_abs_error_px << " px over " << acc.evaluated_px << " px\n";
}

StereoAccuracy runElas(const MiddleburyPair& pair) {
  ElasParams params = ElasParams::dense();
  params.num_disparities = pair.range_px + 1;
  ElasDisparity elas;
  EXPECT_TRUE(elas.init(params, pair.left.cols, pair.left.rows));
  cv::Mat disparity_px;
  EXPECT_TRUE(elas.compute(pair.left, pair.right, &disparity_px));
  return evaluateDisparity(disparity_px, pair.truth_px, pair.nonocc);
}

StereoAccuracy runSgbm(const MiddleburyPair& pair, bool wls) {
  SgbmParams params;
  params.num_disparities = pair.range_px + 1;
  params.wls = wls;
  SgbmDisparity sgbm;
  EXPECT_TRUE(sgbm.init(params, pair.left.cols, pair.left.rows));
  cv::Mat disparity_px;
  EXPECT_TRUE(sgbm.compute(pair.left, pair.right, &disparity_px));
  return evaluateDisparity(disparity_px, pair.truth_px, pair.nonocc);
}

class Middlebury : public ::testing::TestWithParam<const char*> {};

TEST_P(Middlebury, ElasD1AtMostTwoPercent) {
  MiddleburyPair pair;
  if (!loadPair(GetParam(), &pair)) GTEST_SKIP() << "no Middlebury data under " << sharedDataDir();
  const StereoAccuracy acc = runElas(pair);
  report(std::string("elas ") + GetParam(), acc);
  EXPECT_LE(acc.d1, 0.02);
  EXPECT_DOUBLE_EQ(acc.coverage, 1.0);  // dense preset
}

TEST_P(Middlebury, SgbmRunsAndWlsFillsTheMap) {
  MiddleburyPair pair;
  if (!loadPair(GetParam(), &pair)) GTEST_SKIP() << "no Middlebury data under " << sharedDataDir();
  const StereoAccuracy plain = runSgbm(pair, false);
  const StereoAccuracy wls = runSgbm(pair, true);
  report(std::string("sgbm ") + GetParam(), plain);
  report(std::string("sgbm+wls ") + GetParam(), wls);
  // Loose bounds: SGBM is the reference backend, not tuned; these only catch a broken wrapper.
  EXPECT_LT(plain.d1, 0.10);
  EXPECT_GT(plain.coverage, 0.85);
  EXPECT_LT(wls.d1, 0.10);
  EXPECT_GE(wls.coverage, plain.coverage);
}

INSTANTIATE_TEST_SUITE_P(Stereo, Middlebury, ::testing::Values("tsukuba", "venus"));

}  // namespace
}  // namespace deepnav
