#pragma once
#include <string>
#include <vector>

#include "vision/calib/charuco_target.h"
#include "vision/calib/checkerboard_target.h"

namespace deepnav {

struct CalibrateCommandOptions {
  std::string target_path;            // target.yaml (vision/calib/README.md)
  std::vector<std::string> inputs;    // image files, folders of images, or .mcap recordings
  std::string out_path = "calibration.yaml";
  int every = 10;                     // recordings: use every N-th stereo pair
};

// target.yaml: `type: charuco` (the default) or `type: checkerboard`, and that target's keys.
struct CalibrationTargetFile {
  std::string type = "charuco";
  CharucoTarget charuco;            // type charuco
  CheckerboardTarget checkerboard;  // type checkerboard
};

// Reads target.yaml of either type. ChArUco as loadCharucoTarget; a checkerboard needs `inner_corners:
// [cols, rows]` and `square_m`, its screening thresholds have defaults. One message naming the file and key.
bool loadCalibrationTarget(const std::string& path, CalibrationTargetFile* target, std::string* error);

// Reads a ChArUco target.yaml. The board's geometry (squares_x, squares_y, square_m, marker_m, dictionary) must be
// given; the screening thresholds have defaults. A bad file fails with one message naming the field.
bool loadCharucoTarget(const std::string& path, CharucoTarget* target, std::string* error);

// `deepnav calibrate`: stereo calibration from ChArUco or checkerboard views; prints the per-pair report, the overall
// error and a ROS camera_info-compatible summary, writes the OpenCV YAML the board's
// camera.calibration_file points to. Returns the exit code (0 ok, 1 calibration failed, 2 bad input).
int runCalibrateCommand(const CalibrateCommandOptions& options);

}  // namespace deepnav
