#include "tools/sim/normal_rng.h"

#include <vector>

#include <gtest/gtest.h>

#include "sim_test_stats.h"

namespace deepnav::sim {
namespace {

TEST(SimNormalRng, IsStandardNormal) {
  NormalRng rng(123);
  std::vector<double> x;
  for (int i = 0; i < 100000; ++i) x.push_back(rng.normal());
  EXPECT_NEAR(test::mean(x), 0.0, 0.015);
  EXPECT_NEAR(test::stddev(x), 1.0, 0.01);
}

TEST(SimNormalRng, UniformIsInTheOpenClosedUnitInterval) {
  NormalRng rng(5);
  for (int i = 0; i < 100000; ++i) {
    const double u = rng.uniform();
    ASSERT_GT(u, 0.0);
    ASSERT_LE(u, 1.0);
  }
}

TEST(SimNormalRng, SameSeedSameNumbersAndSubSeedsDiffer) {
  NormalRng a(42), b(42), c(43);
  for (int i = 0; i < 100; ++i) {
    const double va = a.normal();
    EXPECT_EQ(va, b.normal());
    EXPECT_NE(va, c.normal());
  }
  EXPECT_NE(NormalRng::subSeed(1, 1), NormalRng::subSeed(1, 2));
  EXPECT_NE(NormalRng::subSeed(1, 1), NormalRng::subSeed(2, 1));
}

TEST(SimNormalRng, UniformIsBuiltFromTheStandardEngineOutput) {
  // The C++ standard fixes the 10000th output of a default-seeded (5489) mt19937_64; the uniform is its
  // top 53 bits, plus one, over 2^53. So the stream is the same with any conforming library.
  NormalRng rng(5489);
  for (int i = 0; i < 9999; ++i) rng.uniform();
  const double expected = static_cast<double>((9981545732273789042ull >> 11) + 1) / 9007199254740992.0;
  EXPECT_EQ(rng.uniform(), expected);
}

}  // namespace
}  // namespace deepnav::sim
