#pragma once
#include <cstdint>
#include <optional>
#include <string_view>

#include "tools/sim/sim_stream.h"

namespace deepnav::sim {

enum class FaultKind : std::uint8_t {
  kDropout = 0,   // samples are not emitted (with `probability`)
  kOutlier,       // each component gets +-magnitude_sigma * the stream's noise sigma (with `probability`)
  kStuck,         // the last emitted value is repeated with fresh time stamps
  kTimeJitter,    // the stamp moves by N(0, std_ms), clamped to +-4 std; the content stays at the true time
  kGarbage,       // each component replaced by a uniform random value over the sensor's range (with
                  // `probability`); camera: both images replaced by uniform noise
  kSlow,          // only one sample in `divisor` is emitted (the stream's rate divided)
  kIntermittent,  // bursts: emitted for `on_s`, silent for `off_s`, repeating from t_start_s
  kClockJump,     // the stamp is offset by `offset_ms` (the sensor's clock jumped); the content stays true
};

// "dropout", "outlier", "stuck", "time_jitter", "garbage", "slow", "intermittent", "clock_jump"
std::string_view faultKindName(FaultKind kind);
std::optional<FaultKind> faultKindFromName(std::string_view name);

// One entry of the scenario's `faults` list, active for nominal sample times in [t_start_s, t_end_s).
struct FaultSpec {
  SimStream stream = SimStream::kImu;
  FaultKind kind = FaultKind::kDropout;
  double t_start_s = 0.0;
  double t_end_s = 0.0;
  double probability = 1.0;       // dropout, outlier, garbage: chance that a sample in the window is hit
  double magnitude_sigma = 10.0;  // outlier: size in units of the stream's white-noise sigma
  double std_ms = 1.0;            // time_jitter: 1-sigma of the stamp error
  int divisor = 4;                // slow: one sample in `divisor` kept
  double on_s = 1.0;              // intermittent: length of a burst of samples
  double off_s = 1.0;             // intermittent: length of a silence
  double offset_ms = 1000.0;      // clock_jump: stamp offset (positive: stamped later than true)

  bool operator==(const FaultSpec&) const = default;
};

}  // namespace deepnav::sim
