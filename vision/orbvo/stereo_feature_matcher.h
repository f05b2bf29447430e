#pragma once
#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "vision/orbvo/orb_feature.h"
#include "vision/orbvo/stereo_rig.h"

namespace deepnav {

struct StereoMatchConfig {
  double row_band_px = 2.0;  // |v_left - v_right| allowed for a level-0 corner; level l: band * s^l
  double min_depth_m = 0.3;  // nearest point kept (largest disparity), > 0
  double max_depth_m = 10.0;     // farthest point kept (smallest disparity), > min_depth_m
  int max_hamming = 64;          // descriptor distance accepted, bits of 256
  double ratio = 0.8;            // best distance < ratio * second best along the band, (0, 1]
  int max_level_difference = 1;  // pyramid levels between the two corners
  int sad_half_window_px = 5;    // subpixel refinement window (2w+1)^2, [1, 15]
  int sad_search_px = 2;  // columns searched on each side of the matched right corner, [1, 8]
  // The minimum cost must be below this fraction of both end costs, (0, 1]
  double sad_distinct_ratio = 0.9;
};

// Matches left corners to right corners of a rectified pair along the rows: candidates lie in the
// band |v_r - v_l| <= row_band and in the disparity range of [min_depth, max_depth]; the best
// Hamming distance must pass max_hamming and the ratio test, and each right corner keeps only its
// best left corner. The disparity is then refined to subpixel on the level-0 images: zero-mean SAD
// of a (2w+1)^2 window at columns u_r + k, k in [-search, search], and the parabola through the
// minimum and its two neighbours, k* = (c_-1 - c_+1) / (2 (c_-1 - 2 c_0 + c_+1)). A minimum on the
// edge of the search range, or one above sad_distinct_ratio times the costs at both ends of the
// range (a flat or ambiguous row, e.g. a corner matched on the wrong row), rejects the match.
// Matched corners are triangulated in the left frame. Allocation: every buffer is sized in init();
// match() does not allocate. Why the left corners of the last match() went unmatched.
struct StereoMatchStats {
  int no_candidate = 0;  // nothing in the band and disparity range
  int descriptor = 0;    // best distance over max_hamming or failing the ratio test
  int duplicate = 0;     // their right corner preferred another left corner
  // Window out of the image, minimum on the search edge, flat or ambiguous cost
  int refinement = 0;
  int depth = 0;  // refined disparity out of the depth range
};

class StereoFeatureMatcher {
 public:
  // max_features: the larger of the two images' feature capacities. level_scale_factor: the pyramid
  // scale between levels (widens the band of coarse corners).
  bool init(const StereoMatchConfig& config, const StereoRig& rig, int max_features,
            double level_scale_factor);

  // u_right_px[i] is the right column of left feature i (< 0 when unmatched) and p_in_cam_m[i] its
  // point in the left camera frame (zero when unmatched). Both are resized to left.size() (within
  // the init capacity). Returns the number of matches.
  int match(const cv::Mat& left_grey, const cv::Mat& right_grey,
            const std::vector<OrbFeature>& left, const std::vector<OrbDescriptor>& left_desc,
            const std::vector<OrbFeature>& right, const std::vector<OrbDescriptor>& right_desc,
            std::vector<float>* u_right_px, std::vector<Eigen::Vector3d>* p_in_cam_m);

  const StereoMatchStats& stats() const { return stats_; }

  // Subpixel right column of the left pixel (u, v) near right column u_right_guess (public for
  // tests). False when the window leaves an image, the minimum lies on the search edge or the cost
  // is flat.
  bool refineRightColumn(const cv::Mat& left_grey, const cv::Mat& right_grey, double u_px,
                         double v_px, double u_right_guess_px, double* u_right_px) const;

 private:
  void indexRightRows(const std::vector<OrbFeature>& right);
  int bestRightCandidate(const OrbFeature& lf, const OrbDescriptor& ld,
                         const std::vector<OrbFeature>& right,
                         const std::vector<OrbDescriptor>& right_desc, int* distance);

  StereoMatchConfig config_{};
  StereoRig rig_{};
  double level_scale_factor_ = 1.2;
  double min_disparity_px_ = 0.0;
  double max_disparity_px_ = 0.0;
  std::vector<int>
      row_start_;  // right corners of row r: sorted_right_[row_start_[r] .. row_start_[r+1])
  std::vector<int> sorted_right_;
  std::vector<int> best_right_;  // per left corner
  std::vector<int> best_distance_;
  std::vector<int> right_owner_;  // per right corner: left corner with the smallest distance
  std::vector<int> owner_distance_;
  StereoMatchStats stats_{};
};

}  // namespace deepnav
