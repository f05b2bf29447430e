#include "tests/support/replay_fault_injector.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/overloaded.h"
#include "base/so3.h"

namespace deepnav {
namespace {

constexpr double kHugeVariance = 1e300;
constexpr double kHugeSigma = 1e150;

// Accepted measurements of the sources a sample feeds, from the filter's own (revisable) counters; of a
// vision result, those of the part the fault altered (markers or VO).
std::uint32_t acceptedOf(const NavCore& core, const InputSample& sample, InjectedFault kind) {
  auto acc = [&core](NavSource s) -> std::uint32_t { return core.ekf().health(s).counters.accepted; };
  return std::visit(Overloaded{[](const ImuSample&) -> std::uint32_t { return 0; },
                               [&](const DvlSample&) { return acc(kSrcDvl); },
                               [&](const HeadingSample&) { return acc(kSrcHeading); },
                               [&](const AttitudeSample&) { return acc(kSrcAttitude); },
                               [&](const DepthSample&) { return acc(kSrcDepth); },
                               [&](const VisionResult&) {
                                 return kind == InjectedFault::kMarkerOutlier ? acc(kSrcMarkers)
                                                                              : acc(kSrcVoOrb) + acc(kSrcVoPlanes);
                               }},
                    sample);
}

// The values of a navigation-sensor sample the fault suite compares (InputRecord::value).
Eigen::Vector3d recordedValue(const InputSample& sample) {
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  std::visit(Overloaded{[](const ImuSample&) {},
                        [&v](const DvlSample& m) { v = m.v_dvl_mps; },
                        [&v](const HeadingSample& m) { v.x() = m.heading_rad; },
                        [&v](const AttitudeSample& m) { v.head<2>() << m.roll_rad, m.pitch_rad; },
                        [&v](const DepthSample& m) { v.x() = m.depth_m; },
                        [](const VisionResult&) {}},
             sample);
  return v;
}

// A 6x6 or 3x3 "covariance" that is not one.
template <typename M>
void setBadMatrix(CovarianceValue value, double bad, M* cov) {
  switch (value) {
    case CovarianceValue::kNan:
    case CovarianceValue::kInf:
    case CovarianceValue::kHuge:
      cov->setConstant(0.0);
      cov->diagonal().setConstant(bad);
      if (value != CovarianceValue::kHuge) (*cov)(0, 1) = (*cov)(1, 0) = bad;
      break;
    case CovarianceValue::kNegative:
      *cov = -cov->cwiseAbs();
      cov->diagonal().setConstant(-1e-4);
      break;
    case CovarianceValue::kIndefinite:
      cov->diagonal() = cov->diagonal().cwiseAbs().cwiseMax(1e-6);
      (*cov)(0, 1) = (*cov)(1, 0) = 10.0 * std::sqrt((*cov)(0, 0) * (*cov)(1, 1));
      break;
  }
}

}  // namespace

ReplayFaultInjector::ReplayFaultInjector(const InjectedFaultSpec& spec)
    : spec_(spec), rng_state_(spec.seed * 0x9E3779B97F4A7C15ull + 1) {}

double ReplayFaultInjector::randomSign() {
  // xorshift64*: enough for signs, and the same on every machine.
  rng_state_ ^= rng_state_ >> 12;
  rng_state_ ^= rng_state_ << 25;
  rng_state_ ^= rng_state_ >> 27;
  return ((rng_state_ * 0x2545F4914F6CDD1Dull) >> 63) ? 1.0 : -1.0;
}

bool ReplayFaultInjector::hits(TimeUs t_us) {
  if (spec_.kind == InjectedFault::kNone) return false;
  const double t_s = usToS(t_us);
  if (t_s < spec_.t_start_s || t_s >= spec_.t_end_s) return false;
  return eligible_++ % static_cast<std::uint64_t>(std::max(1, spec_.every_n)) == 0;
}

double ReplayFaultInjector::badValue() const {
  switch (spec_.value) {
    case CovarianceValue::kNan: return std::numeric_limits<double>::quiet_NaN();
    case CovarianceValue::kInf: return std::numeric_limits<double>::infinity();
    case CovarianceValue::kNegative:
    case CovarianceValue::kIndefinite: return -0.05;
    case CovarianceValue::kHuge: return kHugeSigma;
  }
  return 0.0;
}

void ReplayFaultInjector::consumeCounted(const InputSample& sample, NavCore* core) {
  ++counters_.injected;
  const std::uint32_t before = acceptedOf(*core, sample, spec_.kind);
  consumeRecorded(sample, core);
  if (acceptedOf(*core, sample, spec_.kind) > before) ++counters_.accepted_injected;
}

void ReplayFaultInjector::consumeRecorded(const InputSample& sample, NavCore* core) {
  const InputKind kind = inputKind(sample);
  if (kind == InputKind::kImu || kind == InputKind::kVision) return core->consume(sample);
  InputRecord r;
  r.kind = kind;
  r.t_us = sampleTimeUs(sample);
  r.value = recordedValue(sample);
  const std::uint32_t before = acceptedOf(*core, sample, spec_.kind);
  core->consume(sample);
  r.accepted = acceptedOf(*core, sample, spec_.kind) > before;
  inputs_.push_back(r);
}

InputSample ReplayFaultInjector::withBadCovariance(const InputSample& sample) const {
  InputSample out = sample;
  const double bad = spec_.value == CovarianceValue::kHuge ? kHugeVariance : badValue();
  switch (spec_.target) {
    case CovarianceTarget::kDvl:
      if (auto* m = std::get_if<DvlSample>(&out)) {
        setBadMatrix(spec_.value, bad, &m->cov_v_dvl_mps2);
        if (spec_.value != CovarianceValue::kIndefinite) m->fom_mps = badValue();
      }
      break;
    case CovarianceTarget::kDepth:
      if (auto* m = std::get_if<DepthSample>(&out)) m->sigma_m = badValue();
      break;
    case CovarianceTarget::kHeading:
      if (auto* m = std::get_if<HeadingSample>(&out)) m->sigma_rad = badValue();
      break;
    case CovarianceTarget::kAttitude:
      if (auto* m = std::get_if<AttitudeSample>(&out)) m->sigma_rad = badValue();
      break;
    case CovarianceTarget::kVo:
      if (auto* v = std::get_if<VisionResult>(&out)) {
        if (v->vo_orb.valid) setBadMatrix(spec_.value, bad, &v->vo_orb.cov);
        if (v->vo_planes.valid) setBadMatrix(spec_.value, bad, &v->vo_planes.cov);
      }
      break;
  }
  return out;
}

VisionResult ReplayFaultInjector::withOutliers(const VisionResult& v) {
  VisionResult out = v;
  const double k = spec_.magnitude_sigma;
  auto kickVo = [&](VoMeasurement* vo) {
    if (!vo->valid) return;
    Eigen::Vector3d dp, dtheta;
    for (int i = 0; i < 3; ++i) {
      dp[i] = randomSign() * k * std::sqrt(std::max(0.0, vo->cov(i, i)));
      dtheta[i] = randomSign() * k * std::sqrt(std::max(0.0, vo->cov(3 + i, 3 + i)));
    }
    if (vo->has_translation) vo->p_camb_in_cama_m += dp;
    vo->q_cama_camb = (vo->q_cama_camb * expSo3Quat(dtheta)).normalized();
  };
  if (spec_.kind == InjectedFault::kVoOutlier) {
    kickVo(&out.vo_orb);
    kickVo(&out.vo_planes);
    return out;
  }
  for (int i = 0; i < out.marker_count && i < VisionResult::kMaxMarkers; ++i) {
    MarkerObservation& m = out.markers[static_cast<std::size_t>(i)];
    const double sigma = markerPoseSigmas(m, spec_.markers).position_m;
    // Across the line of sight on both image axes and along it: the marker is elsewhere in the panel.
    const Eigen::Vector3d d(randomSign(), randomSign(), randomSign());
    m.p_marker_in_cam_m += k * sigma * d;
    m.p_marker_in_cam_alt_m += k * sigma * d;
  }
  return out;
}

void ReplayFaultInjector::onVision(const VisionResult& v, NavCore* core) {
  const bool has_vo = v.vo_orb.valid || v.vo_planes.valid;
  switch (spec_.kind) {
    case InjectedFault::kVoOutlier:
      if (has_vo && hits(v.t_us)) return consumeCounted(withOutliers(v), core);
      break;
    case InjectedFault::kMarkerOutlier:
      if (v.marker_count > 0 && hits(v.t_us)) return consumeCounted(withOutliers(v), core);
      break;
    case InjectedFault::kBadCovariance:
      if (spec_.target == CovarianceTarget::kVo && has_vo && hits(v.t_us))
        return consumeCounted(withBadCovariance(v), core);
      break;
    case InjectedFault::kVisionDelay:
      if (hits(v.t_us)) {
        ++counters_.injected;
        held_.push_back({last_tick_us_ + static_cast<TimeUs>(std::llround(spec_.delay_ms * 1e3)), v});
        return;
      }
      break;
    case InjectedFault::kVisionReorder:
      if (!held_.empty()) {
        // The result after a held one arrives first, the held one right behind it.
        core->consume(v);
        core->consume(held_.front().result);
        held_.clear();
        ++counters_.released;
        return;
      }
      if (hits(v.t_us)) {
        ++counters_.injected;
        held_.push_back({std::numeric_limits<TimeUs>::max(), v});
        return;
      }
      break;
    case InjectedFault::kNone:
      break;
  }
  core->consume(v);
}

void ReplayFaultInjector::onInput(const InputSample& sample, NavCore* core) {
  if (const auto* v = std::get_if<VisionResult>(&sample)) return onVision(*v, core);
  if (spec_.kind != InjectedFault::kBadCovariance || spec_.target == CovarianceTarget::kVo) {
    consumeRecorded(sample, core);
    return;
  }
  const bool targeted = [&] {
    switch (spec_.target) {
      case CovarianceTarget::kDvl: return std::holds_alternative<DvlSample>(sample);
      case CovarianceTarget::kDepth: return std::holds_alternative<DepthSample>(sample);
      case CovarianceTarget::kHeading: return std::holds_alternative<HeadingSample>(sample);
      case CovarianceTarget::kAttitude: return std::holds_alternative<AttitudeSample>(sample);
      case CovarianceTarget::kVo: return false;
    }
    return false;
  }();
  if (targeted && hits(sampleTimeUs(sample))) return consumeCounted(withBadCovariance(sample), core);
  consumeRecorded(sample, core);
}

void ReplayFaultInjector::beforeTick(TimeUs t_us, NavCore* core) {
  last_tick_us_ = t_us;
  if (spec_.kind != InjectedFault::kVisionDelay) return;
  // Held results are due in arrival order (all were delayed by the same amount).
  std::size_t n = 0;
  while (n < held_.size() && held_[n].due_us <= t_us) {
    core->consume(held_[n].result);
    ++counters_.released;
    ++n;
  }
  held_.erase(held_.begin(), held_.begin() + static_cast<std::ptrdiff_t>(n));
}

void ReplayFaultInjector::afterTick(const NavSolution& s, const NavCore& /*core*/) {
  TickRecord r;
  r.t_us = s.t_us;
  r.p_robot_in_odom_m = s.p_robot_in_odom_m;
  r.q_odom_robot = s.q_odom_robot;
  r.status = s.status;
  r.faults = s.faults;
  r.position_sigma_m = std::sqrt(std::max(s.cov_pose(0, 0), s.cov_pose(1, 1)));
  r.finite = isFinite(s);
  r.aligned = s.stage != NavStage::kInit;
  ticks_.push_back(r);
}

}  // namespace deepnav
