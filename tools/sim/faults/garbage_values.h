#pragma once
#include "tools/sim/normal_rng.h"
#include "tools/sim/sim_event.h"

namespace deepnav::sim {

// Ranges of the `garbage` fault: what a sensor that outputs nonsense (a wrong baud rate decoded, a
// firmware fault) can plausibly produce while still passing its own frame checks.
struct GarbageRanges {
  static constexpr double kGyro_radps = 5.0;       // +- per axis
  static constexpr double kAccel_mps2 = 50.0;      // +- per axis
  static constexpr double kDvl_mps = 5.0;          // +- per axis
  static constexpr double kAttitude_rad = 3.14159; // +- roll and pitch
  static constexpr double kDepthMax_m = 1000.0;    // [0, max]
};

// Replaces every measured component of a sensor sample by a uniform random value over its range (heading
// over [0, 2 pi)); stamps, validity flags and stated sigmas are kept, as a sensor unaware of its fault
// would report them. A camera tick is flagged `corrupted` (its images become noise when rendered).
void fillGarbage(NormalRng& rng, SimSample* sample);

}  // namespace deepnav::sim
