#pragma once
#include <cstddef>
#include <span>
#include <string>
#include <type_traits>

#include "base/param_decl.h"
#include "drivers/buffers/frame_pool.h"
#include "drivers/buffers/spsc_ring.h"
#include "nav/types/input_sample.h"

namespace deepnav {

// Capacities of the live input buffers. The ring and pool sizes are the board's buffers.* keys
// (liveInputCapacityParams()); the frame size is the camera's (camera.width_px, height_px, channels), which the
// loop sets before allocating.
struct LiveInputCapacities {
  std::size_t imu = 512, dvl = 64, heading = 64, attitude = 64, depth = 64;  // samples
  std::size_t frames = 6;                                                    // stereo pairs in the pool
  int width_px = 688, height_px = 516, channels = 1;
};

// The board keys of the capacities (section kBuffersSection of a board file): unit, range and meaning,
// declared once; the defaults are the initialisers above.
inline constexpr const char* kBuffersSection = "buffers";
std::span<const ParamDecl<LiveInputCapacities>> liveInputCapacityParams();

// False with a message naming the field and the key when a capacity is outside its declared range.
bool validateLiveInputCapacities(const LiveInputCapacities& c, std::string* error);

// Everything drivers hand to the nav loop: one single-producer/single-consumer ring per sensor (each
// fed by one driver thread) and the stereo frame pool, whose filled slots travel by index to the vision
// worker. Allocated once at start-up; never resized.
struct LiveInputs {
  SpscRing<ImuSample> imu;
  SpscRing<DvlSample> dvl;
  SpscRing<HeadingSample> heading;
  SpscRing<AttitudeSample> attitude;
  SpscRing<DepthSample> depth;
  FramePool pool;
  SpscRing<int> frames;  // filled pool slots, capture order

  // The ring of a sample kind, by type: a kind without a ring does not compile.
  template <typename T>
  SpscRing<T>& ring() {
    if constexpr (std::is_same_v<T, ImuSample>) return imu;
    else if constexpr (std::is_same_v<T, DvlSample>) return dvl;
    else if constexpr (std::is_same_v<T, HeadingSample>) return heading;
    else if constexpr (std::is_same_v<T, AttitudeSample>) return attitude;
    else if constexpr (std::is_same_v<T, DepthSample>) return depth;
    else static_assert(!sizeof(T), "LiveInputs: no ring for this sample kind (docs/adding-a-sensor-kind.md)");
  }

  // Calls f on every sensor ring, in the loop's merge order: of samples with equal stamps, the earlier
  // ring's is consumed first (the IMU's before the aiding sensors').
  template <typename F>
  void forEachSensorRing(F&& f) {
    forEachRingOf(*this, f);
  }
  template <typename F>
  void forEachSensorRing(F&& f) const {
    forEachRingOf(*this, f);
  }

  bool allocate(const LiveInputCapacities& c) {
    return imu.allocate(c.imu) && dvl.allocate(c.dvl) && heading.allocate(c.heading) &&
           attitude.allocate(c.attitude) && depth.allocate(c.depth) &&
           pool.allocate(c.frames, c.width_px, c.height_px, c.channels) && frames.allocate(c.frames);
  }

 private:
  template <typename Self, typename F>
  static void forEachRingOf(Self& self, F& f) {
    f(self.imu);
    f(self.dvl);
    f(self.heading);
    f(self.attitude);
    f(self.depth);
  }
};

}  // namespace deepnav
