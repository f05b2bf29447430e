#pragma once
#include <array>

#include "tools/sim/render/lamp_beam.h"
#include "tools/sim/water_config.h"

namespace deepnav::sim {

// Optics of one turbidity preset, per colour channel in BGR order (the order of the images). Radiances
// are in linear sensor units: 1 = full scale of the sensor before the camera's tone curve.
// The image formation using them is written out in tools/sim/render/README.md.
struct WaterOptics {
  std::array<float, 3> attenuation_per_m{};  // beta_c: beam attenuation (absorption + scattering), 1/m
  std::array<float, 3> backscatter{};        // B_inf_c: veiling light of an infinitely long water path
  float lamp_intensity = 1.0f;  // per lamp: radiance of a white Lambertian surface 1 m in front of it (m^2)
  float read_noise = 0.002f;    // sensor read noise sigma, linear full-scale units
  float shot_noise = 2.5e-4f;   // shot noise: variance = shot_noise * signal (1 / full-well electrons)
};

// clear: open-ocean water at depth, the panel crisp at 1.5 m and dimly visible from 8 m.
// moderate: coastal water, a veil over everything beyond 2 m.
// murky: sediment in suspension, the panel readable at 1 m, hazy at 1.5 m, gone at 3 m; the camera
// gain is up, so more noise.
WaterOptics waterOptics(WaterPreset preset);

// The deep-sea image formation terms of the scenario's water keys (all off by default), in the units the
// renderer uses (README: deep-sea image formation).
struct WaterEffects {
  LampBeam beam;                  // the lamps' cut-off (none: the cosine beam)
  bool lamp_backscatter = false;  // single scattering of the lamps' light instead of the uniform veil
  bool plumes = false;            // sediment plumes in the scenario
  HenyeyGreenstein phase;
  float scattering_albedo = 0.8f;
  std::array<float, 3> scattering_per_m{};     // b_c = albedo beta_c
  float forward_scatter_rad_per_m = 0.0f;      // rms blur angle per metre of range; 0 = no blur
  std::array<float, 3> forward_scatter_per_m{};  // b_c (1 - b_b / b): small-angle scattering
  bool column() const { return lamp_backscatter || plumes; }
  bool any() const { return beam.cut_off || column() || forward_scatter_rad_per_m > 0.0f; }
};
WaterEffects waterEffects(const WaterConfig& config, const WaterOptics& optics);
// The backscattered fraction b_b / b of the Henyey-Greenstein phase function with asymmetry g.
double henyeyGreensteinBackscatterRatio(double g);

}  // namespace deepnav::sim
