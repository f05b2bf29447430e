#pragma once
#include "nav/ekf/filter_state.h"

namespace deepnav {

struct EkfConfig;

// An IMU gap longer than EkfConfig::imu_max_gap_us (the IMU stopped, or its clock jumped ahead) is not
// integrated with the one sample that ends it: first-order propagation over seconds is meaningless and
// its covariance breaks the filter (it diverged by 20 m in 5 s after a 5 s outage before this). Instead
// the state coasts over the gap dt on its velocity, as the published solution did during the outage:
//   p += v dt;  P = Phi P Phi^T + Q,  Phi = I with dp/dv = I dt,
//   Q per axis, white acceleration of density q = coast_accel_noise_mps2_rthz^2 (nearly-constant-velocity
//   model):  [q dt^3/3, q dt^2/2;  q dt^2/2, q dt]
// and the attitude variances are raised to at least the initial ones (the vehicle may have turned).
// Clones are dropped (their correlations with the coasted state are unknown).
void bridgeImuGap(double dt_s, const EkfConfig& config, FilterState* s);

}  // namespace deepnav
