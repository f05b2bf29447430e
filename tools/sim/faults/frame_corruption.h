#pragma once
#include <cstdint>

#include "vision/types/stereo_frame.h"

namespace deepnav::sim {

// The `garbage` fault on the camera stream: both images of a rendered pair are overwritten with uniform
// noise (a damaged transfer that still has the right size and format). Deterministic in (seed, index).
void corruptStereoFrame(std::uint64_t seed, std::uint32_t frame_index, StereoFrame* frame);

}  // namespace deepnav::sim
