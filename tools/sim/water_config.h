#pragma once
#include <cstdint>
#include <optional>
#include <string_view>

namespace deepnav::sim {

// Turbidity preset for the stereo renderer (the sensor models ignore it).
enum class WaterPreset : std::uint8_t { kClear = 0, kModerate, kMurky };

std::string_view waterPresetName(WaterPreset preset);  // "clear", "moderate", "murky"
std::optional<WaterPreset> waterPresetFromName(std::string_view name);

// Scenario key `water`. The renderer's optics per preset: tools/sim/render/water_optics.h.
struct WaterConfig {
  WaterPreset preset = WaterPreset::kModerate;
  int fish_count = 0;  // fish (small ellipsoids) swimming around the panel, for the renderer; [0, 50]

  bool operator==(const WaterConfig&) const = default;
};

}  // namespace deepnav::sim
