#include "tools/sim/faults/fault_schedule.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace deepnav::sim {

namespace {
constexpr std::array<std::string_view, 4> kKindNames{"dropout", "outlier", "stuck", "time_jitter"};
constexpr double kJitterClampSigma = 4.0;
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
    if (!(f.t_end_s > f.t_start_s) || f.stream == SimStream::kGroundTruth ||
        !(f.probability >= 0.0 && f.probability <= 1.0) || !(f.std_ms >= 0.0)) {
      if (error) *error = "faults[" + std::to_string(i) + "]: invalid window, stream, probability or std_ms";
      return false;
    }
    if (f.kind == FaultKind::kTimeJitter)
      max_jitter_us_ += static_cast<TimeUs>(std::ceil(kJitterClampSigma * f.std_ms * 1e3));  // overlaps add
  }
  return true;
}

FaultDecision FaultSchedule::decide(SimStream stream, double t_s, NormalRng& rng) const {
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
    }
  }
  return d;
}

}  // namespace deepnav::sim
