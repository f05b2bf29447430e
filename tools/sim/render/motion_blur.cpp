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
  row_du_.assign(static_cast<std::size_t>(width_), 0.0f);
  row_dv_.assign(static_cast<std::size_t>(width_), 0.0f);
  row_length2_.assign(static_cast<std::size_t>(width_), 0.0f);
  reciprocal_[0] = 0.0f;
  for (int k = 1; k <= kMaxSamples; ++k) reciprocal_[k] = 1.0f / static_cast<float>(k);
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
  const float inv_fx = 1.0f / fx_, inv_fy = 1.0f / fy_;
  // Segments within these bounds need no clamping (the bilinear cell's right and lower neighbours exist).
  const float max_u = static_cast<float>(width_ - 1) - 1e-3f, max_v = static_cast<float>(height_ - 1) - 1e-3f;
  const float min_length2 = kMinLength_px * kMinLength_px;
  float* du_row = row_du_.data();
  float* dv_row = row_dv_.data();
  float* length2_row = row_length2_.data();
  for (int v = 0; v < height_; ++v) {
    const float y = (static_cast<float>(v) - cy_) * inv_fy;
    const float* depth_row = depth_m + static_cast<std::size_t>(v) * width_;
    // The row's flow first, in a loop without branches the compiler vectorises.
    for (int u = 0; u < width_; ++u) {
      const float x = (static_cast<float>(u) - cx_) * inv_fx;
      const float z = depth_row[u];
      const float inv_z = z > 0.0f ? 1.0f / (z > 0.0f ? z : 1.0f) : 0.0f;
      const float dx = (-vx + x * vz) * inv_z + x * y * wx - (1.0f + x * x) * wy + y * wz;
      const float dy = (-vy + y * vz) * inv_z + (1.0f + y * y) * wx - x * y * wy - x * wz;
      du_row[u] = fx_ * dx * exposure_s;
      dv_row[u] = fy_ * dy * exposure_s;
      length2_row[u] = du_row[u] * du_row[u] + dv_row[u] * dv_row[u];
    }
    for (int u = 0; u < width_; ++u) {
      const float length2 = length2_row[u];
      max_length = std::max(max_length, length2);
      if (!(length2 >= min_length2)) continue;
      const float du = du_row[u], dv = dv_row[u];
      // 2 + floor(length) samples (1 + ceil but for whole lengths; no libm call on the x86-64 baseline).
      const int n = std::min(2 + static_cast<int>(std::sqrt(length2)), kMaxSamples);
      const float inv_n1 = reciprocal_[n - 1];
      const float u0 = static_cast<float>(u) - 0.5f * du, v0 = static_cast<float>(v) - 0.5f * dv;
      const float su = du * inv_n1, sv = dv * inv_n1;
      float* out = radiance + (static_cast<std::size_t>(v) * width_ + u) * channels_;
      const bool inside = std::min(u0, u0 + du) >= 0.0f && std::max(u0, u0 + du) <= max_u &&
                          std::min(v0, v0 + dv) >= 0.0f && std::max(v0, v0 + dv) <= max_v;
      if (inside && channels_ == 1) {
        // The common case: the whole segment inside, grey; no clamping, truncation is floor.
        const float* sharp = sharp_.data();
        const int w = width_;
        float acc = 0.0f;
        for (int k = 0; k < n; ++k) {
          const float pu = u0 + static_cast<float>(k) * su, pv = v0 + static_cast<float>(k) * sv;
          const int iu = static_cast<int>(pu), iv = static_cast<int>(pv);
          const float wu = pu - static_cast<float>(iu), wv = pv - static_cast<float>(iv);
          const float* cell = sharp + static_cast<std::size_t>(iv) * w + iu;
          const float top = cell[0] + wu * (cell[1] - cell[0]);
          const float bottom = cell[w] + wu * (cell[w + 1] - cell[w]);
          acc += top + wv * (bottom - top);
        }
        out[0] = acc * reciprocal_[n];
        continue;
      }
      float acc[3] = {0.0f, 0.0f, 0.0f};
      for (int k = 0; k < n; ++k) sample(u0 + static_cast<float>(k) * su, v0 + static_cast<float>(k) * sv, acc);
      for (int c = 0; c < channels_; ++c) out[c] = acc[c] * reciprocal_[n];
    }
  }
  max_length = std::sqrt(max_length);
  last_max_length_px_ = max_length;
}

}  // namespace deepnav::sim
