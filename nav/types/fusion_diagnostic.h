#pragma once
#include <array>
#include <cstdint>

#include "nav/types/nav_solution.h"
#include "nav/types/time.h"

namespace deepnav {

constexpr int kFusionMaxDim = 6;  // largest measurement (6-DoF pose)

// Why a measurement was or was not fused (the reason of one FusionDiagnostic).
enum class FusionReason : std::uint8_t {
  kFused = 0,        // passed the gate and fused
  kFusedDeweighted,  // fused with an inflated variance (compass suspected of magnetic disturbance)
  kGate,             // innovation test ratio > 1
  kUnusable,         // no innovation could be formed (geometry, S not positive definite)
  kBadInput,         // NaN, Inf, negative variance, invalid flag
  kFrozen,           // bit-identical to the previous samples of its source
  kLate,             // older than the delay window
  kMagDisturbance,   // compass refused: magnetic disturbance (mag_disturbance.h)
  kFutureStamp,      // stamped further ahead of the IMU clock than the delay window (a clock jump)
};

// One measurement's fusion, in the spirit of PX4's estimator_aid_src_* messages: what the filter saw
// (innovation, the diagonal of its covariance S = H P H^T + R, the test ratio) and what it did. Emitted at
// the first fusion of a measurement (a later re-fusion after a rewind, with the same decision, is not
// repeated). Measurements refused at the door carry dim 0.
struct FusionDiagnostic {
  TimeUs t_us = 0;                  // capture time of the measurement
  NavSource source = kSrcCount;
  FusionReason reason = FusionReason::kFused;
  std::uint8_t dim = 0;             // used entries of the arrays below
  std::uint8_t mag_state = 0;       // MagState of the compass after this sample (0 clean, 1 suspect, 2 disturbed)
  std::array<double, kFusionMaxDim> innovation{};           // measurement units (m, m/s, rad)
  std::array<double, kFusionMaxDim> innovation_variance{};  // diag of S, squared units
  double test_ratio = 0.0;          // <= 1 passes; infinity when unusable; 0 when not gated
};

}  // namespace deepnav
