#pragma once
#include <opencv2/core.hpp>
#include <vector>

#include "vision/orbvo/orb_frame.h"
#include "vision/orbvo/vo_map.h"

namespace deepnav {

// Relocalisation when lost: every stored keyframe ranked by thumbnail similarity, the best
// thumbnail_candidates by descriptor matches, the best `candidates` tried with PnP.
struct RelocalisationConfig {
  int thumbnail_candidates = 8;  // >= candidates
  int query_features = 200;      // features of the lost frame used to rank keyframes, >= 10
  int candidates = 3;            // best-ranked keyframes tried with PnP, >= 1
  int max_hamming = 64;          // bits of 256
  double ratio = 0.8;            // ratio test of the descriptor matching, (0, 1]
  int min_inliers = 25;          // tracked points needed to accept a relocalisation
};

// The candidates of a relocalisation: every stored keyframe ranked by thumbnail similarity
// (keyframe_thumbnail.h), the most similar few by ratio-test descriptor matches of a subset of the
// lost frame's features; then, candidate by candidate, the lost frame's features associated with
// the candidate's map points (brute-force ratio-test matching). The pose from those associations
// is the odometry's. Also makes the keyframes' thumbnails. Sized in init(); does not allocate after.
class KeyframeRelocaliser {
 public:
  bool init(const RelocalisationConfig& config, int max_keyframes, int capacity);

  // The thumbnail of a grey image (CV_8UC1) into out[0 .. kThumbnailSize).
  void makeThumbnailOf(const cv::Mat& grey, float* out);

  // Ranks the map's keyframes for the lost frame `cur` (grey_left its left image). Returns the
  // stride of the query features, the argument of nextCandidate().
  int rank(const cv::Mat& grey_left, const OrbFrame& cur, const VoMap& map);

  // Age of the best-ranked keyframe not tried yet, -1 when none has enough matches left.
  int nextCandidate(int keyframe_count, int stride);

  // Associates cur's features with the keyframe's live map points (the previous associations
  // cleared); each keyframe feature keeps its best current feature. Returns the number made.
  int matchKeyframe(const Keyframe& kf, const VoMap& map, OrbFrame* cur);

 private:
  int countMatches(const OrbFrame& cur, const Keyframe& kf, int stride) const;

  RelocalisationConfig config_{};
  cv::Mat thumbnail_scratch_;
  std::vector<float> thumbnail_;   // the lost frame's
  std::vector<float> similarity_;  // per keyframe age
  std::vector<int> score_;         // per keyframe age, -1: not ranked or tried
  std::vector<int> owner_;         // per keyframe feature: best current feature
  std::vector<int> owner_distance_;
};

}  // namespace deepnav
