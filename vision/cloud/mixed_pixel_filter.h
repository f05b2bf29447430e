#pragma once
#include <cstdint>
#include <opencv2/core.hpp>

#include "vision/cloud/organized_cloud.h"

namespace deepnav {

// Removes mixed pixels ("veils", comet-like streaks): at a depth discontinuity a stereo matcher
// blends foreground and background, leaving points strung along the viewing rays between the two
// surfaces. A real surface seen at incidence alpha makes neighbouring points differ by a segment
// at 90 deg - alpha to the ray; a streak makes segments almost parallel to the ray. Both ends of
// every horizontal or vertical neighbour segment closer than min_ray_angle_deg to the ray of its
// first point are dropped (this also erodes one pixel on each side of a clean depth edge).
struct MixedPixelConfig {
  bool enabled = true;
  // Segments within this angle of the viewing ray are streaks: 5 deg keeps surfaces up to 85 deg
  // incidence. A streak of k pixels spanning a depth gap dZ at depth Z makes segments of about
  // atan(k Z / (f dZ)) to the ray (f = 700 px, Z = 2 m, dZ = 1 m, k = 6: 1 deg). Far, noisy points
  // at full resolution can look like streaks too (sigma_Z against the pixel footprint Z / f).
  double min_ray_angle_deg = 5.0;
};

class MixedPixelFilter {
 public:
  // Sizes the mark buffer for a grid (start-up). Returns false for bad sizes or angle.
  bool init(const MixedPixelConfig& config, int rows, int cols);
  // Invalidates the mixed points of *cloud in place; returns how many were removed (-1 on a size
  // mismatch). Does nothing when disabled.
  int apply(OrganizedCloud* cloud);

 private:
  void markPair(const cv::Vec3f& p, const cv::Vec3f& q, std::uint8_t* mark_p,
                std::uint8_t* mark_q) const;

  MixedPixelConfig config_;
  float cos2_max_ = 0.0f;  // cos^2 of min_ray_angle
  cv::Mat mark_;           // CV_8UC1 grid: 1 = to remove
};

}  // namespace deepnav
