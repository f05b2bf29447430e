#include "vision/planes/plane_correspondence.h"

#include <algorithm>
#include <cmath>

namespace deepnav {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

double angleBetween(const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  return std::acos(std::clamp(u.dot(v), -1.0, 1.0));
}

}  // namespace

bool PlaneCorrespondenceSearch::init(const PlaneRegistrationConfig& config) {
  if (config.max_log_size_ratio <= 0.0 || config.max_cross_angle_diff_deg <= 0.0 ||
      config.parallel_angle_deg <= 0.0 || config.max_parallel_offset_diff_m <= 0.0 ||
      config.max_search_nodes < 0) {
    return false;
  }
  config_ = config;
  cos_max_normal_change_ = std::cos(std::min(180.0, config.max_normal_change_deg) * kDegToRad);
  return true;
}

bool PlaneCorrespondenceSearch::consistent(const PlaneSet& a, const PlaneSet& b,
                                           const PlaneMatch& u, const PlaneMatch& v) const {
  if (u.a == v.a || u.b == v.b) return false;  // one-to-one
  const Plane& ai = a[u.a];
  const Plane& ak = a[v.a];
  const Plane& bj = b[u.b];
  const Plane& bl = b[v.b];
  const double angle_a = angleBetween(ai.n_in_cam, ak.n_in_cam);
  const double angle_b = angleBetween(bj.n_in_cam, bl.n_in_cam);
  if (std::abs(angle_a - angle_b) > config_.max_cross_angle_diff_deg * kDegToRad) return false;
  const double parallel = config_.parallel_angle_deg * kDegToRad;
  if (angle_a < parallel && angle_b < parallel) {
    const double offset_a = ai.d_m - ak.d_m;
    const double offset_b = bj.d_m - bl.d_m;
    if (std::abs(offset_a - offset_b) > config_.max_parallel_offset_diff_m) return false;
  }
  return true;
}

int PlaneCorrespondenceSearch::find(const PlaneSet& a, const PlaneSet& b,
                                    std::array<PlaneMatch, kMaxMatches>* matches) {
  candidate_count_ = 0;
  for (int i = 0; i < a.size(); ++i) {
    for (int j = 0; j < b.size(); ++j) {
      if (std::abs(a[i].log_pdet_hessian - b[j].log_pdet_hessian) > config_.max_log_size_ratio) {
        continue;
      }
      if (a[i].n_in_cam.dot(b[j].n_in_cam) < cos_max_normal_change_) continue;
      if (candidate_count_ == kMaxCandidates) continue;  // full: later pairs are not considered
      candidate_score_[candidate_count_] = std::min(a[i].point_count, b[j].point_count);
      candidates_[candidate_count_++] = PlaneMatch{i, j};
    }
  }
  Bits all;
  for (int u = 0; u < candidate_count_; ++u) {
    adjacent_[u].reset();
    all.set(u);
  }
  for (int u = 0; u < candidate_count_; ++u) {
    for (int v = u + 1; v < candidate_count_; ++v) {
      if (consistent(a, b, candidates_[u], candidates_[v])) {
        adjacent_[u].set(v);
        adjacent_[v].set(u);
      }
    }
  }
  best_size_ = 0;
  best_score_ = 0.0;
  nodes_ = 0;
  exhausted_ = false;
  expand(all, 0, 0.0);
  for (int i = 0; i < best_size_; ++i) (*matches)[i] = candidates_[best_[i]];
  return best_size_;
}

// Carraghan-Pardalos branch and bound: grow the current clique by each remaining candidate in
// turn, keeping only candidates consistent with all chosen ones; prune when even taking every
// remaining candidate cannot beat the best size.
void PlaneCorrespondenceSearch::expand(Bits candidates, int depth, double score) {
  ++nodes_;
  if (config_.max_search_nodes > 0 && nodes_ > config_.max_search_nodes) {
    exhausted_ = true;
    return;
  }
  if (candidates.none() || depth == kMaxMatches) {
    if (depth > best_size_ || (depth == best_size_ && score > best_score_)) {
      best_size_ = depth;
      best_score_ = score;
      std::copy(current_.begin(), current_.begin() + depth, best_.begin());
    }
    return;
  }
  while (candidates.any()) {
    if (depth + static_cast<int>(candidates.count()) < best_size_ || exhausted_) return;
    const int v = static_cast<int>(candidates._Find_first());
    candidates.reset(v);
    current_[depth] = v;
    expand(candidates & adjacent_[v], depth + 1, score + candidate_score_[v]);
  }
}

}  // namespace deepnav
