#pragma once
#include <string>

namespace deepnav {

struct StereoCommandOptions {
  std::string left_path;
  std::string right_path;
  std::string method = "elas";  // elas | sgbm | sgbm-wls
  int max_disparity_px = 64;
  std::string out_path;         // .pfm
  // Largest pair accepted, in pixels per image: refused before any matcher buffer is allocated (ELAS
  // needs about 100 bytes per pixel: an 8000x8000 pair took 6.6 GB). 10 MP takes a 4K pair (4096x2160).
  long long max_pixels = 10'000'000;
  std::string elas_preset = "dense";  // dense | robotics (ElasParams::dense() / robotics())
  // > 0: match the pair this many times and print the min and median compute time per call (image
  // decoding and the PFM excluded), to time deepnav against another matcher on the same files.
  int repeat = 0;
};

// `deepnav stereo`: dense disparity of a rectified pair, written as PFM. Returns the exit code.
int runStereoCommand(const StereoCommandOptions& options);

}  // namespace deepnav
