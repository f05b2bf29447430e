#pragma once
#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

#include "tools/sim/render/float4.h"
#include "tools/sim/render/water_optics.h"

namespace deepnav::sim {

// Forward-scatter blur growing with range. As in the Jaffe-McGlamery model (McGlamery 1980, "A computer
// model for underwater camera systems", Proc. SPIE 208; Jaffe 1990, "Computer modeling and the design of
// optimal underwater imaging systems", IEEE J. Oceanic Eng. 15(2)), the light reflected by a surface at
// range R reaches the camera partly unscattered and partly scattered through small angles, the latter
// spread by a point spread function whose width grows with R. Here the split keeps the renderer's
// surface radiance L_d (README: image formation) as the total of the two:
//   L = veil + exp(-b_f R) L_d + (1 - exp(-b_f R)) (G_sigma(R) * L_d),   sigma(R) = f_px k R
// with b_f = b (1 - b_b / b) the small-angle scattering coefficient (the probability of at least one
// forward scattering event over R is 1 - exp(-b_f R)), G_sigma a blur of sigma pixels and k the rms
// blur angle per metre of range (water.forward_scatter_mrad_per_m). The variable-width blur is a
// pyramid of 2 x 2 box reductions of L_d upsampled bilinearly: level l (a box of 2^l then a tent of 2^l)
// has an rms width of about 2^(l-1) pixels; a sigma between two levels blends them (levelOf), below 1 px
// L_d itself with level 1. Per row only the levels its pixels need are upsampled.
class ForwardScatter {
 public:
  static constexpr int kLevels = 5;  // sigma up to 16 px
  void init(int width_px, int height_px, int channels, float fx_px, const WaterEffects& effects);
  // direct: the surface radiance L_d per pixel (0 in open water); distance_m: the hit's distance per pixel
  // (0 = none); radiance (in, out): the view's total radiance, to which the blur's change is added.
  void apply(const float* direct, const float* distance_m, float* radiance);

  // The continuous pyramid level of a blur of sigma pixels: sigma below 1 px; else 1 + log2(sigma) with
  // the logarithm linear within each octave (the float's exponent plus its mantissa), so a sigma between
  // two levels' blends them by how far it lies between their sigmas.
  static float levelOf(float sigma_px) {
    if (sigma_px < 1.0f) return sigma_px;
    std::uint32_t bits;
    std::memcpy(&bits, &sigma_px, sizeof(bits));
    const int exponent = static_cast<int>(bits >> 23) - 127;
    const std::uint32_t mantissa_bits = (bits & 0x7FFFFFu) | 0x3F800000u;
    float mantissa;  // in [1, 2)
    std::memcpy(&mantissa, &mantissa_bits, sizeof(mantissa));
    return static_cast<float>(exponent) + mantissa;
  }
  // The same for four sigmas (lanes).
  static Float4 levelOf4(Float4 sigma_px) {
    const Int4 bits = reinterpret_cast<Int4>(sigma_px);
    const Float4 exponent = __builtin_convertvector((bits >> 23) - 127, Float4);
    const Float4 mantissa = reinterpret_cast<Float4>((bits & 0x7FFFFF) | 0x3F800000);
    return sigma_px < 1.0f ? sigma_px : exponent + mantissa;
  }

 private:
  struct Level {
    int width = 0, height = 0;
    std::vector<float> data;
    std::vector<float> wide;  // each row upsampled to the full width (bilinear), height x width x channels
  };
  void reduce(const float* in, int in_w, int in_h, Level* out) const;
  void widen(int level);
  // Row v of level l (>= 1) upsampled to full resolution into out (width x channels).
  void upsampledRow(int level, int v, float* out) const;

  int width_ = 0, height_ = 0, channels_ = 1;
  float px_per_m_ = 0.0f;  // f_px k: sigma in pixels per metre of range
  float forward_grey_per_m_ = 0.0f;  // b_f of a grey image
  // 1 - exp(-b_f x) per channel (lanes; grey: green's) every kStep_m of range x.
  static constexpr float kStep_m = 0.01f;
  std::vector<Float4> scattered_;
  std::array<Level, kLevels + 1> levels_;  // [0] unused: level 0 is the input itself
  std::vector<float> level_map_;                      // per pixel: its level, -1 in open water
  std::vector<float> level_row_, blurred_row_, tent_;  // per row scratch
};

}  // namespace deepnav::sim
