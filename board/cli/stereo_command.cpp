#include "board/cli/stereo_command.h"

#include <cstdio>
#include <exception>
#include <memory>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "drivers/files/pfm_file.h"
#include "vision/stereo/elas_disparity.h"
#include "vision/stereo/sgbm_disparity.h"

namespace deepnav {
namespace {

std::unique_ptr<DisparityEstimator> makeEstimator(const StereoCommandOptions& o, int w, int h) {
  if (o.method == "elas") {
    auto elas = std::make_unique<ElasDisparity>();
    ElasParams p = ElasParams::dense();
    p.num_disparities = o.max_disparity_px;
    if (!elas->init(p, w, h)) return nullptr;
    return elas;
  }
  auto sgbm = std::make_unique<SgbmDisparity>();
  SgbmParams p;
  p.num_disparities = o.max_disparity_px;
  p.wls = o.method == "sgbm-wls";
  if (!sgbm->init(p, w, h)) return nullptr;
  return sgbm;
}

// The pair's size against --max-pixels and --max-disp, before any matcher buffer exists. Empty: fits.
std::string checkPairSize(const StereoCommandOptions& o, const cv::Mat& left) {
  const long long pixels = static_cast<long long>(left.cols) * left.rows;
  if (pixels > o.max_pixels) {
    return o.left_path + ": " + std::to_string(left.cols) + "x" + std::to_string(left.rows) + " (" +
           std::to_string(pixels) + " pixels) is larger than --max-pixels " + std::to_string(o.max_pixels);
  }
  const bool sgbm = o.method != "elas";
  // SGBM searches the range rounded up to 16 and OpenCV throws when that reaches the width; a range that
  // reaches the width holds disparities no pixel can have (u - d < 0 for every column), for ELAS too.
  const int searched = sgbm ? (o.max_disparity_px + 15) / 16 * 16 : o.max_disparity_px;
  if (searched < left.cols) return "";
  const int largest = sgbm ? sgbmLargestDisparities(left.cols) : left.cols - 1;
  std::string why = "--max-disp " + std::to_string(o.max_disparity_px) +
                    (sgbm ? " (searched as " + std::to_string(searched) + ", a multiple of 16)" : std::string()) +
                    " reaches the image width of " + std::to_string(left.cols) + " px (" + o.left_path + "); " +
                    o.method;
  return why + (largest >= 1 ? " admits at most --max-disp " + std::to_string(largest) + " on it"
                             : " needs an image wider than 16 px");
}

int runStereo(const StereoCommandOptions& o) {
  const cv::Mat left = cv::imread(o.left_path, cv::IMREAD_COLOR);
  const cv::Mat right = cv::imread(o.right_path, cv::IMREAD_COLOR);
  if (left.empty() || right.empty()) {
    std::fprintf(stderr, "deepnav stereo: cannot read %s\n", (left.empty() ? o.left_path : o.right_path).c_str());
    return 1;
  }
  if (left.size() != right.size()) {
    std::fprintf(stderr, "deepnav stereo: %s and %s differ in size\n", o.left_path.c_str(), o.right_path.c_str());
    return 1;
  }
  if (const std::string why = checkPairSize(o, left); !why.empty()) {
    std::fprintf(stderr, "deepnav stereo: %s\n", why.c_str());
    return 2;
  }
  const auto estimator = makeEstimator(o, left.cols, left.rows);
  cv::Mat disparity;
  if (!estimator || !estimator->compute(left, right, &disparity)) {
    std::fprintf(stderr, "deepnav stereo: %s failed on this pair (max disparity %d)\n", o.method.c_str(),
                 o.max_disparity_px);
    return 1;
  }
  std::string error;
  if (!writePfm(o.out_path, disparity, &error)) {
    std::fprintf(stderr, "deepnav stereo: %s\n", error.c_str());
    return 1;
  }
  const int valid = cv::countNonZero(disparity >= 0.0f);
  std::printf("%s: %dx%d, %.1f %% of pixels with a disparity\n", o.out_path.c_str(), disparity.cols, disparity.rows,
              100.0 * valid / static_cast<double>(disparity.total()));
  return 0;
}

}  // namespace

// A library exception (OpenCV asserting on an argument, out of memory) ends the command with its message
// instead of an abort.
int runStereoCommand(const StereoCommandOptions& o) {
  try {
    return runStereo(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "deepnav stereo: %s on %s and %s failed: %s\n", o.method.c_str(), o.left_path.c_str(),
                 o.right_path.c_str(), e.what());
    return 1;
  }
}

}  // namespace deepnav
