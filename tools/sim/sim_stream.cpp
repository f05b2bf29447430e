#include "tools/sim/sim_stream.h"

#include <array>

namespace deepnav::sim {

namespace {
constexpr std::array<std::string_view, kSimStreamCount> kNames{"ground_truth", "imu", "dvl", "compass",
                                                                "attitude", "depth", "camera"};
}  // namespace

std::string_view streamName(SimStream stream) {
  const int i = static_cast<int>(stream);
  return i >= 0 && i < kSimStreamCount ? kNames[i] : std::string_view("unknown");
}

std::optional<SimStream> streamFromName(std::string_view name) {
  for (int i = 0; i < kSimStreamCount; ++i)
    if (kNames[i] == name) return static_cast<SimStream>(i);
  return std::nullopt;
}

}  // namespace deepnav::sim
