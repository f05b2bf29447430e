#include "tools/sim/normal_rng.h"

#include <cmath>
#include <numbers>

namespace deepnav::sim {

std::uint64_t NormalRng::subSeed(std::uint64_t seed, std::uint64_t stream_id) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (stream_id + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

double NormalRng::uniform() {
  constexpr double kTwoPowMinus53 = 1.0 / 9007199254740992.0;
  return static_cast<double>((engine_() >> 11) + 1) * kTwoPowMinus53;
}

double NormalRng::normal() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  const double radius = std::sqrt(-2.0 * std::log(uniform()));
  const double angle = 2.0 * std::numbers::pi * uniform();
  spare_ = radius * std::sin(angle);
  has_spare_ = true;
  return radius * std::cos(angle);
}

}  // namespace deepnav::sim
