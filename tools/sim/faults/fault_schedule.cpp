#include "tools/sim/faults/fault_schedule.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace deepnav::sim {

namespace {
constexpr std::array<std::string_view, 8> kKindNames{"dropout", "outlier", "stuck",        "time_jitter",
                                                     "garbage", "slow",    "intermittent", "clock_jump"};
constexpr double kJitterClampSigma = 4.0;

bool validParams(const FaultSpec& f) {
  return f.probability >= 0.0 && f.probability <= 1.0 && f.std_ms >= 0.0 && f.divisor >= 1 && f.on_s > 0.0 &&
         f.off_s >= 0.0 && std::isfinite(f.offset_ms);
}

// Intermittent: silent in the second part of each (on + off) period counted from the window's start.
bool inSilence(const FaultSpec& f, double t_s) {
  const double period = f.on_s + f.off_s;
  return std::fmod(t_s - f.t_start_s, period) >= f.on_s;
}
}  // namespace

std::string_view faultKindName(FaultKind kind) { return kKindNames[static_cast<int>(kind)]; }

std::optional<FaultKind> faultKindFromName(std::string_view name) {
  for (std::size_t i = 0; i < kKindNames.size(); ++i)
    if (kKindNames[i] == name) return static_cast<FaultKind>(i);
  return std::nullopt;
}

bool FaultSchedule::init(const std::vector<FaultSpec>& faults, std::string* error) {
  faults_ = faults;
  max_jitter_us_ = 0;
  for (std::size_t i = 0; i < faults.size(); ++i) {
    const FaultSpec& f = faults[i];
    if (!(f.t_end_s > f.t_start_s) || f.stream == SimStream::kGroundTruth || !validParams(f)) {
      if (error) *error = "faults[" + std::to_string(i) + "]: invalid window, stream or parameter";
      return false;
    }
    // Overlapping shifts add.
    if (f.kind == FaultKind::kTimeJitter)
      max_jitter_us_ += static_cast<TimeUs>(std::ceil(kJitterClampSigma * f.std_ms * 1e3));
    if (f.kind == FaultKind::kClockJump) max_jitter_us_ += static_cast<TimeUs>(std::ceil(std::abs(f.offset_ms) * 1e3));
  }
  return true;
}

FaultDecision FaultSchedule::decide(SimStream stream, double t_s, std::uint64_t index, NormalRng& rng) const {
  FaultDecision d;
  for (const FaultSpec& f : faults_) {
    if (f.stream != stream || t_s < f.t_start_s || t_s >= f.t_end_s) continue;
    switch (f.kind) {
      case FaultKind::kDropout:
        if (rng.uniform() <= f.probability) d.drop = true;
        break;
      case FaultKind::kOutlier:
        if (rng.uniform() <= f.probability) d.outlier_sigma = std::max(d.outlier_sigma, f.magnitude_sigma);
        break;
      case FaultKind::kStuck:
        d.stuck = true;
        break;
      case FaultKind::kTimeJitter: {
        const double clamp_ms = kJitterClampSigma * f.std_ms;
        const double jitter_ms = std::clamp(rng.normal(f.std_ms), -clamp_ms, clamp_ms);
        d.jitter_us += static_cast<TimeUs>(std::llround(jitter_ms * 1e3));
        break;
      }
      case FaultKind::kGarbage:
        if (rng.uniform() <= f.probability) d.garbage = true;
        break;
      case FaultKind::kSlow:
        if (index % static_cast<std::uint64_t>(f.divisor) != 0) d.drop = true;
        break;
      case FaultKind::kIntermittent:
        if (inSilence(f, t_s)) d.drop = true;
        break;
      case FaultKind::kClockJump:
        d.clock_offset_us += static_cast<TimeUs>(std::llround(f.offset_ms * 1e3));
        break;
    }
  }
  return d;
}

}  // namespace deepnav::sim
