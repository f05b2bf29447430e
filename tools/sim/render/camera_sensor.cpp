#include "tools/sim/render/camera_sensor.h"

#include <algorithm>
#include <cmath>

#include "tools/sim/normal_rng.h"
#include "tools/sim/render/procedural_noise.h"

namespace deepnav::sim {

namespace {
}  // namespace

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
  const int c = channels_, w = width_;
  const int row = w * c;
  // Horizontal [1 2 1] / 4.
  for (int y = 0; y < height_; ++y) {
    const float* in = radiance + static_cast<std::size_t>(y) * row;
    float* out = blurred_rows_.data() + static_cast<std::size_t>(y) * row;
    for (int x = 0; x < w; ++x) {
      const int xl = std::max(x - 1, 0) * c, xr = std::min(x + 1, w - 1) * c;
      for (int k = 0; k < c; ++k) out[x * c + k] = 0.25f * (in[xl + k] + 2.0f * in[x * c + k] + in[xr + k]);
    }
  }
  // Vertical [1 2 1] / 4, noise, gain, quantisation.
  const std::uint32_t key_lo = static_cast<std::uint32_t>(frame_key), key_hi = static_cast<std::uint32_t>(frame_key >> 32);
  const std::size_t offsets = normals_.size() - static_cast<std::size_t>(row);
  for (int y = 0; y < height_; ++y) {
    const float* up = blurred_rows_.data() + static_cast<std::size_t>(std::max(y - 1, 0)) * row;
    const float* mid = blurred_rows_.data() + static_cast<std::size_t>(y) * row;
    const float* down = blurred_rows_.data() + static_cast<std::size_t>(std::min(y + 1, height_ - 1)) * row;
    const float* noise = normals_.data() + hashU32(key_lo, key_hi, static_cast<std::uint32_t>(y)) % offsets;
    std::uint8_t* out = image->ptr<std::uint8_t>(y);
    for (int i = 0; i < row; ++i) {
      const float signal = 0.25f * (up[i] + 2.0f * mid[i] + down[i]);
      const float noisy = gain * (signal + std::sqrt(read_var_ + shot_ * std::max(signal, 0.0f)) * noise[i]);
      const float clamped = std::min(std::max(noisy, 0.0f), 1.0f);
      out[i] = static_cast<std::uint8_t>(clamped * 255.0f + 0.5f);
    }
  }
}

}  // namespace deepnav::sim
