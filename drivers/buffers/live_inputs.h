#pragma once
#include <cstddef>
#include <span>
#include <string>
#include <tuple>
#include <type_traits>
#include <variant>

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

// The ring capacity of each sensor kind: one row per ring of LiveInputs.
template <typename T>
std::size_t ringCapacity(const LiveInputCapacities& c) {
  if constexpr (std::is_same_v<T, ImuSample>) return c.imu;
  else if constexpr (std::is_same_v<T, DvlSample>) return c.dvl;
  else if constexpr (std::is_same_v<T, HeadingSample>) return c.heading;
  else if constexpr (std::is_same_v<T, AttitudeSample>) return c.attitude;
  else if constexpr (std::is_same_v<T, DepthSample>) return c.depth;
  else static_assert(!sizeof(T), "LiveInputCapacities: no capacity for this sample kind (docs/adding-a-sensor-kind.md)");
}

// The sensor rings, one per InputSample kind but the vision result (which the worker produces), in the
// loop's merge order: of samples with equal stamps, the earlier ring's is consumed first (the IMU's before
// the aiding sensors'). A new sensor kind is a new entry here (docs/adding-a-sensor-kind.md).
using LiveSensorRings = std::tuple<SpscRing<ImuSample>, SpscRing<DvlSample>, SpscRing<HeadingSample>,
                                   SpscRing<AttitudeSample>, SpscRing<DepthSample>>;

namespace live_inputs_detail {
template <typename T, typename Tuple>
struct HasRing;
template <typename T, typename... R>
struct HasRing<T, std::tuple<R...>> : std::bool_constant<(std::is_same_v<SpscRing<T>, R> || ...)> {};
}  // namespace live_inputs_detail

// True for a sample kind that has a ring in LiveSensorRings.
template <typename T>
inline constexpr bool kHasLiveRing = live_inputs_detail::HasRing<T, LiveSensorRings>::value;

// Everything drivers hand to the nav loop: one single-producer/single-consumer ring per sensor kind (each
// fed by one driver thread) and the stereo frame pool, whose filled slots travel by index to the vision
// worker. Allocated once at start-up; never resized.
class LiveInputs {
 public:
  FramePool pool;
  SpscRing<int> frames;  // filled pool slots, capture order

  // The ring of a sample kind, by type: a kind without a ring does not compile.
  template <typename T>
    requires kHasLiveRing<T>
  SpscRing<T>& ring() {
    return std::get<SpscRing<T>>(rings_);
  }

  // Calls f on every sensor ring, in the merge order above.
  template <typename F>
  void forEachSensorRing(F&& f) {
    std::apply([&f](auto&... ring) { (f(ring), ...); }, rings_);
  }
  template <typename F>
  void forEachSensorRing(F&& f) const {
    std::apply([&f](const auto&... ring) { (f(ring), ...); }, rings_);
  }

  bool allocate(const LiveInputCapacities& c) {
    bool ok = true;
    forEachSensorRing([&](auto& ring) {
      using T = typename std::decay_t<decltype(ring)>::value_type;
      ok = ok && ring.allocate(ringCapacity<T>(c));
    });
    return ok && pool.allocate(c.frames, c.width_px, c.height_px, c.channels) && frames.allocate(c.frames);
  }

 private:
  LiveSensorRings rings_;
};

namespace live_inputs_detail {
// True when every InputSample kind but the vision result has exactly one ring.
template <typename... T>
constexpr bool oneRingPerSensorKind(const std::variant<T...>*) {
  return ((std::is_same_v<T, VisionResult> || kHasLiveRing<T>) && ...) &&
         std::tuple_size_v<LiveSensorRings> + 1 == sizeof...(T);
}
}  // namespace live_inputs_detail
static_assert(live_inputs_detail::oneRingPerSensorKind(static_cast<const InputSample*>(nullptr)),
              "LiveInputs: one ring per sensor kind of InputSample (docs/adding-a-sensor-kind.md)");

}  // namespace deepnav
