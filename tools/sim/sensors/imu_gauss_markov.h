#pragma once
#include <Eigen/Core>

#include "tools/sim/normal_rng.h"

namespace deepnav::sim {

// Allan deviation of a first-order Gauss-Markov process of steady-state sigma s and correlation time T,
// averaged over tau (x = tau / T), from its autocorrelation s^2 exp(-|t|/T):
//   AVAR(tau) = Var(mean over tau) - Cov(consecutive means)
//             = (s^2 / x^2) [2x - 3 + 4 exp(-x) - exp(-2x)].
// Its maximum, 0.6174 s, is at x = 1.8926. A data sheet's "bias instability" is the floor of the
// measured Allan curve (e.g. Sensonor's STIM FAQ: "lowest point of the curve", IEEE 952), so the model
// takes sigma_GM = bias_instability / 0.6174 and the bias drifts at that floor around tau = 1.89 T.
double gaussMarkovAllanDeviation(double sigma, double correlation_time_s, double tau_s);
inline constexpr double kGaussMarkovAdevPeakOverSigma = 0.6173643;  // max over x of the bracket's sqrt
inline constexpr double kGaussMarkovAdevPeakTauOverT = 1.8926;

// Three independent first-order Gauss-Markov processes (one per axis), exactly discretised at step dt:
//   b(k+1) = exp(-dt/T) b(k) + sigma sqrt(1 - exp(-2 dt/T)) n(k),   n ~ N(0, I),
// started from the stationary distribution N(0, sigma^2 I), so the process is stationary from sample 0.
class GaussMarkov3 {
 public:
  void init(double sigma, double correlation_time_s, double dt_s, NormalRng* rng);
  void step(NormalRng* rng);
  const Eigen::Vector3d& value() const { return value_; }

 private:
  Eigen::Vector3d value_ = Eigen::Vector3d::Zero();
  double decay_ = 0.0;
  double drive_sigma_ = 0.0;
};

}  // namespace deepnav::sim
