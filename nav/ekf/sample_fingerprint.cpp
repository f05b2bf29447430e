#include "nav/ekf/sample_fingerprint.h"

#include <cstring>

namespace deepnav {
namespace {

constexpr std::uint64_t kFnvOffset = 14695981039346656037ull;
constexpr std::uint64_t kFnvPrime = 1099511628211ull;

std::uint64_t mix(std::uint64_t h, double v) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  for (int i = 0; i < 8; ++i) {
    h ^= (bits >> (8 * i)) & 0xffu;
    h *= kFnvPrime;
  }
  return h;
}

}  // namespace

std::uint64_t sampleFingerprint(const DvlSample& m) {
  return mix(mix(mix(kFnvOffset, m.v_dvl_mps.x()), m.v_dvl_mps.y()), m.v_dvl_mps.z());
}

std::uint64_t sampleFingerprint(const DepthSample& m) { return mix(mix(kFnvOffset, m.depth_m), m.pressure_pa); }

std::uint64_t sampleFingerprint(const HeadingSample& m) { return mix(kFnvOffset, m.heading_rad); }

std::uint64_t sampleFingerprint(const AttitudeSample& m) { return mix(mix(kFnvOffset, m.roll_rad), m.pitch_rad); }

std::uint64_t sampleFingerprint(const ImuSample& m) {
  std::uint64_t h = kFnvOffset;
  for (int i = 0; i < 3; ++i) h = mix(mix(h, m.w_imu_radps[i]), m.f_imu_mps2[i]);
  return h;
}

}  // namespace deepnav
