#include "drivers/buffers/frame_pool.h"

#include <gtest/gtest.h>

namespace deepnav {
namespace {

TEST(FramePool, SlotsAreReusedOnlyWhenEveryReferenceIsReleased) {
  FramePool pool;
  ASSERT_TRUE(pool.allocate(2, 688, 516, 1));
  EXPECT_EQ(pool.frame(0).left.cols, 688);
  EXPECT_EQ(pool.frame(0).right.rows, 516);
  const int a = pool.acquire();
  const int b = pool.acquire();
  ASSERT_GE(a, 0);
  ASSERT_GE(b, 0);
  EXPECT_NE(a, b);
  EXPECT_EQ(pool.acquire(), -1);  // exhausted: the driver drops the new pair
  EXPECT_EQ(pool.exhausted(), 1u);
  pool.addRef(a);   // recorder holds it too
  pool.release(a);  // vision done
  EXPECT_EQ(pool.acquire(), -1);
  pool.release(a);  // recorder done
  EXPECT_EQ(pool.acquire(), a);
}

TEST(FramePool, ImagesKeepTheirBuffersAcrossUse) {
  FramePool pool;
  ASSERT_TRUE(pool.allocate(3, 64, 32, 3));
  const uchar* data = pool.frame(1).left.data;
  EXPECT_EQ(pool.frame(1).left.type(), CV_8UC3);
  EXPECT_EQ(data, pool.frame(1).left.data);
  EXPECT_FALSE(pool.allocate(0, 64, 32, 1));
  EXPECT_FALSE(pool.allocate(1, 64, 32, 2));
}

}  // namespace
}  // namespace deepnav
