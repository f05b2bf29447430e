#include "vision/calib/stereo_charuco_calibration.h"

namespace deepnav {

bool calibrateStereoCharuco(const std::vector<CalibrationPairInput>& pairs, const CharucoTarget& target,
                            StereoCharucoResult* result, std::string* error) {
  *result = StereoCharucoResult{};
  std::string target_error;
  if (!validateCharucoTarget(target, &target_error)) {
    if (error) *error = "target: " + target_error;
    return false;
  }
  const auto board = makeCharucoBoard(target);
  const ViewScreening screening{target.min_corners, target.max_edge_width_px, target.duplicate_px, target.fix_k3};
  return calibrateStereoViews(
      pairs, [&](const cv::Mat& grey) { return detectCharucoView(grey, board); }, board->chessboardCorners, screening,
      nullptr, result, error);
}

}  // namespace deepnav
