#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace deepnav::sim {

// An albedo image (BGR, linear, 8 bits per channel: value / 255 is the albedo) with its mip pyramid,
// sampled bilinearly from the level that matches the pixel footprint (no shimmering when the panel is
// far, crisp edges when it is near). Texel i covers [i, i + 1) in texel coordinates.
class TextureMap {
 public:
  // wrap: the texture tiles (width and height must be powers of two); else coordinates are clamped.
  bool create(int width_texels, int height_texels, bool wrap);
  // Level 0, CV_8UC3, to paint into before buildMips().
  cv::Mat& base() { return levels_[0]; }
  const cv::Mat& base() const { return levels_[0]; }
  // Box-filtered levels down to about 8 texels.
  void buildMips();

  // Albedo at level-0 texel coordinates (u, v) for a pixel covering footprint_texels level-0 texels.
  Eigen::Vector3f sample(float u, float v, float footprint_texels) const;
  int levels() const { return static_cast<int>(levels_.size()); }

 private:
  Eigen::Vector3f sampleLevel(int level, float u, float v) const;

  std::vector<cv::Mat> levels_;
  std::vector<float> scale_;  // level-L texels per level-0 texel (both axes; sizes halve exactly or clamp)
  bool wrap_ = false;
};

}  // namespace deepnav::sim
