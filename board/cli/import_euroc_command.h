#pragma once
#include <string>

namespace deepnav {

struct ImportEurocOptions {
  std::string dir;               // the EuRoC/ASL folder (holding mav0/, or mav0 itself)
  std::string out_path;          // the deepnav recording to write (.mcap)
  std::string calibration_out;   // optional: the stereo calibration as OpenCV YAML (camera.calibration_file)
  std::string board_path;        // optional: a board stored in the recording (with its calibration)
  bool skip_missing_images = false;  // leave out listed images whose file is missing (a folder cut short)
  double duration_s = 0.0;       // > 0: import only the first duration_s seconds
  bool quiet = false;            // no summary on stdout
};

// `deepnav import euroc DIR --out rec.mcap`: the folder's stereo pairs (cam0 left, cam1 right, paired by
// identical timestamps), its IMU samples rotated into the FLU robot frame (drivers/euroc/euroc_frames.h)
// and its ground truth when present, merged in time order into a deepnav recording; the stereo
// calibration from the sensor.yaml files goes into the recording's metadata (and --calibration-out).
// Prints the board's mounting keys for the rig. Returns the exit code (0, or 1 with a message naming the
// file and line or key).
int runImportEurocCommand(const ImportEurocOptions& options);

}  // namespace deepnav
