#pragma once
#include <cstdint>

#include "nav/types/time.h"

namespace deepnav {

struct EkfConfig;

// Health of the compass against magnetic disturbance (after PX4 ekf2's handling of a bad magnetometer:
// watch the heading innovations, stop trusting the sensor while they are inconsistent, resume when they
// settle). Near steel (the panel) the compass reads the local field, a heading error of several degrees
// that grows as the vehicle approaches. While the yaw is held by something else (absolute poses from the
// markers fused recently, and the predicted yaw variance H P H^T small against the compass variance R), a
// persistent offset of the heading innovation means the compass is wrong, not the state. Without an
// absolute pose the compass is the only heading reference and the gyro's short-term hold cannot tell its
// disturbance from its slowly varying deviation: the detector then never refuses it.
//
// Statistic: the normalised innovation z = nu / sqrt(H P H^T + R) (nominal R, whatever the action), whose
// low-passed mean m (time constant tau) is ~0 with standard deviation ~1/sqrt(2 tau f) for a consistent
// compass at rate f. States and transitions (hysteresis: enter high, leave low and only after a hold):
//   clean     --(yaw held, |m| > suspect)-->  suspect   : compass fused with R x r_scale (de-weighted)
//   clean/suspect --(yaw held, |m| > enter)--> disturbed : compass refused (de-weighted while no marker
//                                                          pose was fused within the aided window)
//   suspect/disturbed --(|m| < exit for exit_hold)--> clean
// The innovations keep being computed while the compass is refused, so recovery is seen as it happens.
enum class MagState : std::uint8_t { kClean = 0, kSuspect = 1, kDisturbed = 2 };

// What to do with one compass sample. kUndecided marks a logged sample the detector has not seen yet.
enum class MagAction : std::uint8_t { kUndecided = 0, kFuse, kDeweight, kRefuse };

struct MagDisturbanceCounters {
  std::uint32_t samples = 0;       // compass samples judged
  std::uint32_t deweighted = 0;    // fused with the inflated variance
  std::uint32_t refused = 0;       // refused as disturbed
  std::uint32_t suspect_entries = 0;
  std::uint32_t disturbed_entries = 0;
  std::uint32_t recoveries = 0;    // back to clean
  TimeUs last_transition_t_us = -1;
};

struct MagDisturbanceParams {
  bool enabled = false;
  double tau_s = 3.0;
  double suspect_sigma = 1.0;
  double enter_sigma = 2.0;
  double exit_sigma = 0.5;
  TimeUs exit_hold_us = 3'000'000;
  double r_scale = 25.0;
  double yaw_held_ratio = 1.0;
  TimeUs aided_window_us = 2'000'000;
};

MagDisturbanceParams magDisturbanceParams(const EkfConfig& config);

class MagDisturbanceDetector {
 public:
  void configure(const MagDisturbanceParams& params);
  // Back to clean with a zero mean; the counters are kept.
  void restart();
  // One compass sample: its heading innovation (rad), the predicted yaw variance H P H^T and the
  // compass variance R (rad^2); pose_aided: an absolute pose was fused recently. Samples must come in time
  // order (first fusion of each sample).
  MagAction update(TimeUs t_us, double innovation_rad, double hph_rad2, double r_rad2, bool pose_aided);

  bool enabled() const { return params_.enabled; }
  double rScale() const { return params_.r_scale; }
  MagState state() const { return state_; }
  const MagDisturbanceCounters& counters() const { return counters_; }

 private:
  void updateMean(TimeUs t_us, double z);
  void transition(TimeUs t_us, bool yaw_held);
  void enter(MagState next, TimeUs t_us);

  MagDisturbanceParams params_;
  MagState state_ = MagState::kClean;
  double mean_z_ = 0.0;
  TimeUs last_t_us_ = -1;
  TimeUs calm_since_us_ = -1;  // -1: |m| is not below exit
  MagDisturbanceCounters counters_;
};

}  // namespace deepnav
