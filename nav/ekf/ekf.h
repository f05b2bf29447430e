#pragma once
#include <cstdint>
#include <string>

#include <Eigen/Core>

#include "nav/ekf/covariance_guard.h"
#include "nav/ekf/ekf_config.h"
#include "nav/ekf/ekf_measurements.h"
#include "nav/ekf/filter_state.h"
#include "nav/ekf/fuse_result.h"
#include "nav/ekf/fusion_diagnostic.h"
#include "nav/ekf/initial_alignment.h"
#include "nav/ekf/mag_disturbance.h"
#include "nav/ekf/innovation_gate.h"
#include "nav/ekf/measurement_log.h"
#include "nav/ekf/measurement_update.h"
#include "nav/ekf/source_health.h"
#include "nav/ekf/state_history.h"
#include "nav/types/attitude_sample.h"
#include "nav/types/depth_sample.h"
#include "nav/types/dvl_sample.h"
#include "nav/types/heading_sample.h"
#include "nav/types/imu_sample.h"
#include "nav/types/nav_solution.h"

namespace deepnav {

// Explicit initial state for reset(); a zero covariance means "use the configured initial sigmas".
struct EkfInitialState {
  NominalState x;
  CoreMatrix P = CoreMatrix::Zero();
};

// Filter-wide counters (per-source ones are in SourceHealth).
struct EkfCounters {
  std::uint32_t numeric_resets = 0;     // a non-finite or non-PD state was replaced by a sane one
  std::uint32_t history_overflows = 0;  // measurement log full: oldest evicted, window shortened
  std::uint32_t imu_gaps = 0;           // IMU steps longer than imu_max_gap_us
  std::uint32_t replays = 0;            // rewinds for a late measurement
  std::uint32_t clone_failures = 0;     // clone or release refused (full, duplicate or unknown id)
  std::uint32_t history_overwrites = 0; // IMU epochs lost because history_imu_capacity < window
  std::uint32_t gate_resets = 0;        // lockout recoveries of DVL, depth, compass or AHRS (gate_reset.h)
};

// Error-state EKF of an ROV: IMU-driven nominal state (p, v, q, bg, ba) with a 15-dim error state plus
// stochastic pose clones, aided by DVL, depth, compass, AHRS roll/pitch, absolute and relative poses.
// Measurements are fused at their capture time up to max_delay_us late: the filter rewinds to the IMU
// epoch before it (StateHistory), fuses, and re-runs the buffered IMU samples and later measurements,
// so the result equals in-order fusion. A measurement newer than the last IMU sample is queued until the
// IMU reaches it. Every buffer is allocated in init(); nothing allocates or throws afterwards.
class Ekf {
 public:
  Ekf() = default;
  Ekf(const Ekf&) = delete;
  Ekf& operator=(const Ekf&) = delete;

  // Validates the config and allocates the history; false with a message naming the key on error.
  bool init(const EkfConfig& config, std::string* error);

  // Starts from an explicit state at t_us (drops history, clones and queued measurements).
  // False (and nothing changed) when the state is not finite or the filter not initialised.
  bool reset(TimeUs t_us, const EkfInitialState& initial);

  // IMU samples must come in increasing time; each drives the step ending at its time stamp.
  // Before alignment they feed the roll/pitch alignment.
  void setImu(const ImuSample& sample);

  // The loop's clock at its latest tick: a sample consumed after it arrived at most one tick later, so
  // one stamped further ahead of it than the delay window carries a jumped clock and is refused
  // (FusionReason::kFutureStamp). Never called (bare filter, unit tests): no such check.
  void noteLoopTime(TimeUs t_us) { loop_t_us_ = t_us; }

  FuseResult fuseDvl(const DvlSample& m);
  FuseResult fuseDepth(const DepthSample& m);
  FuseResult fuseHeading(const HeadingSample& m);
  FuseResult fuseAttitude(const AttitudeSample& m);
  FuseResult fusePose(const PoseMeasurement& m);
  FuseResult fuseRelativePose(const RelativePoseMeasurement& m);

  // Stochastic cloning: copy the pose at t_us into the state as clone `id` (for a later relative pose),
  // and release it (marginalise). Both are events at their time, like measurements.
  FuseResult clonePose(TimeUs t_us, std::uint32_t id);
  FuseResult releaseClone(TimeUs t_us, std::uint32_t id);

  NavSolution solution() const;
  // The same, with the stale flags judged at now_us (the loop's tick time): a source that stopped is
  // flagged even when no other input arrives to move the filter's clock.
  NavSolution solution(TimeUs now_us) const;

  bool initialised() const { return initialised_; }
  bool aligned() const { return aligned_; }
  // True when a measurement taken at t_us can no longer be fused: older than the oldest snapshot the
  // delay window keeps (it would be dropped late).
  bool beyondWindow(TimeUs t_us) const { return aligned_ && (history_.empty() || t_us < history_.timeAt(0)); }
  const FilterState& state() const { return state_; }
  const SourceHealth& health(NavSource src) const { return health_.source(src); }
  const EkfCounters& counters() const { return counters_; }
  const EkfConfig& config() const { return config_; }
  // Compass health against magnetic disturbance: state, decisions and their counters.
  const MagDisturbanceDetector& magDisturbance() const { return mag_; }
  // Per-fusion diagnostics since the last clearDiagnostics() (the loop records and clears them every tick).
  const FusionDiagnosticBuffer& diagnostics() const { return diagnostics_; }
  void clearDiagnostics() { diagnostics_.clear(); }

 private:
  FuseResult submit(const LoggedMeasurement& e, NavSource src, bool valid);
  FuseResult fuseLate(const LoggedMeasurement& e, NavSource src);
  bool insertWithEviction(const LoggedMeasurement& e, int* index);
  void replayFrom(int history_index);
  void stepImu(const ImuSample& sample, FilterState* snapshot);
  void propagateTo(TimeUs t_us, const RobotImu& u);
  void applyMeasurement(LoggedMeasurement& e);
  UpdateOutcome applyPayload(LoggedMeasurement& e);
  UpdateOutcome applyRelativePose(const RelativePoseMeasurement& m);
  Linearization& considerUnaided(Linearization* lin) const;
  UpdateOutcome notePoseFused(TimeUs t_us, const UpdateOutcome& out);
  UpdateOutcome applyHeading(LoggedMeasurement& e);
  MagAction judgeCompass(TimeUs t_us, const Linearization& lin);
  void noteDiagnostic(const LoggedMeasurement& e, NavSource src, const UpdateOutcome& r);
  void noteRefusedAtDoor(TimeUs t_us, NavSource src, FusionReason reason);
  void finishStep(int sym_dim);
  void trimHistory();
  void alignFromImu(const ImuSample& sample);
  void restartAfterImuGap(const ImuSample& sample);
  void startHistory(const ImuSample& sample);
  bool isValidImu(const ImuSample& sample) const;
  bool refuseFutureStamp(NavSource src, TimeUs t_us);
  std::uint32_t statusBits(TimeUs now_us) const;
  void coast(TimeUs now_us, NavSolution* s) const;
  void noteInputTime(TimeUs t_us);
  NavSource sourceOf(const MeasurementPayload& payload) const;
  LoggedMeasurement makeLogged(TimeUs t_us, const MeasurementPayload& payload);
  // Door checks of a valid DVL/depth/compass/AHRS sample: false when it is frozen (counted); logs a gate
  // reset before it when its source is locked out.
  // value: the sample's measured values; angles: wrap their changes to [-pi, pi]; tolerance: the largest
  // change between consecutive samples of a sensor that looks healthy by itself (only then is a lockout
  // reset, so that random garbage never opens the gate).
  bool admitAidingSample(NavSource src, TimeUs t_us, std::uint64_t fingerprint, const Eigen::Vector3d& value,
                         bool angles, double tolerance);
  // The lockout check of one sample (admitAidingSample's tail; marker poses come here directly): counts the
  // sample's change against the one before, logs a gate reset before it when the source is locked out.
  void resetIfLockedOut(NavSource src, TimeUs t_us, const Eigen::Vector3d& value, double change, double tolerance);

  EkfConfig config_;
  bool initialised_ = false;
  bool aligned_ = false;
  FilterState state_;
  NominalState last_good_x_;
  VarianceBounds bounds_;
  GateThresholds gate_dvl_, gate_depth_, gate_heading_, gate_attitude_, gate_pose_, gate_relative_;
  StateHistory history_;
  MeasurementLog log_;
  InitialAlignment alignment_;
  SourceHealthMonitor health_;
  EkfCounters counters_;
  MagDisturbanceDetector mag_;
  FusionDiagnosticBuffer diagnostics_;
  std::uint64_t next_seq_ = 0;
  TimeUs last_imu_t_us_ = 0;
  TimeUs latest_input_t_us_ = 0;
  TimeUs loop_t_us_ = -1;  // noteLoopTime(); -1: not known
  bool has_last_imu_ = false;
};

}  // namespace deepnav
