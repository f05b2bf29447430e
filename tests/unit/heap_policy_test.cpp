#include "drivers/realtime/heap_policy.h"

#include <malloc.h>

#include <cstdlib>
#include <cstring>

#include <gtest/gtest.h>

namespace deepnav {
namespace {

// Number of blocks glibc currently serves from their own mapping (mallinfo2().hblks).
std::size_t mappedBlocks() { return mallinfo2().hblks; }

// malloc, write, and let the pointer escape: without the escape GCC elides a malloc/memset/free sequence.
void* touched(std::size_t bytes) {
  void* p = std::malloc(bytes);
  std::memset(p, 1, bytes);
  asm volatile("" : : "g"(p) : "memory");
  return p;
}

// ctest runs each test in its own process, so changing this process's allocator policy touches no other test.
TEST(HeapPolicy, ImageSizedBlocksStayMappedAfterALargerOneIsFreed) {
  // GIVEN the policy fixed (a sanitizer's allocator does not take it)
  if (!fixHeapPolicy()) GTEST_SKIP() << "the allocator of this build ignores mallopt";
  // WHEN an 8 MiB block is freed (glibc's dynamic rule would raise the threshold to 8 MiB here)
  std::free(touched(8u << 20));
  // THEN a 355 KiB block (one 688x516 grey image) is still its own mapping, and its free returns it
  const std::size_t before = mappedBlocks();
  void* image = touched(688u * 516u);
  EXPECT_EQ(mappedBlocks(), before + 1);
  std::free(image);
  EXPECT_EQ(mappedBlocks(), before);
  // AND a small object stays in the arena
  void* small = touched(4096);
  EXPECT_EQ(mappedBlocks(), before);
  std::free(small);
}

}  // namespace
}  // namespace deepnav
