#include "tools/sim/render/water_optics.h"

#include <cmath>

namespace deepnav::sim {

// Attenuation coefficients: clear is of the order of Jerlov's open-ocean types, moderate of coastal
// water, murky of a sediment plume (red attenuated most). Lamp power (with the fixed exposure) is set so
// that white paint at the dive's dwell distance (the cameras are 0.9 m from the face: standoff 1.5 m
// minus the 0.6 m camera lever arm) sits just below full scale in clear and moderate water, about half
// of it in murky water, where the backscatter veil then takes most of the contrast.
WaterOptics waterOptics(WaterPreset preset) {
  WaterOptics w;
  switch (preset) {
    case WaterPreset::kClear:
      w.attenuation_per_m = {0.06f, 0.08f, 0.40f};
      w.backscatter = {0.004f, 0.005f, 0.001f};
      w.lamp_intensity = 0.5f;
      w.read_noise = 0.0015f;
      w.shot_noise = 2.0e-4f;
      break;
    case WaterPreset::kModerate:
      w.attenuation_per_m = {0.40f, 0.35f, 0.70f};
      w.backscatter = {0.025f, 0.030f, 0.008f};
      w.lamp_intensity = 0.87f;
      w.read_noise = 0.0025f;
      w.shot_noise = 3.0e-4f;
      break;
    case WaterPreset::kMurky:
      w.attenuation_per_m = {1.50f, 1.40f, 1.80f};
      w.backscatter = {0.13f, 0.15f, 0.06f};
      w.lamp_intensity = 2.7f;
      w.read_noise = 0.004f;
      w.shot_noise = 6.0e-4f;
      break;
  }
  return w;
}

double henyeyGreensteinBackscatterRatio(double g) {
  // The integral of p over the backward hemisphere, 2 pi int_{-1}^{0} p(mu) dmu, in closed form.
  if (g == 0.0) return 0.5;
  return (1.0 - g) / (2.0 * g) * ((1.0 + g) / std::sqrt(1.0 + g * g) - 1.0);
}

WaterEffects waterEffects(const WaterConfig& config, const WaterOptics& optics) {
  WaterEffects e;
  e.beam = LampBeam::fromHalfAngle(config.lamp_beam_half_angle_deg);
  e.lamp_backscatter = config.lamp_backscatter;
  e.plumes = !config.plumes.empty();
  e.phase.g = static_cast<float>(config.phase_g);
  e.scattering_albedo = static_cast<float>(config.scattering_albedo);
  e.forward_scatter_rad_per_m = static_cast<float>(1e-3 * config.forward_scatter_mrad_per_m);
  const double forward = 1.0 - henyeyGreensteinBackscatterRatio(config.phase_g);
  for (int c = 0; c < 3; ++c) {
    e.scattering_per_m[c] = static_cast<float>(config.scattering_albedo * optics.attenuation_per_m[c]);
    e.forward_scatter_per_m[c] = static_cast<float>(forward * e.scattering_per_m[c]);
  }
  return e;
}

}  // namespace deepnav::sim
