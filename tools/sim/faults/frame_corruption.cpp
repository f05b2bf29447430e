#include "tools/sim/faults/frame_corruption.h"

#include <opencv2/core.hpp>

#include "tools/sim/normal_rng.h"

namespace deepnav::sim {

void corruptStereoFrame(std::uint64_t seed, std::uint32_t frame_index, StereoFrame* frame) {
  cv::RNG rng(NormalRng::subSeed(seed, 0xC0FFEE00u + frame_index));
  rng.fill(frame->left, cv::RNG::UNIFORM, 0, 256);
  rng.fill(frame->right, cv::RNG::UNIFORM, 0, 256);
}

}  // namespace deepnav::sim
