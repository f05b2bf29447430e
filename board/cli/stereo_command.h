#pragma once
#include <string>

namespace deepnav {

struct StereoCommandOptions {
  std::string left_path;
  std::string right_path;
  std::string method = "elas";  // elas | sgbm | sgbm-wls
  int max_disparity_px = 64;
  std::string out_path;         // .pfm
};

// `deepnav stereo`: dense disparity of a rectified pair, written as PFM. Returns the exit code.
int runStereoCommand(const StereoCommandOptions& options);

}  // namespace deepnav
