#pragma once
#include <string>
#include <vector>

namespace deepnav {

struct ImportCalibrationOptions {
  std::string format;               // kalibr | opencv | camera-info
  std::vector<std::string> inputs;  // kalibr: camchain.yaml; opencv: 1-2 files; camera-info: left.yaml right.yaml
  std::string out_path = "calibration.yaml";
  std::string image_size;  // opencv: "WIDTHxHEIGHT" when the files hold none
};

// `deepnav import calibration`: reads a Kalibr, OpenCV stereo_calib or camera_info pair calibration, checks
// that deepnav can rectify with it, prints what was imported (focal lengths, baseline in m, resolution)
// and writes deepnav's calibration file (board/config/stereo_calibration_file.h). Exit code 0 ok,
// 2 bad input (one message naming the file and key).
int runImportCalibrationCommand(const ImportCalibrationOptions& options);

}  // namespace deepnav
