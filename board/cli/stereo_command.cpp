#include "board/cli/stereo_command.h"

#include <cstdio>
#include <memory>

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

}  // namespace

int runStereoCommand(const StereoCommandOptions& o) {
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

}  // namespace deepnav
