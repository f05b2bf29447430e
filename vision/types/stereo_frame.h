#pragma once
#include <cstdint>

#include <opencv2/core.hpp>

#include "nav/types/time.h"

namespace deepnav {

// A synchronised stereo pair. The images live in buffers preallocated by the FramePool; a frame is
// passed by pointer/index, never copied in the steady state.
struct StereoFrame {
  TimeUs t_us = 0;              // capture time: middle of the exposure, on the system clock
  std::uint32_t exposure_us = 0;
  std::uint64_t sequence = 0;   // frame counter from the cameras
  cv::Mat left;                 // CV_8UC1 (grey) or CV_8UC3 (BGR), rectified or raw per `rectified`
  cv::Mat right;
  bool rectified = false;
};

}  // namespace deepnav

namespace deepnav {

// Allocates both images of a frame (start-up only). channels is 1 (grey) or 3 (BGR).
bool allocateStereoFrame(StereoFrame& frame, int width_px, int height_px, int channels);

}  // namespace deepnav
