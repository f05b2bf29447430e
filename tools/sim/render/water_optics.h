#pragma once
#include <array>

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

}  // namespace deepnav::sim
