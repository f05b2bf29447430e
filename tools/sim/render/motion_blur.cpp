#include "tools/sim/render/motion_blur.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace deepnav::sim {

bool MotionBlur::init(const CameraConfig& camera, int channels) {
  if (camera.width_px < 2 || camera.height_px < 2 || (channels != 1 && channels != 3)) return false;
  width_ = camera.width_px;
  height_ = camera.height_px;
  channels_ = channels;
  fx_ = static_cast<float>(camera.fx_px);
  fy_ = static_cast<float>(camera.fy_px);
  cx_ = static_cast<float>(camera.cx_px);
  cy_ = static_cast<float>(camera.cy_px);
  sharp_.assign(static_cast<std::size_t>(width_) * height_ * channels_, 0.0f);
  return true;
}

// Bilinear sample of the sharp image at (u, v), borders clamped, added to acc[0..channels).
void MotionBlur::sample(float u, float v, float* acc) const {
  u = std::clamp(u, 0.0f, static_cast<float>(width_ - 1));
  v = std::clamp(v, 0.0f, static_cast<float>(height_ - 1));
  const int u0 = std::min(static_cast<int>(u), width_ - 2), v0 = std::min(static_cast<int>(v), height_ - 2);
  const float fu = u - static_cast<float>(u0), fv = v - static_cast<float>(v0);
  const std::size_t row = static_cast<std::size_t>(width_) * channels_;
  const float* p00 = sharp_.data() + static_cast<std::size_t>(v0) * row + static_cast<std::size_t>(u0) * channels_;
  const float* p10 = p00 + row;
  for (int c = 0; c < channels_; ++c) {
    const float top = p00[c] + fu * (p00[channels_ + c] - p00[c]);
    const float bottom = p10[c] + fu * (p10[channels_ + c] - p10[c]);
    acc[c] += top + fv * (bottom - top);
  }
}

void MotionBlur::apply(float* radiance, const float* depth_m, const Eigen::Vector3d& v_cam_mps,
                       const Eigen::Vector3d& w_cam_radps, float exposure_s) {
  std::memcpy(sharp_.data(), radiance, sharp_.size() * sizeof(float));
  const float vx = static_cast<float>(v_cam_mps.x()), vy = static_cast<float>(v_cam_mps.y());
  const float vz = static_cast<float>(v_cam_mps.z());
  const float wx = static_cast<float>(w_cam_radps.x()), wy = static_cast<float>(w_cam_radps.y());
  const float wz = static_cast<float>(w_cam_radps.z());
  float max_length = 0.0f;
  for (int v = 0; v < height_; ++v) {
    const float y = (static_cast<float>(v) - cy_) / fy_;
    for (int u = 0; u < width_; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * width_ + u;
      const float x = (static_cast<float>(u) - cx_) / fx_;
      const float inv_z = depth_m[i] > 0.0f ? 1.0f / depth_m[i] : 0.0f;
      const float dx = (-vx + x * vz) * inv_z + x * y * wx - (1.0f + x * x) * wy + y * wz;
      const float dy = (-vy + y * vz) * inv_z + (1.0f + y * y) * wx - x * y * wy - x * wz;
      const float du = fx_ * dx * exposure_s, dv = fy_ * dy * exposure_s;
      const float length = std::sqrt(du * du + dv * dv);
      max_length = std::max(max_length, length);
      if (!(length >= kMinLength_px)) continue;
      const int n = std::min(1 + static_cast<int>(std::ceil(length)), kMaxSamples);
      float acc[3] = {0.0f, 0.0f, 0.0f};
      for (int k = 0; k < n; ++k) {
        const float s = static_cast<float>(k) / static_cast<float>(n - 1) - 0.5f;
        sample(static_cast<float>(u) + s * du, static_cast<float>(v) + s * dv, acc);
      }
      float* out = radiance + i * channels_;
      for (int c = 0; c < channels_; ++c) out[c] = acc[c] / static_cast<float>(n);
    }
  }
  last_max_length_px_ = max_length;
}

}  // namespace deepnav::sim
