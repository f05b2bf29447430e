#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace deepnav::sim {

// Turbidity preset for the stereo renderer (the sensor models ignore it).
enum class WaterPreset : std::uint8_t { kClear = 0, kModerate, kMurky };

std::string_view waterPresetName(WaterPreset preset);  // "clear", "moderate", "murky"
std::optional<WaterPreset> waterPresetFromName(std::string_view name);

// One sediment plume raised from the seabed (key `water.plumes[i]`): a Gaussian cloud of extra beam
// attenuation centred on the seabed, appearing at t_start_s (ramping up over rise_s), growing, drifting
// with the horizontal current and settling out (tools/sim/render/sediment_plume.h).
struct SedimentPlumeConfig {
  double t_start_s = 0.0;                          // when the sediment is raised, s of the dive
  std::array<double, 2> centre_in_odom_m{0.0, 0.0};  // east, north; on the seabed
  double radius_m = 0.5;                           // horizontal Gaussian sigma at the start
  double height_m = 0.4;                           // vertical sigma above the seabed at the start
  double growth_mps = 0.02;                        // growth of the horizontal sigma
  double attenuation_per_m = 3.0;                  // extra beam attenuation at the centre at the start, 1/m
  double rise_s = 10.0;                            // ramp-up time of the cloud
  double decay_s = 120.0;                          // e-folding time of the settling out

  bool operator==(const SedimentPlumeConfig&) const = default;
};

// Scenario key `water`. The renderer's optics per preset: tools/sim/render/water_optics.h. Every deep-sea
// image formation term below is off by default (the renders of the default scenarios stay as they were).
struct WaterConfig {
  WaterPreset preset = WaterPreset::kModerate;
  int fish_count = 0;  // fish (small ellipsoids) swimming around the panel, for the renderer; [0, 50]

  // The vehicle's two lamps, in the left camera frame: outside each camera, above and ahead of the
  // optical centres; beam: cosine pattern cut off at beam_half_angle_deg (90 = the plain cosine beam).
  double lamp_outside_m = 0.25;
  double lamp_above_m = 0.20;
  double lamp_forward_m = 0.0;
  double lamp_beam_half_angle_deg = 90.0;
  // Backscatter as single scattering of the lamps' light along each ray (lamp position, beam pattern and
  // phase function) instead of the uniform veil B_inf (1 - exp(-beta d)).
  bool lamp_backscatter = false;
  double scattering_albedo = 0.8;  // b / c, single-scattering albedo of the particles
  double phase_g = 0.924;          // Henyey-Greenstein asymmetry (b_b / b = 0.017, Petzold's 0.018)
  // Water current in the odometry frame (east, north, up): drifts marine snow and plumes.
  std::array<double, 3> current_mps{0.0, 0.0, 0.0};
  // Marine snow: particles per m^3 (0 = none), diameters drawn log-uniformly in the range, sinking speed.
  double snow_density_per_m3 = 0.0;
  std::array<double, 2> snow_diameter_mm{0.5, 3.0};
  double snow_sink_mps = 5.8e-4;  // 50 m/day
  double snow_albedo = 0.5;
  // Forward-scatter blur: rms angular spread of the small-angle scattered image light per metre of range
  // (0 = none).
  double forward_scatter_mrad_per_m = 0.0;
  std::vector<SedimentPlumeConfig> plumes;

  bool operator==(const WaterConfig&) const = default;
};

}  // namespace deepnav::sim
