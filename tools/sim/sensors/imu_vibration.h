#pragma once
#include <array>

#include <Eigen/Core>

#include "nav/types/time.h"
#include "tools/sim/normal_rng.h"

namespace deepnav::sim {

// Thruster-induced vibration seen by one sensor triad (accelerometers or gyros), in the IMU frame.
// Per axis: three sinusoids at the thrusters' blade-pass frequencies plus white broadband noise,
//   v(t_k) = sum_j A sin(2 pi f_j t_k + phi_ij) + n_k,
// with the power split 3/4 tonal (equal per tone) and 1/4 broadband, so the per-axis rms is `rms`:
// A = rms sqrt(2 * 0.75 / 3) (a sinusoid of amplitude A has rms A / sqrt 2), sigma_n = rms sqrt(0.25).
// The tones are evaluated at the sample instants only, with no anti-aliasing filter: a tone above the
// Nyquist frequency folds to |f - round(f / r) r| as in a sampled sensor without one. Phases are drawn
// once (uniform in [0, 2 pi)) at init.
class ImuVibration {
 public:
  static constexpr int kTones = 3;
  static constexpr double kTonalPowerFraction = 0.75;

  void init(double rms, const std::array<double, kTones>& frequencies_hz, NormalRng* rng);
  Eigen::Vector3d sample(TimeUs t_us, NormalRng* rng) const;

 private:
  std::array<double, kTones> omega_radps_{};
  std::array<std::array<double, kTones>, 3> phase_rad_{};  // [axis][tone]
  double amplitude_ = 0.0;
  double broadband_sigma_ = 0.0;
};

}  // namespace deepnav::sim
