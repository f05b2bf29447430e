#include "drivers/buffers/spsc_ring.h"

#include <thread>

#include <gtest/gtest.h>

namespace deepnav {

TEST(SpscRing, RefusesWhenFullAndKeepsOldSamples) {
  SpscRing<int> ring;
  ASSERT_TRUE(ring.allocate(3));  // rounded to 4
  EXPECT_EQ(ring.capacity(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(ring.push(i));
  EXPECT_FALSE(ring.push(99));
  EXPECT_EQ(ring.dropped(), 1u);
  int v = -1;
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(ring.tryPop(v));
    EXPECT_EQ(v, i);
  }
  EXPECT_FALSE(ring.tryPop(v));
}

TEST(SpscRing, UnallocatedRingRefusesPush) {
  SpscRing<int> ring;
  EXPECT_FALSE(ring.push(1));
  EXPECT_EQ(ring.front(), nullptr);
  EXPECT_FALSE(ring.allocate(0));
}

TEST(SpscRing, TwoThreadsDeliverEverySampleInOrder) {
  SpscRing<long> ring;
  ASSERT_TRUE(ring.allocate(64));
  constexpr long kCount = 200000;
  std::thread producer([&] {
    for (long i = 0; i < kCount;) {
      if (ring.push(i)) ++i;
    }
  });
  long expected = 0;
  long v = 0;
  while (expected < kCount) {
    if (ring.tryPop(v)) {
      ASSERT_EQ(v, expected);
      ++expected;
    }
  }
  producer.join();
  EXPECT_EQ(ring.size(), 0u);
}

}  // namespace deepnav
