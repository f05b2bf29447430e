#pragma once
#include "nav/ekf/filter_state.h"
#include "nav/ekf/measurement_update.h"
#include "nav/types/heading_sample.h"

namespace deepnav {

struct EkfConfig;

bool isValidHeading(const HeadingSample& m);

// ENU yaw measured by a compass (heading clockwise from north):
//   yaw_meas = pi/2 - (heading + declination - bias)        (declination only for magnetic headings)
// Model: yaw(R) = atan2(R10, R00) (ZYX Euler). With c = R_hat e_x and R = Exp(dtheta) R_hat,
//   H_theta = [ -c0 c2, -c1 c2, c0^2 + c1^2 ] / (c0^2 + c1^2);  residual wrapped to [-pi, pi).
// With the compass bias b and deviation B..E estimated (systematic_states.h) the model is
// yaw_meas = yaw - (b + B sin psi + C cos psi + D sin 2psi + E cos 2psi), psi the magnetic heading.
// Noise: the sample's sigma (else heading_sigma_rad), raised to heading_sigma_floor_rad.
// Returns false near pitch +-90 deg, where yaw is undefined.
bool linearizeHeading(const FilterState& s, const HeadingSample& m, const EkfConfig& config, Linearization* out);

// The conversion above, exposed for the alignment and the tests.
double yawFromHeading(const HeadingSample& m, const EkfConfig& config);

}  // namespace deepnav
