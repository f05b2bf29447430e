#pragma once
#include <array>
#include <cstdint>
#include <opencv2/core.hpp>

#include "vision/orbvo/orb_feature.h"

namespace deepnav {

// Rotated BRIEF (Rublee et al., "ORB: an efficient alternative to SIFT or SURF", ICCV 2011): bit i
// of the descriptor is I(p_i) < I(q_i) over 256 point pairs of a smoothed patch, the pairs turned
// by the corner's orientation. Our pairs are drawn once from an isotropic Gaussian of sigma = 31/5
// px (Calonder et al., BRIEF, ECCV 2010, sampling G II) with a fixed seed, not ORB's learned set;
// the rotation is quantised to 32 bins of 11.25 deg and precomputed, as in the ORB paper.
// Orientation is the intensity centroid (Rosin 1999): theta = atan2(m01, m10) over a disc of
// radius 15.
class SteeredBrief {
 public:
  static constexpr int kBits = 256;
  static constexpr int kAngleBins = 32;
  static constexpr int kPairRadiusPx = 13;  // every (rotated) sample lies within 14 px
  static constexpr int kOrientationRadiusPx = 15;
  static constexpr int kBorderPx = 16;  // a corner needs this much image around it

  SteeredBrief();

  // Orientation of the corner at integer (x, y) of `image` (CV_8UC1), >= kBorderPx from every side.
  // The moments are exact integer sums, vectorised with OpenCV's universal intrinsics (NEON on
  // aarch64); orientationRadScalar is the plain loop, kept as the tests' reference.
  float orientationRad(const cv::Mat& image, int x, int y) const;
  float orientationRadScalar(const cv::Mat& image, int x, int y) const;

  // Descriptor of the patch centred at integer (x, y) of `smoothed` (CV_8UC1), >= kBorderPx inside.
  void describe(const cv::Mat& smoothed, int x, int y, float angle_rad, OrbDescriptor* out) const;

  // The sample pairs as byte offsets from the centre pixel for one row step (bytes), per angle bin
  // (p, q interleaved): describe() without the per-bit address arithmetic.
  struct Offsets {
    int step = 0;
    std::array<std::array<int, 2 * kBits>, kAngleBins> offset{};
  };
  void fillOffsets(int step, Offsets* out) const;
  // Same bits as describe(); `offsets` must be filled for smoothed.step1().
  void describe(const cv::Mat& smoothed, const Offsets& offsets, int x, int y, float angle_rad,
                OrbDescriptor* out) const;

 private:
  // Per angle bin, per bit: (dx_p, dy_p, dx_q, dy_q).
  std::array<std::array<std::int8_t, 4 * kBits>, kAngleBins> pairs_{};
  std::array<int, kOrientationRadiusPx + 1> disc_half_width_{};  // half chord of the disc per |dy|
  // Per |dy|, over the 32 columns x-15 .. x+16: the column's u (m10 weight) and |dy| (m01 weight)
  // inside the disc's chord, 0 outside.
  std::array<std::array<std::int16_t, 32>, kOrientationRadiusPx + 1> u_weight_{};
  std::array<std::array<std::int16_t, 32>, kOrientationRadiusPx + 1> dy_weight_{};
};

}  // namespace deepnav
