// `deepnav stereo` as a user runs it, on the real Middlebury pairs: the PFM it writes is accurate.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "drivers/files/pfm_file.h"
#include "vision/stereo/stereo_accuracy.h"

namespace deepnav {
namespace {

std::filesystem::path sharedData() {
  const char* env = std::getenv("DEEPNAV_SHARED_DATA");
  return env ? std::filesystem::path(env) : std::filesystem::path(DEEPNAV_SOURCE_DIR) / "../shared/data";
}

class StereoCli : public ::testing::TestWithParam<const char*> {};

TEST_P(StereoCli, ElasPfmMeetsTheD1Target) {
  const auto dir = sharedData() / "stereo" / GetParam();
  if (!std::filesystem::exists(dir / "imL.png")) GTEST_SKIP() << "no " << dir;
  double scale = 0;
  int range = 0;
  std::ifstream(dir / "info.txt") >> scale >> range;
  ASSERT_GT(scale, 0.0);
  const std::string out = ::testing::TempDir() + std::string(GetParam()) + ".pfm";
  const std::string cmd = std::string(DEEPNAV_BIN_DIR) + "/deepnav stereo " + (dir / "imL.png").string() + " " +
                          (dir / "imR.png").string() + " --method elas --max-disp " + std::to_string(range) +
                          " --out " + out + " > /dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  cv::Mat estimate;
  std::string error;
  ASSERT_TRUE(readPfm(out, &estimate, &error)) << error;
  cv::Mat valid = estimate.clone();
  valid.setTo(-1.0f, estimate == std::numeric_limits<float>::infinity());  // PFM invalid -> our invalid
  cv::Mat truth;
  cv::imread((dir / "groundtruth.png").string(), cv::IMREAD_GRAYSCALE).convertTo(truth, CV_32F, 1.0 / scale);
  const cv::Mat mask = cv::imread((dir / "nonocc.png").string(), cv::IMREAD_GRAYSCALE);
  const StereoAccuracy a = evaluateDisparity(valid, truth, mask);
  std::printf("%s: D1 %.2f %%, >1px %.2f %%, coverage %.1f %%\n", GetParam(), 100 * a.d1, 100 * a.bad1,
              100 * a.coverage);
  EXPECT_LE(a.d1, 0.02);
}

INSTANTIATE_TEST_SUITE_P(Middlebury, StereoCli, ::testing::Values("middlebury-tsukuba", "middlebury-venus"));

}  // namespace
}  // namespace deepnav
