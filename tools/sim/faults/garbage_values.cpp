#include "tools/sim/faults/garbage_values.h"

#include <numbers>

namespace deepnav::sim {

namespace {
double symmetric(NormalRng& rng, double range) { return (2.0 * rng.uniform() - 1.0) * range; }
}  // namespace

void fillGarbage(NormalRng& rng, SimSample* sample) {
  using G = GarbageRanges;
  if (auto* imu = std::get_if<ImuSample>(sample)) {
    for (int i = 0; i < 3; ++i) imu->w_imu_radps[i] = symmetric(rng, G::kGyro_radps);
    for (int i = 0; i < 3; ++i) imu->f_imu_mps2[i] = symmetric(rng, G::kAccel_mps2);
  } else if (auto* dvl = std::get_if<DvlSample>(sample)) {
    for (int i = 0; i < 3; ++i) dvl->v_dvl_mps[i] = symmetric(rng, G::kDvl_mps);
  } else if (auto* heading = std::get_if<HeadingSample>(sample)) {
    heading->heading_rad = rng.uniform() * 2.0 * std::numbers::pi;
    if (heading->heading_rad >= 2.0 * std::numbers::pi) heading->heading_rad = 0.0;
  } else if (auto* att = std::get_if<AttitudeSample>(sample)) {
    att->roll_rad = symmetric(rng, G::kAttitude_rad);
    att->pitch_rad = symmetric(rng, G::kAttitude_rad);
  } else if (auto* depth = std::get_if<DepthSample>(sample)) {
    depth->depth_m = rng.uniform() * G::kDepthMax_m;
  } else if (auto* tick = std::get_if<CameraTick>(sample)) {
    tick->corrupted = true;
  }
}

}  // namespace deepnav::sim
