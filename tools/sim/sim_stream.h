#pragma once
#include <cstdint>
#include <optional>
#include <string_view>

namespace deepnav::sim {

// The simulator's output streams. The order is the tie-break for events stamped at the same microsecond.
enum class SimStream : std::uint8_t { kGroundTruth = 0, kImu, kDvl, kCompass, kAttitude, kDepth, kCamera, kCount };

constexpr int kSimStreamCount = static_cast<int>(SimStream::kCount);

// Name used in scenario files ("ground_truth", "imu", "dvl", "compass", "attitude", "depth", "camera").
std::string_view streamName(SimStream stream);
std::optional<SimStream> streamFromName(std::string_view name);

}  // namespace deepnav::sim
