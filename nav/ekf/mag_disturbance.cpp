#include "nav/ekf/mag_disturbance.h"

#include <algorithm>
#include <cmath>

#include "nav/ekf/ekf_config.h"

namespace deepnav {

MagDisturbanceParams magDisturbanceParams(const EkfConfig& c) {
  MagDisturbanceParams p;
  p.enabled = c.mag_disturbance_enabled;
  p.tau_s = c.mag_disturbance_tau_s;
  p.suspect_sigma = c.mag_disturbance_suspect_sigma;
  p.enter_sigma = c.mag_disturbance_enter_sigma;
  p.exit_sigma = c.mag_disturbance_exit_sigma;
  p.exit_hold_us = c.mag_disturbance_exit_hold_us;
  p.r_scale = c.mag_disturbance_r_scale;
  p.yaw_held_ratio = c.mag_disturbance_yaw_held_ratio;
  p.aided_window_us = c.mag_disturbance_aided_window_us;
  return p;
}

void MagDisturbanceDetector::configure(const MagDisturbanceParams& params) {
  params_ = params;
  counters_ = MagDisturbanceCounters{};
  restart();
}

void MagDisturbanceDetector::restart() {
  state_ = MagState::kClean;
  mean_z_ = 0.0;
  last_t_us_ = -1;
  calm_since_us_ = -1;
}

// First-order low-pass with the gain of the elapsed time, alpha = 1 - exp(-dt / tau), so the time
// constant holds whatever the compass rate; a time step backwards or a first sample only starts it.
void MagDisturbanceDetector::updateMean(TimeUs t_us, double z) {
  const double dt_s = last_t_us_ >= 0 ? usToS(t_us - last_t_us_) : 0.0;
  last_t_us_ = std::max(last_t_us_, t_us);
  if (!(dt_s > 0.0)) return;
  const double alpha = 1.0 - std::exp(-dt_s / params_.tau_s);
  mean_z_ += alpha * (z - mean_z_);
}

void MagDisturbanceDetector::enter(MagState next, TimeUs t_us) {
  if (next == state_) return;
  if (next == MagState::kSuspect) ++counters_.suspect_entries;
  if (next == MagState::kDisturbed) ++counters_.disturbed_entries;
  if (next == MagState::kClean) ++counters_.recoveries;
  counters_.last_transition_t_us = t_us;
  state_ = next;
  calm_since_us_ = -1;
}

void MagDisturbanceDetector::transition(TimeUs t_us, bool yaw_held) {
  const double m = std::abs(mean_z_);
  if (yaw_held && m > params_.enter_sigma) return enter(MagState::kDisturbed, t_us);
  if (state_ == MagState::kClean) {
    if (yaw_held && m > params_.suspect_sigma) enter(MagState::kSuspect, t_us);
    return;
  }
  if (m >= params_.exit_sigma) {
    calm_since_us_ = -1;
    return;
  }
  if (calm_since_us_ < 0) calm_since_us_ = t_us;
  if (t_us - calm_since_us_ >= params_.exit_hold_us) enter(MagState::kClean, t_us);
}

MagAction MagDisturbanceDetector::update(TimeUs t_us, double innovation_rad, double hph_rad2, double r_rad2,
                                         bool pose_aided) {
  if (!params_.enabled) return MagAction::kFuse;
  const double s = hph_rad2 + r_rad2;
  if (!(s > 0.0) || !std::isfinite(innovation_rad) || !std::isfinite(s)) return MagAction::kFuse;
  ++counters_.samples;
  updateMean(t_us, innovation_rad / std::sqrt(s));
  transition(t_us, pose_aided && hph_rad2 < params_.yaw_held_ratio * r_rad2);
  switch (state_) {
    case MagState::kClean: return MagAction::kFuse;
    case MagState::kSuspect: ++counters_.deweighted; return MagAction::kDeweight;
    case MagState::kDisturbed:
      // Refused only while a marker pose holds the heading: without one (markers occluded, or gated after a
      // drift) the compass is the only absolute reference left, so it is de-weighted instead of dropped,
      // and the drift stays bounded.
      if (!pose_aided) {
        ++counters_.deweighted;
        return MagAction::kDeweight;
      }
      ++counters_.refused;
      return MagAction::kRefuse;
  }
  return MagAction::kFuse;
}

}  // namespace deepnav
