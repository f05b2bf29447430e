#include "tools/sim/render/water_optics.h"

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

}  // namespace deepnav::sim
