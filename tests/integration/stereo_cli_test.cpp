// `deepnav stereo` as a user runs it, on the real Middlebury pairs: the PFM it writes is accurate.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <tuple>
#include <utility>

#include <sys/wait.h>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "drivers/files/pfm_file.h"
#include "vision/stereo/stereo_accuracy.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

std::filesystem::path sharedData() { return deepnav::testing::sharedDataDir(); }

class StereoCli : public ::testing::TestWithParam<const char*> {};

TEST_P(StereoCli, ElasPfmMeetsTheD1Target) {
  const auto dir = sharedData() / "stereo" / GetParam();
  if (!std::filesystem::exists(dir / "imL.png")) GTEST_SKIP() << "no " << dir;
  double scale = 0;
  int range = 0;
  std::ifstream(dir / "info.txt") >> scale >> range;
  ASSERT_GT(scale, 0.0);
  const std::string out = ::testing::TempDir() + std::string(GetParam()) + ".pfm";
  const std::string cmd = deepnav::testing::binDir() + "/deepnav stereo " + (dir / "imL.png").string() + " " +
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

// `deepnav stereo ARGS` with stderr captured: {exit code (-1: killed by a signal), stderr}.
std::pair<int, std::string> runStereo(const std::string& args) {
  const std::string err = ::testing::TempDir() + "stereo_cli_stderr.txt";
  const std::string cmd = deepnav::testing::binDir() + "/deepnav stereo " + args + " > /dev/null 2> " + err;
  const int status = std::system(cmd.c_str());
  std::ifstream in(err);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text};
}

// A random grey pair of w x h written as PNG; returns "LEFT RIGHT".
std::string randomPair(int w, int h) {
  const std::string base = ::testing::TempDir() + "stereo_cli_" + std::to_string(w) + "x" + std::to_string(h);
  cv::Mat left(h, w, CV_8UC1), right(h, w, CV_8UC1);
  cv::randu(left, 0, 255);
  cv::randu(right, 0, 255);
  EXPECT_TRUE(cv::imwrite(base + "_l.png", left));
  EXPECT_TRUE(cv::imwrite(base + "_r.png", right));
  return base + "_l.png " + base + "_r.png";
}

// Issue 21: SGBM aborted (SIGABRT, uncaught cv::Exception in buffer_area.cpp) when the range rounded up to
// 16 reached the width: any 16x16 image, or 128 px wide at 128. Now refused with the largest range that fits.
TEST(StereoCliArguments, AnSgbmRangeReachingTheImageWidthIsRefusedNotAborted) {
  const std::string out = " --out " + ::testing::TempDir() + "stereo_cli_range.pfm";
  const std::string small = randomPair(16, 16);
  for (const char* method : {"sgbm", "sgbm-wls"}) {
    const auto [code, text] = runStereo(small + " --method " + method + out);
    EXPECT_EQ(code, 2) << method << ": " << text;
    EXPECT_NE(text.find("reaches the image width of 16 px"), std::string::npos) << text;
  }
  const std::string wide = randomPair(128, 64);
  auto [code, text] = runStereo(wide + " --method sgbm --max-disp 128" + out);
  EXPECT_EQ(code, 2) << text;
  EXPECT_NE(text.find("admits at most --max-disp 112"), std::string::npos) << text;
  std::tie(code, text) = runStereo(wide + " --method sgbm --max-disp 112" + out);
  EXPECT_EQ(code, 0) << text;
  std::tie(code, text) = runStereo(wide + " --method elas --max-disp 128" + out);
  EXPECT_EQ(code, 2) << text;
}

// Issue 21: ELAS on an 8000x8000 pair took 6.6 GB. A pair above --max-pixels is refused before matching.
TEST(StereoCliArguments, APairLargerThanMaxPixelsIsRefusedBeforeMatching) {
  const std::string out = " --out " + ::testing::TempDir() + "stereo_cli_pixels.pfm";
  const std::string pair = randomPair(400, 300);
  auto [code, text] = runStereo(pair + " --method elas --max-pixels 100000" + out);
  EXPECT_EQ(code, 2) << text;
  EXPECT_NE(text.find("400x300 (120000 pixels) is larger than --max-pixels 100000"), std::string::npos) << text;
  std::tie(code, text) = runStereo(pair + " --method elas --max-pixels 120000" + out);
  EXPECT_EQ(code, 0) << text;
}

// `deepnav stereo ARGS` with stdout captured: {exit code, stdout}.
std::pair<int, std::string> runStereoOut(const std::string& args) {
  const std::string out = ::testing::TempDir() + "stereo_cli_stdout.txt";
  const std::string cmd = deepnav::testing::binDir() + "/deepnav stereo " + args + " > " + out + " 2>&1";
  const int status = std::system(cmd.c_str());
  std::ifstream in(out);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text};
}

cv::Mat readMap(const std::string& path) {
  cv::Mat map;
  std::string error;
  EXPECT_TRUE(readPfm(path, &map, &error)) << error;
  return map;
}

// Issue 20: --repeat N matches the pair N times and prints min <= median <= max of the compute time; the map
// it writes is the one a single call writes (the estimator's buffers are reused, not its results).
TEST(StereoCliArguments, RepeatPrintsMinAndMedianComputeTimeAndTheSameMap) {
  const std::string pair = randomPair(200, 120);
  const std::string once = ::testing::TempDir() + "stereo_cli_once.pfm";
  const std::string repeated = ::testing::TempDir() + "stereo_cli_repeated.pfm";
  for (const char* preset : {"dense", "robotics"}) {
    const std::string base = pair + " --method elas --max-disp 32 --preset " + preset;
    auto [code, text] = runStereoOut(base + " --out " + once);
    ASSERT_EQ(code, 0) << text;
    EXPECT_EQ(text.find("compute time"), std::string::npos) << text;  // no timing unless asked
    std::tie(code, text) = runStereoOut(base + " --repeat 5 --out " + repeated);
    ASSERT_EQ(code, 0) << text;
    const std::string head = std::string("elas ") + preset + " compute time over 5 calls (image I/O excluded): min ";
    const auto at = text.find(head);
    ASSERT_NE(at, std::string::npos) << text;
    double min_ms = -1, median_ms = -1, max_ms = -1;
    ASSERT_EQ(std::sscanf(text.c_str() + at + head.size(), "%lf ms, median %lf ms, max %lf ms", &min_ms, &median_ms,
                          &max_ms),
              3)
        << text;
    EXPECT_GT(min_ms, 0.0);
    EXPECT_LE(min_ms, median_ms);
    EXPECT_LE(median_ms, max_ms);
    const cv::Mat a = readMap(once), b = readMap(repeated);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(cv::norm(a != b, cv::NORM_L1), 0.0) << preset;  // +inf == +inf for invalid pixels
  }
  const auto [code, text] = runStereoOut(pair + " --method sgbm --max-disp 32 --repeat 2 --out " + once);
  EXPECT_EQ(code, 0) << text;
  EXPECT_NE(text.find("sgbm compute time over 2 calls"), std::string::npos) << text;
  EXPECT_NE(runStereoOut(pair + " --repeat 0 --out " + once).first, 0);
}

}  // namespace
}  // namespace deepnav
