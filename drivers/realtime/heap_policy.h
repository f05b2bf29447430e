#pragma once

namespace deepnav {

// The process's heap policy, fixed at start-up before any large buffer exists (call it first in main).
//
// glibc raises its mmap threshold each time a mapped block is freed (dynamic threshold, up to 32 MiB), so
// after the first image-sized buffer is released, later image-sized buffers (stereo frames, disparity and
// cloud buffers, OpenCV temporaries of the vision worker) come from the arenas instead of mmap. There they
// fragment the arenas and are never returned to the kernel: resident memory climbs in small steps over
// hours (measured, tools/soak/README.md: +2.3 MiB over 40 restarts of the runtime, and the dive peak never
// comes down). With the threshold fixed, every block of kMmapThresholdBytes or more is its own mapping,
// given back to the kernel when freed, and the arenas hold only small objects.
inline constexpr int kMmapThresholdBytes = 128 * 1024;

// Returns false when the allocator does not take the setting (a sanitizer's allocator, another libc); the
// process runs on with that allocator's own policy.
bool fixHeapPolicy();

}  // namespace deepnav
