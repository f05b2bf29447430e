#pragma once
// DVL model set-ups shared by the simulator's DVL tests (header-only, test code).
#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "tools/sim/sensors/dvl_model.h"

namespace deepnav::sim::test {

// The DVL model without its per-axis and range noise, mounted at the robot origin: the terms a test turns
// on are the only ones left.
inline DvlConfig noiselessDvlConfig() {
  DvlConfig c;
  c.noise_fraction_of_speed = 0.0;
  c.noise_floor_mps = 0.0;
  c.range_noise_m = 0.0;
  c.p_dvl_in_robot_m = {0.0, 0.0, 0.0};
  return c;
}

// A DVL model over a flat seabed at z = 0 of the odometry frame; a bad config fails the test.
inline DvlModel makeDvl(const DvlConfig& c, std::uint64_t seed) {
  DvlModel dvl;
  std::string error;
  EXPECT_TRUE(dvl.init(c, 0.0, seed, &error)) << error;
  return dvl;
}

}  // namespace deepnav::sim::test
