#include "tools/sim/water_config.h"

#include <array>

namespace deepnav::sim {

namespace {
constexpr std::array<std::string_view, 3> kPresetNames{"clear", "moderate", "murky"};
}  // namespace

std::string_view waterPresetName(WaterPreset preset) { return kPresetNames[static_cast<int>(preset)]; }

std::optional<WaterPreset> waterPresetFromName(std::string_view name) {
  for (std::size_t i = 0; i < kPresetNames.size(); ++i)
    if (kPresetNames[i] == name) return static_cast<WaterPreset>(i);
  return std::nullopt;
}

}  // namespace deepnav::sim
