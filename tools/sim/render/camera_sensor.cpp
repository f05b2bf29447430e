#include "tools/sim/render/camera_sensor.h"

#include <algorithm>
#include <cmath>

#include "tools/sim/normal_rng.h"
#include "tools/sim/render/float4.h"
#include "tools/sim/render/procedural_noise.h"

namespace deepnav::sim {

bool CameraSensor::init(int width_px, int height_px, int channels, const WaterOptics& optics, std::uint64_t seed) {
  if (width_px < 3 || height_px < 3 || (channels != 1 && channels != 3)) return false;
  width_ = width_px, height_ = height_px, channels_ = channels;
  read_var_ = optics.read_noise * optics.read_noise;
  shot_ = optics.shot_noise;
  blurred_rows_.assign(static_cast<std::size_t>(width_) * height_ * channels_, 0.0f);
  const std::size_t row = static_cast<std::size_t>(width_) * channels_;
  normals_.resize(std::max<std::size_t>(65536, 4 * row));
  NormalRng rng(NormalRng::subSeed(seed, 0x5E5502u));
  for (float& n : normals_) n = static_cast<float>(rng.normal());
  return true;
}

void CameraSensor::setSensor(SensorNoiseModel model, const CameraSensorConfig& sensor) {
  noise_model_ = model;
  sensor_ = sensor;
}

CameraSensor::Exposure CameraSensor::exposureFor(float gain) const {
  const double ref_s = 1e-3 * sensor_.exposure_ref_ms, max_s = 1e-3 * sensor_.exposure_max_ms;
  Exposure e;
  const double t_s = std::min(static_cast<double>(gain) * ref_s, max_s);
  e.time_s = static_cast<float>(t_s);
  e.analogue_gain = static_cast<float>(static_cast<double>(gain) * ref_s / t_s);
  return e;
}

float CameraSensor::autoExposureGain(const float* radiance) const {
  double sum = 0.0;
  std::size_t n = 0;
  const std::size_t count = static_cast<std::size_t>(width_) * height_ * channels_;
  for (std::size_t i = 0; i < count; i += 4 * static_cast<std::size_t>(channels_) + 1, ++n) sum += radiance[i];
  const float mean = n > 0 ? static_cast<float>(sum / n) : 0.0f;
  if (!(mean > 0.0f)) return kMaxGain;
  return std::clamp(kTargetMean / mean, kMinGain, kMaxGain);
}

void CameraSensor::expose(const float* radiance, float gain, std::uint64_t frame_key, cv::Mat* image) {
  const int row = width_ * channels_;
  for (int y = 0; y < height_; ++y)
    blurRow(radiance + static_cast<std::size_t>(y) * row, blurred_rows_.data() + static_cast<std::size_t>(y) * row);
  // Vertical [1 2 1] / 4, noise, gain, quantisation.
  const std::uint32_t key_lo = static_cast<std::uint32_t>(frame_key), key_hi = static_cast<std::uint32_t>(frame_key >> 32);
  const std::size_t offsets = normals_.size() - static_cast<std::size_t>(row);
  float read_var = read_var_, shot = shot_;
  if (noise_model_ == SensorNoiseModel::kEmva1288) {
    // Noise referred to the radiance I (class comment): t_ref / t = a / g.
    const Exposure e = exposureFor(gain);
    const double ratio = 1e-3 * sensor_.exposure_ref_ms / e.time_s;
    const double read = ratio * sensor_.dark_noise_e / sensor_.full_well_e;
    read_var = static_cast<float>(read * read);
    shot = static_cast<float>(ratio / sensor_.full_well_e);
  }
  for (int y = 0; y < height_; ++y) {
    const float* up = blurred_rows_.data() + static_cast<std::size_t>(std::max(y - 1, 0)) * row;
    const float* mid = blurred_rows_.data() + static_cast<std::size_t>(y) * row;
    const float* down = blurred_rows_.data() + static_cast<std::size_t>(std::min(y + 1, height_ - 1)) * row;
    const float* noise = normals_.data() + hashU32(key_lo, key_hi, static_cast<std::uint32_t>(y)) % offsets;
    exposeRow(up, mid, down, noise, gain, read_var, shot, image->ptr<std::uint8_t>(y));
  }
}

void CameraSensor::blurRow(const float* in, float* out) const {
  // Horizontal [1 2 1] / 4, the edge pixels replicated; the interior as one flat loop over the
  // interleaved channels, which the compiler vectorises (the same operations in the same order).
  const int c = channels_, row = width_ * channels_;
  for (int k = 0; k < c; ++k) {
    out[k] = 0.25f * (in[k] + 2.0f * in[k] + in[c + k]);
    out[row - c + k] = 0.25f * (in[row - 2 * c + k] + 2.0f * in[row - c + k] + in[row - c + k]);
  }
  for (int i = c; i < row - c; ++i) out[i] = 0.25f * (in[i - c] + 2.0f * in[i] + in[i + c]);
}

void CameraSensor::exposeRow(const float* up, const float* mid, const float* down, const float* noise, float gain,
                             float read_var, float shot, std::uint8_t* out) const {
  // S = g (I + sqrt(read^2 + shot max(I, 0)) n), then round(255 clamp(S, 0, 1)); four values at a time
  // (the square root was the one operation the compiler would not vectorise), the tail one by one.
  const int row = width_ * channels_;
  int i = 0;
  for (; i + 4 <= row; i += 4) {
    const Float4 signal = 0.25f * (loadFloat4(up + i) + 2.0f * loadFloat4(mid + i) + loadFloat4(down + i));
    const Float4 zero{}, one = zero + 1.0f;  // the selects below are std::max and std::min, lane-wise
    const Float4 positive = signal < zero ? zero : signal;
    const Float4 noisy = gain * (signal + sqrt4(read_var + shot * positive) * loadFloat4(noise + i));
    const Float4 low = noisy < zero ? zero : noisy;
    const Float4 clamped = one < low ? one : low;
    const Int4 dn = __builtin_convertvector(clamped * 255.0f + 0.5f, Int4);
    for (int k = 0; k < 4; ++k) out[i + k] = static_cast<std::uint8_t>(dn[k]);
  }
  for (; i < row; ++i) {
    const float signal = 0.25f * (up[i] + 2.0f * mid[i] + down[i]);
    const float noisy = gain * (signal + std::sqrt(read_var + shot * std::max(signal, 0.0f)) * noise[i]);
    const float clamped = std::min(std::max(noisy, 0.0f), 1.0f);
    out[i] = static_cast<std::uint8_t>(clamped * 255.0f + 0.5f);
  }
}

}  // namespace deepnav::sim
