#pragma once
#include "nav/ekf/error_state.h"
#include "nav/ekf/filter_state.h"

namespace deepnav {

struct EkfConfig;

// IMU biases as first-order Gauss-Markov processes (the bench's model, tools/sim/sensors/imu_gauss_markov.h),
// exactly discretised over dt for each of gyro and accelerometer whose tau > 0:
//   b(k+1) = exp(-dt/tau) b(k) + w,  Var(w) = sigma^2 (1 - exp(-2 dt/tau))  (~ 2 sigma^2 dt / tau),
// so Phi's bias block becomes exp(-dt/tau) I (~ (1 - dt/tau) I), Q's gets the GM driving noise on top of
// the random walk already there, and the nominal bias decays towards zero. tau = 0: untouched.
void applyBiasGaussMarkov(const EkfConfig& config, double dt_s, CoreMatrix* Phi, CoreMatrix* Q, NominalState* x);

// True when either bias is modelled as Gauss-Markov.
bool biasGaussMarkovEnabled(const EkfConfig& config);

}  // namespace deepnav
