#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "vision/calib/charuco_target.h"
#include "vision/calib/stereo_calibration.h"
#include "vision/calib/stereo_charuco_calibration.h"

namespace deepnav::sim {

// Pose of the board in the left camera's optical frame: p_in_left = R_left_board * p_in_board + t.
struct BoardPose {
  cv::Matx33d R_left_board = cv::Matx33d::eye();
  cv::Vec3d p_board_in_left_m{0.0, 0.0, 1.0};
};

// Renders a ChArUco board as a calibrated stereo rig (distortion included) sees it: for every pixel, the
// undistorted ray meets the board plane (a homography), where the board texture is sampled. The
// texture is drawn from the board's own object points (markers by cv::aruco::drawMarker), so the
// rendered corners sit exactly where OpenCV's board says they are.
class CharucoImageRenderer {
 public:
  bool init(const CharucoTarget& target, const StereoCalibration& rig, std::string* error);

  // Grey images with a little lens blur and sensor noise (seeded); blur_sigma_px adds defocus.
  void renderPair(const BoardPose& pose, std::uint64_t seed, double blur_sigma_px, cv::Mat* left,
                  cv::Mat* right) const;

  const StereoCalibration& rig() const { return rig_; }

 private:
  void renderView(const cv::Matx33d& R_cam_board, const cv::Vec3d& t_cam_board, const cv::Mat& rays,
                  std::uint64_t seed, double blur_sigma_px, cv::Mat* out) const;

  StereoCalibration rig_;
  cv::Mat texture_;          // CV_32F, grey 0..255, board coordinates x_m * scale + margin
  double texels_per_m_ = 0.0;
  double margin_texels_ = 0.0;
  cv::Mat left_rays_;        // CV_64FC2: undistorted normalised coordinates of every pixel
  cv::Mat right_rays_;
};

// The rig the calibration tests recover: 688 x 516, an in-air machine-vision lens with barrel
// distortion, a 0.3 m baseline with a slight toe-in.
StereoCalibration simulatedCalibrationRig();

// A spread of board poses seen by both cameras of that rig (0.8-1.6 m, tilted up to ~35 deg).
std::vector<BoardPose> calibrationPoses();

// A full set of pairs: the good poses, then three that must be rejected: "blurred" (defocus),
// "duplicate" (the first pose again) and "few_corners" (the board mostly out of view).
std::vector<CalibrationPairInput> makeCalibrationPairs(const CharucoImageRenderer& renderer, std::uint64_t seed);

}  // namespace deepnav::sim
