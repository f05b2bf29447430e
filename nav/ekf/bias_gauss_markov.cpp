#include "nav/ekf/bias_gauss_markov.h"

#include <cmath>

#include "nav/ekf/ekf_config.h"

namespace deepnav {
namespace {

void applyOne(int offset, double tau_s, double sigma, double dt_s, CoreMatrix* Phi, CoreMatrix* Q,
              Eigen::Vector3d* b) {
  if (tau_s <= 0.0) return;
  const double decay = std::exp(-dt_s / tau_s);
  // Every column of Phi's bias rows is identity there (biases do not depend on other states).
  Phi->block<3, 3>(offset, offset) = Eigen::Matrix3d::Identity() * decay;
  Q->block<3, 3>(offset, offset).diagonal().array() += sigma * sigma * (1.0 - decay * decay);
  *b *= decay;
}

}  // namespace

bool biasGaussMarkovEnabled(const EkfConfig& c) { return c.gyro_bias_gm_tau_s > 0.0 || c.accel_bias_gm_tau_s > 0.0; }

void applyBiasGaussMarkov(const EkfConfig& c, double dt_s, CoreMatrix* Phi, CoreMatrix* Q, NominalState* x) {
  applyOne(es::kBg, c.gyro_bias_gm_tau_s, c.gyro_bias_gm_sigma_radps, dt_s, Phi, Q, &x->b_gyro_radps);
  applyOne(es::kBa, c.accel_bias_gm_tau_s, c.accel_bias_gm_sigma_mps2, dt_s, Phi, Q, &x->b_accel_mps2);
}

}  // namespace deepnav
