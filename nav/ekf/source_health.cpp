#include "nav/ekf/source_health.h"

#include <algorithm>

#include "nav/ekf/ekf_config.h"

namespace deepnav {

void SourceHealthMonitor::configure(const EkfConfig& c) {
  sources_ = {};
  timeout_us_ = {};
  timeout_us_[kSrcImu] = c.timeout_imu_us;
  timeout_us_[kSrcDvl] = c.timeout_dvl_us;
  timeout_us_[kSrcDepth] = c.timeout_depth_us;
  timeout_us_[kSrcHeading] = c.timeout_heading_us;
  timeout_us_[kSrcAttitude] = c.timeout_attitude_us;
  timeout_us_[kSrcMarkers] = c.timeout_markers_us;
  timeout_us_[kSrcVoOrb] = c.timeout_vo_us;
  timeout_us_[kSrcVoPlanes] = c.timeout_vo_us;
  timeout_us_[kSrcCamera] = 0;  // the camera itself is watched by the vision side
}

void SourceHealthMonitor::start(TimeUs t_us) { start_us_ = t_us; }

void SourceHealthMonitor::record(NavSource src, FuseStatus previous, FuseStatus now, TimeUs t_us,
                                 double test_ratio) {
  SourceHealth& h = at(src);
  if (previous == FuseStatus::kAccepted) --h.counters.accepted;
  if (previous == FuseStatus::kRejected) --h.counters.rejected;
  if (now == FuseStatus::kAccepted) {
    ++h.counters.accepted;
    h.last_accepted_t_us = std::max(h.last_accepted_t_us, t_us);
  }
  if (now == FuseStatus::kRejected) ++h.counters.rejected;
  h.last_seen_t_us = std::max(h.last_seen_t_us, t_us);
  h.last_rejected = now == FuseStatus::kRejected;
  h.last_stamp_bad = false;
  h.last_test_ratio = test_ratio;
}

bool SourceHealthMonitor::noteFrozen(NavSource src, std::uint64_t fingerprint, int limit) {
  SourceHealth& h = at(src);
  h.repeats = h.repeats > 0 && fingerprint == h.last_fingerprint ? h.repeats + 1 : 1;
  h.last_fingerprint = fingerprint;
  if (limit <= 0 || h.repeats < limit) return false;
  ++h.counters.frozen;
  h.last_rejected = true;
  return true;
}

bool SourceHealthMonitor::lockedOut(NavSource src, TimeUs t_us, TimeUs after_us) const {
  const SourceHealth& h = source(src);
  if (after_us <= 0 || !h.last_rejected) return false;
  const TimeUs since = std::max({h.last_accepted_t_us, h.last_gate_reset_t_us, start_us_});
  return t_us - since > after_us;
}

void SourceHealthMonitor::noteGateReset(NavSource src, TimeUs t_us) {
  SourceHealth& h = at(src);
  h.last_gate_reset_t_us = std::max(h.last_gate_reset_t_us, t_us);
  ++h.counters.gate_resets;
}

void SourceHealthMonitor::noteChange(NavSource src, const Eigen::Vector3d& value, double change, double tolerance) {
  SourceHealth& h = at(src);
  h.smooth_streak = change <= tolerance ? h.smooth_streak + 1 : 0;
  h.last_value = value;
}

bool SourceHealthMonitor::isStale(NavSource src, TimeUs now_us) const {
  const TimeUs timeout = timeout_us_[static_cast<std::size_t>(src)];
  if (timeout <= 0) return false;
  const TimeUs last = std::max(source(src).last_seen_t_us, start_us_);
  return now_us - last > timeout;
}

bool SourceHealthMonitor::acceptedWithin(NavSource src, TimeUs now_us, TimeUs window_us) const {
  const TimeUs last = source(src).last_accepted_t_us;
  return last >= 0 && now_us - last <= window_us;
}

std::uint32_t SourceHealthMonitor::faultBits(TimeUs now_us) const {
  std::uint32_t bits = 0;
  for (int i = 0; i < kSrcCount; ++i) {
    const auto src = static_cast<NavSource>(i);
    if (isStale(src, now_us)) bits |= staleBit(src);
    if (source(src).last_rejected || source(src).last_stamp_bad) bits |= rejectBit(src);
  }
  return bits;
}

std::uint32_t SourceHealthMonitor::rejectedTotal() const {
  std::uint32_t n = 0;
  for (const SourceHealth& h : sources_) n += h.counters.rejected;
  return n;
}

std::uint32_t SourceHealthMonitor::droppedLateTotal() const {
  std::uint32_t n = 0;
  for (const SourceHealth& h : sources_) n += h.counters.dropped_late;
  return n;
}

}  // namespace deepnav
