#pragma once
#include <cstdint>

namespace deepnav {

// One monotonic clock for the whole system, in microseconds. Drivers map every sensor clock onto it.
using TimeUs = std::int64_t;

constexpr TimeUs kUsPerS = 1'000'000;

constexpr double usToS(TimeUs t_us) { return static_cast<double>(t_us) * 1e-6; }
constexpr TimeUs sToUs(double t_s) { return static_cast<TimeUs>(t_s * 1e6 + (t_s >= 0 ? 0.5 : -0.5)); }

}  // namespace deepnav
