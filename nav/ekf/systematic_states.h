#pragma once
#include "nav/ekf/filter_state.h"
#include "nav/types/estimator_states.h"

namespace deepnav {

struct EkfConfig;

// Systematic sensor errors estimated as random constants once markers or VO constrain the pose
// (issue 18). Each group is in the state only when the board gives it a prior sigma > 0:
//   DVL scale factor s (1):        v_meas = (1 + s) Exp(-alpha) R_dvl_robot v_dvl_point   (dvl_updater.h)
//   DVL misalignment alpha (3):    R_robot_dvl_true = R_robot_dvl Exp(alpha); roll and pitch show
//                                  through the depth rate while moving, yaw through the track (markers)
//   DVL velocity bias b (3):       v_meas = (1 + s) Exp(-alpha) R_dvl_robot v_dvl_point + b, DVL axes;
//                                  shows as a drift while the robot holds station against the markers
//   compass bias b (1):            heading = psi + b + B sin psi + C cos psi + D sin 2psi + E cos 2psi
//   compass deviation B..E (4):    (heading_updater.h; the deviation's constant A is part of b)
// They sit after the clones in the error state (error_state.h) with no process noise.

// Offsets of the enabled groups inside the systematic block, from the config's prior sigmas.
SystematicLayout systematicLayout(const EkfConfig& config);

// Prior covariance of the systematic block (diagonal, the config's sigmas), uncorrelated with the rest.
void resetSystematicCovariance(const EkfConfig& config, FilterState* s);

// Moves the systematic block's rows and columns to start at new_offset (before the clone count changes):
// its own block and its cross-covariance with the first min(old, new) states are kept.
void relocateSystematic(int new_offset, FilterState* s);

// The systematic estimates and their 1-sigmas (both 0 for a state not estimated), for the recording and
// the replay's summary.
struct SystematicEstimates {
  SystematicLayout layout;
  SystematicErrors value;
  SystematicErrors sigma;
};
SystematicEstimates systematicEstimates(const FilterState& s);

// The same with the IMU biases, as the loop records them at t_us.
EstimatorStates estimatorStates(const FilterState& s, TimeUs t_us);

// Lower bound of the systematic variances (keeps P positive definite with no process noise).
void boundSystematicVariances(FilterState* s);

}  // namespace deepnav
