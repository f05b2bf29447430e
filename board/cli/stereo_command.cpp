#include "board/cli/stereo_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "drivers/files/pfm_file.h"
#include "vision/stereo/elas_disparity.h"
#include "vision/stereo/sgbm_disparity.h"

namespace deepnav {
namespace {

std::unique_ptr<DisparityEstimator> makeEstimator(const StereoCommandOptions& o, int w, int h) {
  if (o.method == "elas") {
    auto elas = std::make_unique<ElasDisparity>();
    ElasParams p = o.elas_preset == "robotics" ? ElasParams::robotics() : ElasParams::dense();
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

// Matches the pair max(1, repeat) times on the same estimator (its buffers warm after the first call);
// *call_ms: the wall time of each compute() call.
bool computeTimed(const StereoCommandOptions& o, const cv::Mat& left, const cv::Mat& right,
                  DisparityEstimator* estimator, cv::Mat* disparity, std::vector<double>* call_ms) {
  const int calls = std::max(1, o.repeat);
  call_ms->reserve(static_cast<std::size_t>(calls));
  for (int i = 0; i < calls; ++i) {
    const auto start = std::chrono::steady_clock::now();
    const bool ok = estimator->compute(left, right, disparity);
    const auto stop = std::chrono::steady_clock::now();
    if (!ok) return false;
    call_ms->push_back(std::chrono::duration<double, std::milli>(stop - start).count());
  }
  return true;
}

// Median: the middle call, or the mean of the two middle ones for an even count.
void printTimes(const StereoCommandOptions& o, std::vector<double>* call_ms) {
  std::sort(call_ms->begin(), call_ms->end());
  const std::size_t n = call_ms->size();
  const double median = n % 2 == 1 ? (*call_ms)[n / 2] : 0.5 * ((*call_ms)[n / 2 - 1] + (*call_ms)[n / 2]);
  const std::string what = o.method == "elas" ? "elas " + o.elas_preset : o.method;
  std::printf("%s compute time over %zu calls (image I/O excluded): min %.2f ms, median %.2f ms, max %.2f ms\n",
              what.c_str(), n, call_ms->front(), median, call_ms->back());
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
  std::vector<double> call_ms;
  if (!estimator || !computeTimed(o, left, right, estimator.get(), &disparity, &call_ms)) {
    std::fprintf(stderr, "deepnav stereo: %s failed on this pair (max disparity %d)\n", o.method.c_str(),
                 o.max_disparity_px);
    return 1;
  }
  if (o.repeat > 0) printTimes(o, &call_ms);
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
