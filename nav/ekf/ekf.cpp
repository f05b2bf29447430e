#include "nav/ekf/ekf.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/overloaded.h"
#include "base/so3.h"
#include "nav/ekf/attitude_updater.h"
#include "nav/ekf/bias_gauss_markov.h"
#include "nav/ekf/depth_updater.h"
#include "nav/ekf/dvl_updater.h"
#include "nav/ekf/gate_reset.h"
#include "nav/ekf/heading_updater.h"
#include "nav/ekf/imu_gap_bridge.h"
#include "nav/ekf/imu_propagation.h"
#include "nav/ekf/measurement_update.h"
#include "nav/ekf/pose_updater.h"
#include "nav/ekf/relative_pose_updater.h"
#include "nav/ekf/sample_fingerprint.h"
#include "nav/ekf/stochastic_clone.h"

namespace deepnav {
namespace {

UpdateOutcome refused() { return {false, std::numeric_limits<double>::infinity()}; }

// A lockout is reset only after this many consecutive samples each close to the one before it: random
// garbage passes that by chance with probability ~ (gate window / sensor range)^5.
constexpr int kGateResetSmoothSamples = 5;

// Per-fusion diagnostics held between two loop ticks: a tick sees a few tens of measurements at most.
constexpr int kDiagnosticsCapacity = 256;

}  // namespace

bool Ekf::init(const EkfConfig& config, std::string* error) {
  initialised_ = false;
  if (!validateEkfConfig(config, error)) return false;
  if (!history_.allocate(config.history_imu_capacity) || !log_.allocate(config.history_meas_capacity) ||
      !diagnostics_.allocate(kDiagnosticsCapacity)) {
    if (error != nullptr) *error = "EkfConfig.history_imu_capacity: allocation failed";
    return false;
  }
  config_ = config;
  bounds_ = varianceBoundsFrom(config);
  gate_dvl_ = makeGateThresholds(config.gate_dvl_sigma);
  gate_depth_ = makeGateThresholds(config.gate_depth_sigma);
  gate_heading_ = makeGateThresholds(config.gate_heading_sigma);
  gate_attitude_ = makeGateThresholds(config.gate_attitude_sigma);
  gate_pose_ = makeGateThresholds(config.gate_pose_sigma);
  gate_relative_ = makeGateThresholds(config.gate_relative_pose_sigma);
  health_.configure(config);
  mag_.configure(magDisturbanceParams(config));
  alignment_.clear();
  state_ = FilterState{};
  resetCovariance(config_, &state_);
  counters_ = EkfCounters{};
  aligned_ = false;
  has_last_imu_ = false;
  latest_input_t_us_ = 0;
  next_seq_ = 0;
  initialised_ = true;
  return true;
}

bool Ekf::reset(TimeUs t_us, const EkfInitialState& initial) {
  if (!initialised_ || !initial.x.p_robot_in_odom_m.allFinite() || !initial.x.v_robot_in_odom_mps.allFinite() ||
      !initial.x.q_odom_robot.coeffs().allFinite() || initial.x.q_odom_robot.norm() < 1e-6 ||
      !initial.x.b_gyro_radps.allFinite() || !initial.x.b_accel_mps2.allFinite() || !initial.P.allFinite()) {
    return false;
  }
  state_.t_us = t_us;
  state_.x = initial.x;
  state_.x.q_odom_robot.normalize();
  state_.has_imu = false;
  state_.w_robot_meas_radps.setZero();
  state_.last_pose_fused_t_us = -1;
  resetCovariance(config_, &state_);
  mag_.restart();
  if (!initial.P.isZero(0.0)) {
    state_.P.topLeftCorner<es::kCoreDim, es::kCoreDim>() = 0.5 * (initial.P + initial.P.transpose());
  }
  if (!conditionCovariance(bounds_, &state_)) resetCovariance(config_, &state_);
  ImuSample anchor;
  anchor.t_us = t_us;
  startHistory(anchor);
  last_imu_t_us_ = t_us;
  has_last_imu_ = true;
  noteInputTime(t_us);
  return true;
}

void Ekf::startHistory(const ImuSample& sample) {
  history_.clear();
  log_.clear();
  HistoryEntry& e = history_.push();
  e.imu = sample;
  copyFilterState(state_, &e.state);
  last_good_x_ = state_.x;
  aligned_ = true;
  health_.start(sample.t_us);
}

bool Ekf::isValidImu(const ImuSample& s) const {
  return s.w_imu_radps.allFinite() && s.f_imu_mps2.allFinite() &&
         s.w_imu_radps.norm() <= config_.imu_max_rate_radps && s.f_imu_mps2.norm() <= config_.imu_max_accel_mps2;
}

void Ekf::noteInputTime(TimeUs t_us) { latest_input_t_us_ = std::max(latest_input_t_us_, t_us); }

void Ekf::setImu(const ImuSample& sample) {
  if (!initialised_) return;
  if (!isValidImu(sample) || (has_last_imu_ && sample.t_us <= last_imu_t_us_)) {
    health_.countBadInput(kSrcImu);
    return;
  }
  if (aligned_ && health_.noteFrozen(kSrcImu, sampleFingerprint(sample), config_.imu_stuck_after_samples)) {
    // A frozen IMU repeats its last message: integrating it would turn a constant rate and specific
    // force into a drifting pose. Refused, the IMU goes stale and the state coasts (Ekf::coast) as in an
    // outage; the first good sample after it bridges the gap (imu_gap_bridge.h).
    noteRefusedAtDoor(sample.t_us, kSrcImu, FusionReason::kFrozen);
    return;
  }
  noteInputTime(sample.t_us);
  if (!aligned_) {
    alignFromImu(sample);
    return;
  }
  if (sample.t_us - last_imu_t_us_ > config_.imu_max_gap_us) {
    ++counters_.imu_gaps;
    restartAfterImuGap(sample);
    return;
  }
  HistoryEntry& entry = history_.push();
  entry.imu = sample;
  stepImu(sample, &entry.state);
  last_imu_t_us_ = sample.t_us;
  health_.record(kSrcImu, FuseStatus::kQueued, FuseStatus::kAccepted, sample.t_us, 0.0);
  counters_.history_overwrites = history_.overwrites();
  trimHistory();
}

// imu_gap_bridge.h: the state coasts over the gap to this sample, and the history restarts here (no
// rewind across a gap); measurements taken during the gap cannot be fused any more and are dropped.
void Ekf::restartAfterImuGap(const ImuSample& sample) {
  bridgeImuGap(usToS(sample.t_us - state_.t_us), config_, &state_);
  state_.t_us = sample.t_us;
  state_.w_robot_meas_radps =
      imuToRobot(sample, config_.q_robot_imu, config_.p_imu_in_robot_m, state_.w_robot_meas_radps, 0.0).w_robot_radps;
  finishStep(state_.dim());
  const TimeUs stale_start = health_.startTime();
  startHistory(sample);
  health_.start(stale_start);  // the gap does not reset the stale clocks of the other sources
  last_imu_t_us_ = sample.t_us;
  health_.record(kSrcImu, FuseStatus::kQueued, FuseStatus::kAccepted, sample.t_us, 0.0);
}

void Ekf::alignFromImu(const ImuSample& sample) {
  const double dt_s = has_last_imu_ ? usToS(sample.t_us - last_imu_t_us_) : 0.0;
  const RobotImu u = imuToRobot(sample, config_.q_robot_imu, config_.p_imu_in_robot_m, state_.w_robot_meas_radps, dt_s);
  state_.w_robot_meas_radps = u.w_robot_radps;
  state_.has_imu = true;
  alignment_.addImu(u, sample.t_us);
  last_imu_t_us_ = sample.t_us;
  has_last_imu_ = true;
  if (!alignment_.ready(config_.align_imu_samples, config_.align_imu_only)) return;
  state_.t_us = sample.t_us;
  state_.x = alignment_.compute(config_.p_depth_in_robot_m, config_.align_gyro_bias_at_rest);
  resetCovariance(config_, &state_);
  startHistory(sample);
}

void Ekf::stepImu(const ImuSample& sample, FilterState* snapshot) {
  const TimeUs t_prev = state_.t_us;
  const double dt_s = state_.has_imu ? usToS(sample.t_us - t_prev) : 0.0;
  const RobotImu u = imuToRobot(sample, config_.q_robot_imu, config_.p_imu_in_robot_m, state_.w_robot_meas_radps, dt_s);
  state_.w_robot_meas_radps = u.w_robot_radps;
  state_.has_imu = true;
  // Measurements strictly inside (t_prev, t_k): propagate to each, fuse it.
  for (int i = log_.firstAfter(t_prev); i < log_.size() && log_.at(i).t_us < sample.t_us; ++i) {
    propagateTo(log_.at(i).t_us, u);
    applyMeasurement(log_.at(i));
  }
  propagateTo(sample.t_us, u);
  copyFilterState(state_, snapshot);
  for (int i = log_.firstAtOrAfter(sample.t_us); i < log_.size() && log_.at(i).t_us == sample.t_us; ++i) {
    applyMeasurement(log_.at(i));
  }
}

void Ekf::propagateTo(TimeUs t_us, const RobotImu& u) {
  const double dt_s = usToS(t_us - state_.t_us);
  if (dt_s <= 0.0) return;
  CoreMatrix Phi = propagationJacobian(state_.x, u, dt_s);
  CoreMatrix Q = propagationNoise(config_, dt_s);
  state_.x = propagateNominal(state_.x, u, dt_s, config_.gravity_mps2);
  if (biasGaussMarkovEnabled(config_)) applyBiasGaussMarkov(config_, dt_s, &Phi, &Q, &state_.x);
  propagateCovariance(Phi, Q, &state_);
  state_.t_us = t_us;
  finishStep(es::kCoreDim);
}

void Ekf::finishStep(int sym_dim) {
  if (conditionCovariance(bounds_, &state_, sym_dim) && isFiniteState(state_)) {
    last_good_x_ = state_.x;
    return;
  }
  // Something went non-finite or lost positive definiteness: keep the last sane nominal state, restart
  // the covariance (clones cannot be trusted any more and are dropped).
  ++counters_.numeric_resets;
  state_.x = last_good_x_;
  resetCovariance(config_, &state_);
}

// The health slot of a payload's source. Every alternative is named: a new payload kind does not compile
// until it is routed here.
NavSource Ekf::sourceOf(const MeasurementPayload& p) const {
  return std::visit(Overloaded{[](const DvlSample&) { return kSrcDvl; },
                               [](const DepthSample&) { return kSrcDepth; },
                               [](const HeadingSample&) { return kSrcHeading; },
                               [](const AttitudeSample&) { return kSrcAttitude; },
                               [](const PoseMeasurement& m) { return m.source; },
                               [](const RelativePoseMeasurement& m) { return m.source; },
                               // Clone bookkeeping and gate resets have no health slot.
                               [](const CloneRequest&) { return kSrcCount; },
                               [](const CloneRelease&) { return kSrcCount; },
                               [](const GateReset&) { return kSrcCount; }},
                    p);
}

// One update per payload kind (every alternative named, as in sourceOf).
UpdateOutcome Ekf::applyPayload(LoggedMeasurement& e) {
  return std::visit(
      Overloaded{[&](const DvlSample& m) -> UpdateOutcome {
                   Linearization lin;
                   return linearizeDvl(state_, m, config_, &lin)
                              ? gateAndUpdate(considerUnaided(&lin), gate_dvl_, &state_)
                              : refused();
                 },
                 [&](const DepthSample& m) -> UpdateOutcome {
                   Linearization lin;
                   return linearizeDepth(state_, m, config_, &lin)
                              ? gateAndUpdate(considerUnaided(&lin), gate_depth_, &state_)
                              : refused();
                 },
                 [&](const HeadingSample&) { return applyHeading(e); },
                 [&](const AttitudeSample& m) -> UpdateOutcome {
                   Linearization lin;
                   return linearizeAttitude(state_, m, config_, &lin)
                              ? gateAndUpdate(considerUnaided(&lin), gate_attitude_, &state_)
                              : refused();
                 },
                 [&](const PoseMeasurement& m) -> UpdateOutcome {
                   Linearization lin;
                   return notePoseFused(m.t_us, linearizePose(state_, m, &lin) ? gateAndUpdate(lin, gate_pose_, &state_)
                                                                               : refused());
                 },
                 [&](const RelativePoseMeasurement& m) { return applyRelativePose(m); },
                 [&](const CloneRequest& m) -> UpdateOutcome {
                   return {augmentClone(m.id, config_.max_clones, &state_) == CloneStatus::kOk, 0.0};
                 },
                 [&](const CloneRelease& m) -> UpdateOutcome {
                   return {marginaliseClone(m.id, &state_) == CloneStatus::kOk, 0.0};
                 },
                 [&](const GateReset& m) -> UpdateOutcome {
                   resetObservedStates(m.source, config_, &state_);
                   return {true, 0.0};
                 }},
      e.payload);
}

UpdateOutcome Ekf::applyRelativePose(const RelativePoseMeasurement& m) {
  Linearization lin;
  const UpdateOutcome out =
      linearizeRelativePose(state_, m, &lin) ? gateAndUpdate(lin, gate_relative_, &state_) : refused();
  if (m.release_clone) marginaliseClone(m.clone_id, &state_);
  return notePoseFused(m.t_us, out);
}

// Systematic states (systematic_states.h) are observable only with an absolute or relative pose: without
// one recently, DVL, depth, compass and AHRS updates treat them as Schmidt consider states (their
// uncertainty counted, never corrected), so that weakly observable directions do not soak up model errors.
Linearization& Ekf::considerUnaided(Linearization* lin) const {
  const TimeUs last = state_.last_pose_fused_t_us;
  const bool aided = last >= 0 && state_.t_us - last <= config_.position_aided_timeout_us;
  if (state_.sys_layout.dim > 0 && !aided) {
    lin->consider_begin = state_.sysOffset();
    lin->consider_count = state_.sys_layout.dim;
  }
  return *lin;
}

UpdateOutcome Ekf::notePoseFused(TimeUs t_us, const UpdateOutcome& out) {
  if (out.accepted) state_.last_pose_fused_t_us = std::max(state_.last_pose_fused_t_us, t_us);
  return out;
}

// The compass through the magnetic-disturbance detector (mag_disturbance.h). The decision is taken at the
// sample's first fusion and kept in the log, so a re-fusion after a rewind repeats it.
UpdateOutcome Ekf::applyHeading(LoggedMeasurement& e) {
  Linearization lin;
  if (!linearizeHeading(state_, std::get<HeadingSample>(e.payload), config_, &lin)) return refused();
  if (e.mag_action == MagAction::kUndecided) e.mag_action = judgeCompass(e.t_us, lin);
  if (e.mag_action == MagAction::kRefuse) return gateOnly(lin, gate_heading_, state_);
  if (e.mag_action == MagAction::kDeweight) lin.R *= mag_.rScale();
  return gateAndUpdate(considerUnaided(&lin), gate_heading_, &state_);
}

// Yaw variance predicted at the compass, H P H^T, against the compass variance R (one row, nominal R),
// and whether a marker pose (the absolute heading reference) was fused within the aided window.
MagAction Ekf::judgeCompass(TimeUs t_us, const Linearization& lin) {
  if (!mag_.enabled()) return MagAction::kFuse;
  const int n = state_.dim();
  const double hph = lin.H.row(0).head(n).dot(state_.P.topLeftCorner(n, n) * lin.H.row(0).head(n).transpose());
  const bool pose_aided = health_.acceptedWithin(kSrcMarkers, t_us, config_.mag_disturbance_aided_window_us);
  return mag_.update(t_us, lin.residual(0), hph, lin.R(0, 0), pose_aided);
}

void Ekf::noteDiagnostic(const LoggedMeasurement& e, NavSource src, const UpdateOutcome& r) {
  FusionDiagnostic d;
  d.t_us = e.t_us;
  d.source = src;
  d.dim = static_cast<std::uint8_t>(r.m);
  d.innovation = r.innovation;
  d.innovation_variance = r.innovation_variance;
  d.test_ratio = r.test_ratio;
  d.mag_state = static_cast<std::uint8_t>(mag_.state());
  if (r.accepted) {
    d.reason = e.mag_action == MagAction::kDeweight ? FusionReason::kFusedDeweighted : FusionReason::kFused;
  } else if (e.mag_action == MagAction::kRefuse) {
    d.reason = FusionReason::kMagDisturbance;
  } else {
    d.reason = r.m > 0 && std::isfinite(r.test_ratio) ? FusionReason::kGate : FusionReason::kUnusable;
  }
  diagnostics_.push(d);
}

void Ekf::noteRefusedAtDoor(TimeUs t_us, NavSource src, FusionReason reason) {
  if (src == kSrcCount) return;
  FusionDiagnostic d;
  d.t_us = t_us;
  d.source = src;
  d.reason = reason;
  d.mag_state = static_cast<std::uint8_t>(mag_.state());
  diagnostics_.push(d);
}

void Ekf::applyMeasurement(LoggedMeasurement& e) {
  const FuseStatus previous = e.outcome;
  const UpdateOutcome r = applyPayload(e);
  finishStep(state_.dim());
  e.outcome = r.accepted ? FuseStatus::kAccepted : FuseStatus::kRejected;
  if (!r.accepted && e.mag_action == MagAction::kRefuse) e.outcome = FuseStatus::kRefused;
  e.test_ratio = r.test_ratio;
  const NavSource src = sourceOf(e.payload);
  if (src != kSrcCount) {
    health_.record(src, previous, e.outcome, e.t_us, e.test_ratio);
    if (previous == FuseStatus::kQueued) noteDiagnostic(e, src, r);
  } else if ((previous == FuseStatus::kRejected) != (e.outcome == FuseStatus::kRejected)) {
    e.outcome == FuseStatus::kRejected ? ++counters_.clone_failures : --counters_.clone_failures;
  }
}

LoggedMeasurement Ekf::makeLogged(TimeUs t_us, const MeasurementPayload& payload) {
  LoggedMeasurement e;
  e.t_us = t_us;
  e.seq = next_seq_++;
  e.payload = payload;
  return e;
}

FuseResult Ekf::submit(const LoggedMeasurement& e, NavSource src, bool valid) {
  if (!initialised_) return {FuseStatus::kNotAligned, 0.0};
  if (!valid) {
    if (src != kSrcCount) health_.countBadInput(src);
    noteRefusedAtDoor(e.t_us, src, FusionReason::kBadInput);
    return {FuseStatus::kBadInput, 0.0};
  }
  if (refuseFutureStamp(src, e.t_us)) return {FuseStatus::kBadInput, 0.0};
  noteInputTime(e.t_us);
  if (!aligned_) return {FuseStatus::kNotAligned, 0.0};
  if (e.t_us > state_.t_us) {
    int index = -1;
    if (insertWithEviction(e, &index)) return {FuseStatus::kQueued, 0.0};
    if (src != kSrcCount) health_.countDroppedLate(src);
    noteRefusedAtDoor(e.t_us, src, FusionReason::kLate);
    return {FuseStatus::kDroppedLate, 0.0};
  }
  return fuseLate(e, src);
}

FuseResult Ekf::fuseLate(const LoggedMeasurement& e, NavSource src) {
  const FuseResult dropped{FuseStatus::kDroppedLate, 0.0};
  const bool too_old = e.t_us < state_.t_us - config_.max_delay_us;
  int index = -1;
  if (too_old || history_.empty() || e.t_us < history_.timeAt(0) || !insertWithEviction(e, &index)) {
    if (src != kSrcCount) health_.countDroppedLate(src);
    noteRefusedAtDoor(e.t_us, src, FusionReason::kLate);
    return dropped;
  }
  const int base = history_.latestAtOrBefore(e.t_us);
  if (base < 0) {  // the eviction above took the snapshot away; the entry is trimmed with the window
    log_.at(index).outcome = FuseStatus::kDroppedLate;
    if (src != kSrcCount) health_.countDroppedLate(src);
    noteRefusedAtDoor(e.t_us, src, FusionReason::kLate);
    return dropped;
  }
  ++counters_.replays;
  replayFrom(base);
  return {log_.at(index).outcome, log_.at(index).test_ratio};
}

bool Ekf::insertWithEviction(const LoggedMeasurement& e, int* index) {
  if (log_.full()) {
    const TimeUs t_old = log_.at(0).t_us;
    if (t_old > state_.t_us || t_old > e.t_us) return false;  // only queued or newer entries: keep them
    log_.popOldest();
    ++counters_.history_overflows;
    // A snapshot at or before the evicted measurement would replay without it: unusable now.
    while (!history_.empty() && history_.timeAt(0) <= t_old) history_.popOldest();
  }
  *index = log_.insert(e);
  return *index >= 0;
}

void Ekf::replayFrom(int history_index) {
  HistoryEntry& base = history_.at(history_index);
  copyFilterState(base.state, &state_);
  last_good_x_ = state_.x;
  const TimeUs t0 = base.imu.t_us;
  for (int i = log_.firstAtOrAfter(t0); i < log_.size() && log_.at(i).t_us == t0; ++i) {
    applyMeasurement(log_.at(i));
  }
  for (int k = history_index + 1; k < history_.size(); ++k) {
    HistoryEntry& h = history_.at(k);
    stepImu(h.imu, &h.state);
  }
}

void Ekf::trimHistory() {
  const TimeUs horizon = state_.t_us - config_.max_delay_us;
  while (history_.size() > 1 && history_.timeAt(1) <= horizon) history_.popOldest();
  if (history_.empty()) return;
  const TimeUs oldest = history_.timeAt(0);
  while (log_.size() > 0 && log_.at(0).t_us < oldest) log_.popOldest();
}

// A sample is stamped at or before its arrival, which is at most one tick after the loop's latest tick.
// One stamped further ahead than the delay window reaches back comes from a clock that jumped: refused
// before it can move the stale clocks (noteInputTime), feed the lockout logic or wait in the log to be
// fused at a wrong time. It raises the source's reject flag until its next sample (SourceHealth).
bool Ekf::refuseFutureStamp(NavSource src, TimeUs t_us) {
  if (loop_t_us_ < 0 || !aligned_ || src == kSrcCount || t_us - loop_t_us_ <= config_.max_delay_us) return false;
  health_.noteBadStamp(src);
  noteRefusedAtDoor(t_us, src, FusionReason::kFutureStamp);
  return true;
}

bool Ekf::admitAidingSample(NavSource src, TimeUs t_us, std::uint64_t fingerprint, const Eigen::Vector3d& value,
                            bool angles, double tolerance) {
  if (!initialised_) return true;
  if (refuseFutureStamp(src, t_us)) return false;
  if (health_.noteFrozen(src, fingerprint, config_.stuck_after_samples)) {
    if (aligned_) noteRefusedAtDoor(t_us, src, FusionReason::kFrozen);
    return false;
  }
  Eigen::Vector3d change = value - health_.source(src).last_value;
  if (angles) {
    for (int i = 0; i < 3; ++i) change[i] = wrapPi(change[i]);
  }
  resetIfLockedOut(src, t_us, value, change.cwiseAbs().maxCoeff(), tolerance);
  return true;
}

void Ekf::resetIfLockedOut(NavSource src, TimeUs t_us, const Eigen::Vector3d& value, double change,
                           double tolerance) {
  health_.noteChange(src, value, change, tolerance);
  if (aligned_ && health_.source(src).smooth_streak >= kGateResetSmoothSamples &&
      health_.lockedOut(src, t_us, config_.gate_reset_after_us)) {
    health_.noteGateReset(src, t_us);
    ++counters_.gate_resets;
    submit(makeLogged(t_us, GateReset{t_us, src}), kSrcCount, true);
  }
}

FuseResult Ekf::fuseDvl(const DvlSample& m) {
  const bool valid = isValidDvl(m);
  if (valid && !admitAidingSample(kSrcDvl, m.t_us, sampleFingerprint(m), m.v_dvl_mps, false,
                                  config_.gate_dvl_sigma * config_.init_vel_sigma_mps)) {
    return {FuseStatus::kBadInput, 0.0};
  }
  return submit(makeLogged(m.t_us, m), kSrcDvl, valid);
}

FuseResult Ekf::fuseDepth(const DepthSample& m) {
  const bool valid = isValidDepth(m);
  if (valid && !admitAidingSample(kSrcDepth, m.t_us, sampleFingerprint(m), Eigen::Vector3d(m.depth_m, 0, 0), false,
                                  config_.gate_depth_sigma * config_.init_pos_sigma_m)) {
    return {FuseStatus::kBadInput, 0.0};
  }
  if (initialised_ && valid && !aligned_) alignment_.setDepth(m.depth_m);
  return submit(makeLogged(m.t_us, m), kSrcDepth, valid);
}

FuseResult Ekf::fuseHeading(const HeadingSample& m) {
  const bool valid = isValidHeading(m);
  if (valid && !admitAidingSample(kSrcHeading, m.t_us, sampleFingerprint(m), Eigen::Vector3d(m.heading_rad, 0, 0), true,
                                  config_.gate_heading_sigma * config_.init_yaw_sigma_rad)) {
    return {FuseStatus::kBadInput, 0.0};
  }
  if (initialised_ && valid && !aligned_) alignment_.setYaw(yawFromHeading(m, config_));
  return submit(makeLogged(m.t_us, m), kSrcHeading, valid);
}

FuseResult Ekf::fuseAttitude(const AttitudeSample& m) {
  const bool valid = isValidAttitude(m);
  if (valid && !admitAidingSample(kSrcAttitude, m.t_us, sampleFingerprint(m),
                                  Eigen::Vector3d(m.roll_rad, m.pitch_rad, 0), true,
                                  config_.gate_attitude_sigma * config_.init_roll_pitch_sigma_rad)) {
    return {FuseStatus::kBadInput, 0.0};
  }
  return submit(makeLogged(m.t_us, m), kSrcAttitude, valid);
}

FuseResult Ekf::fusePose(const PoseMeasurement& m) {
  const bool valid = isValidPose(m) && m.source < kSrcCount;
  // Marker poses can lock out as the other aiding sources do (gate_reset.h): consecutive poses that agree
  // within the gate window on a position the filter keeps refusing. Not checked for frozen samples: a
  // still camera on a noiseless image may repeat a pose bit for bit.
  if (valid && initialised_ && m.source == kSrcMarkers) {
    const Eigen::Vector3d change = m.p_robot_in_odom_m - health_.source(kSrcMarkers).last_value;
    resetIfLockedOut(kSrcMarkers, m.t_us, m.p_robot_in_odom_m, change.cwiseAbs().maxCoeff(),
                     config_.gate_pose_sigma * config_.init_pos_sigma_m);
  }
  return submit(makeLogged(m.t_us, m), m.source < kSrcCount ? m.source : kSrcMarkers, valid);
}

FuseResult Ekf::fuseRelativePose(const RelativePoseMeasurement& m) {
  const bool valid = isValidRelativePose(m) && m.source < kSrcCount;
  return submit(makeLogged(m.t_us, m), m.source < kSrcCount ? m.source : kSrcVoOrb, valid);
}

FuseResult Ekf::clonePose(TimeUs t_us, std::uint32_t id) {
  return submit(makeLogged(t_us, CloneRequest{t_us, id}), kSrcCount, true);
}

FuseResult Ekf::releaseClone(TimeUs t_us, std::uint32_t id) {
  return submit(makeLogged(t_us, CloneRelease{t_us, id}), kSrcCount, true);
}

}  // namespace deepnav
