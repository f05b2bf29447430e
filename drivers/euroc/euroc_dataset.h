#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "drivers/euroc/euroc_sensor.h"
#include "drivers/euroc/euroc_streams.h"

namespace deepnav {

// A stereo pair: a cam0 and a cam1 image with the same timestamp (the EuRoC cameras are triggered together
// and stamped identically; an image of one camera with no twin is left out and counted).
struct EurocStereoPair {
  std::int64_t t_ns = 0;
  std::string left_path;   // cam0
  std::string right_path;  // cam1
};

// Everything of an EuRoC/ASL folder that deepnav imports: mav0/cam0, mav0/cam1, mav0/imu0 and the optional
// mav0/state_groundtruth_estimate0 (used when it holds a data.csv).
struct EurocDataset {
  std::string mav_dir;  // the mav0 folder
  EurocCamera cam0;
  EurocCamera cam1;
  EurocImuInfo imu;
  std::vector<EurocStereoPair> pairs;
  int cam0_unpaired = 0;
  int cam1_unpaired = 0;
  int cam0_missing = 0;  // listed in data.csv but no file (EurocReadOptions::skip_missing_images)
  int cam1_missing = 0;
  std::vector<EurocImuRow> imu_rows;
  std::vector<EurocTruthRow> truth;  // empty when the folder has no ground truth
};

struct EurocReadOptions {
  bool skip_missing_images = false;  // leave out (and count) listed images whose file is missing
  double duration_s = 0.0;           // > 0: only what lies within this long after the folder's first sample
};

// Reads `dir` (the dataset folder holding mav0/, or mav0 itself). Checks that both cameras share a resolution
// and that there is at least one pair and one IMU sample; errors name the file (and line or key).
bool readEurocDataset(const std::string& dir, const EurocReadOptions& options, EurocDataset* dataset,
                      std::string* error);

}  // namespace deepnav
