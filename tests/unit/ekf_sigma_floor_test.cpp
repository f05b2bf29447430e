// The compass's sigma floor: a sample's own sigma (its repeatability) is raised to the configured floor
// (the datasheet's accuracy), never lowered, and 0 leaves it as it is.
#include <cmath>

#include <gtest/gtest.h>

#include "nav/ekf/ekf_config.h"
#include "nav/ekf/filter_state.h"
#include "nav/ekf/heading_updater.h"
#include "nav/ekf/measurement_update.h"

namespace deepnav {
namespace {

double headingSigma(double sample_sigma_rad, double floor_rad) {
  EkfConfig c;
  c.heading_sigma_floor_rad = floor_rad;
  FilterState s;
  HeadingSample m;
  m.heading_rad = 0.3;
  m.sigma_rad = sample_sigma_rad;
  Linearization l;
  EXPECT_TRUE(linearizeHeading(s, m, c, &l));
  return std::sqrt(l.R(0, 0));
}

// GIVEN a fluxgate compass's samples carrying their repeatability (0.05 deg) as sigma
// WHEN the floor is its heading accuracy (0.3 deg rms, board/sim-sea)
// THEN the filter fuses them at 0.3 deg; a noisier sample keeps its own sigma; floor 0 changes nothing.
TEST(EkfSigmaFloor, HeadingSigmaIsRaisedToTheFloorOnly) {
  const double repeatability_rad = 0.05 * M_PI / 180.0;
  const double accuracy_rad = 0.3 * M_PI / 180.0;
  EXPECT_DOUBLE_EQ(headingSigma(repeatability_rad, accuracy_rad), accuracy_rad);
  EXPECT_DOUBLE_EQ(headingSigma(0.02, accuracy_rad), 0.02);
  EXPECT_DOUBLE_EQ(headingSigma(repeatability_rad, 0.0), repeatability_rad);
}

}  // namespace
}  // namespace deepnav
