#include "vision/calib/stereo_checkerboard_calibration.h"

#include "vision/calib/checkerboard_view.h"

namespace deepnav {

bool calibrateStereoCheckerboard(const std::vector<CalibrationPairInput>& pairs, const CheckerboardTarget& target,
                                 StereoCalibrationResult* result, std::string* error) {
  *result = StereoCalibrationResult{};
  std::string target_error;
  if (!validateCheckerboardTarget(target, &target_error)) {
    if (error) *error = "target: " + target_error;
    return false;
  }
  // The whole board in each camera: a partial view has no numbering.
  const ViewScreening screening{target.inner_cols * target.inner_rows, target.max_edge_width_px, target.duplicate_px,
                                target.fix_k3, true};
  return calibrateStereoViews(
      pairs, [&](const cv::Mat& grey) { return detectCheckerboardView(grey, target); }, checkerboardCorners(target),
      screening, [&](const TargetView& l, TargetView* r) { return checkerboardAlignPair(l, r, target); }, result,
      error);
}

}  // namespace deepnav
