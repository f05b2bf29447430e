// The default ImuConfig must keep producing the stream it produced before the sea-grade error terms
// (Gauss-Markov bias, scale factor, misalignment, lever arm, vibration) were added: every new term is off
// by default and draws from its own sub-stream. The hash below was recorded with the model of commit
// c8fce7c (before those terms existed).
#include <cmath>
#include <cstdint>
#include <cstring>

#include <gtest/gtest.h>

#include "tools/sim/sensors/imu_model.h"
#include "tests/support/x86_64_reference.h"

namespace deepnav::sim {
namespace {

// A moving robot (rates and specific force varying on every axis), so any change to how the truth is
// mapped into the measurement shows up, not only the noise.
KinematicState movingState(int k) {
  const double t_s = 0.01 * k;
  KinematicState s;
  s.t_s = t_s;
  s.w_robot_radps = {0.1 * std::sin(0.7 * t_s), 0.05 * std::cos(1.3 * t_s), 0.2 * std::sin(0.3 * t_s + 1.0)};
  s.f_robot_mps2 = {0.3 * std::cos(0.5 * t_s), 0.2 * std::sin(0.9 * t_s), 9.80665 + 0.1 * std::sin(2.1 * t_s)};
  return s;
}

// FNV-1a over the bytes of every double: any bit that changes changes the hash.
void mix(std::uint64_t* h, double value) {
  unsigned char bytes[sizeof(double)];
  std::memcpy(bytes, &value, sizeof(double));
  for (unsigned char b : bytes) {
    *h ^= b;
    *h *= 1099511628211ULL;
  }
}

std::uint64_t hashDefaultStream(std::uint64_t seed, int samples) {
  ImuModel imu;
  std::string error;
  EXPECT_TRUE(imu.init(ImuConfig{}, seed, &error)) << error;
  std::uint64_t h = 14695981039346656037ULL;
  for (int k = 0; k < samples; ++k) {
    const ImuSample s = imu.measure(movingState(k), k * 10000);
    for (int i = 0; i < 3; ++i) mix(&h, s.w_imu_radps[i]);
    for (int i = 0; i < 3; ++i) mix(&h, s.f_imu_mps2[i]);
    for (int i = 0; i < 3; ++i) mix(&h, imu.gyroBias_radps()[i]);
    for (int i = 0; i < 3; ++i) mix(&h, imu.accelBias_mps2()[i]);
  }
  return h;
}

TEST(SimImuDefaultStream, DefaultConfigStreamIsBitIdenticalToBeforeTheGrades) {
  DEEPNAV_SKIP_UNLESS_X86_64_REFERENCE();
  EXPECT_EQ(hashDefaultStream(1, 5000), 0x7794a81c773ccc72ULL);
  EXPECT_EQ(hashDefaultStream(0x5eed, 5000), 0x5ff254b7583288d8ULL);
}

}  // namespace
}  // namespace deepnav::sim
