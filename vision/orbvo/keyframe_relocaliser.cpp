#include "vision/orbvo/keyframe_relocaliser.h"

#include <algorithm>
#include <limits>

#include "vision/orbvo/keyframe_thumbnail.h"

namespace deepnav {

bool KeyframeRelocaliser::init(const RelocalisationConfig& config, int max_keyframes,
                               int capacity) {
  if (max_keyframes < 1 || capacity < 1) return false;
  config_ = config;
  thumbnail_scratch_.create(kThumbnailHeightPx, kThumbnailWidthPx, CV_8UC1);
  thumbnail_.assign(kThumbnailSize, 0.0f);
  similarity_.assign(max_keyframes, 0.0f);
  score_.assign(max_keyframes, 0);
  owner_.assign(capacity, -1);
  owner_distance_.assign(capacity, 0);
  return true;
}

void KeyframeRelocaliser::makeThumbnailOf(const cv::Mat& grey, float* out) {
  makeThumbnail(grey, &thumbnail_scratch_, out);
}

int KeyframeRelocaliser::rank(const cv::Mat& grey_left, const OrbFrame& cur, const VoMap& map) {
  const int n_kf = map.keyframeCount();
  const int n = static_cast<int>(cur.features.size());
  // Thumbnails rank every keyframe cheaply; descriptors rank the most similar few.
  makeThumbnail(grey_left, &thumbnail_scratch_, thumbnail_.data());
  for (int age = 0; age < n_kf; ++age) {
    similarity_[age] = thumbnailSimilarity(thumbnail_.data(), map.keyframe(age).thumbnail.data());
    score_[age] = -1;
  }
  const int stride = std::max(1, n / config_.query_features);
  for (int k = 0; k < std::min(config_.thumbnail_candidates, n_kf); ++k) {
    const int age = static_cast<int>(
        std::max_element(similarity_.begin(), similarity_.begin() + n_kf) - similarity_.begin());
    similarity_[age] = -2.0f;
    score_[age] = countMatches(cur, map.keyframe(age), stride);
  }
  return stride;
}

int KeyframeRelocaliser::nextCandidate(int keyframe_count, int stride) {
  const int age = static_cast<int>(
      std::max_element(score_.begin(), score_.begin() + keyframe_count) - score_.begin());
  if (score_[age] * stride < config_.min_inliers / 2) return -1;
  score_[age] = -1;
  return age;
}

// Number of query features (every stride-th) with a ratio-test match among the keyframe's map
// points.
int KeyframeRelocaliser::countMatches(const OrbFrame& cur, const Keyframe& kf, int stride) const {
  int score = 0;
  for (std::size_t j = 0; j < cur.features.size(); j += stride) {
    int best = std::numeric_limits<int>::max();
    int second = std::numeric_limits<int>::max();
    for (std::size_t f = 0; f < kf.map_point.size(); ++f) {
      if (kf.map_point[f] < 0) continue;
      const int d = hammingDistance(cur.descriptors[j], kf.descriptors[f]);
      if (d < best) {
        second = best;
        best = d;
      } else if (d < second) {
        second = d;
      }
    }
    score += best <= config_.max_hamming && best < config_.ratio * second;
  }
  return score;
}

int KeyframeRelocaliser::matchKeyframe(const Keyframe& kf, const VoMap& map, OrbFrame* cur) {
  cur->clearAssociations();
  const int nk = static_cast<int>(kf.map_point.size());
  std::fill_n(owner_.begin(), nk, -1);
  for (std::size_t j = 0; j < cur->features.size(); ++j) {
    int best = std::numeric_limits<int>::max();
    int second = std::numeric_limits<int>::max();
    int best_f = -1;
    for (int f = 0; f < nk; ++f) {
      const int m = kf.map_point[f];
      if (m < 0 || !map.point(m).alive) continue;
      const int d = hammingDistance(cur->descriptors[j], kf.descriptors[f]);
      if (d < best) {
        second = best;
        best = d;
        best_f = f;
      } else if (d < second) {
        second = d;
      }
    }
    if (best_f < 0 || best > config_.max_hamming || best >= config_.ratio * second) continue;
    if (owner_[best_f] < 0 || best < owner_distance_[best_f]) {
      owner_[best_f] = static_cast<int>(j);
      owner_distance_[best_f] = best;
    }
  }
  int matches = 0;
  for (int f = 0; f < nk; ++f) {
    const int j = owner_[f];
    if (j < 0) continue;
    cur->map_point[j] = kf.map_point[f];
    cur->match_distance[j] = owner_distance_[f];
    ++matches;
  }
  return matches;
}

}  // namespace deepnav
