#pragma once
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "vision/orbvo/feature_grid.h"
#include "vision/orbvo/orb_feature.h"

namespace deepnav {

struct ProjectionSearchConfig {
  double radius_px = 15.0;  // window half side at level 0; a level-l query searches radius * s^l
  int max_hamming = 64;     // bits of 256
  double ratio = 0.9;       // best < ratio * second best inside the window (1: no ratio test)
  int max_level_difference = 1;  // pyramid levels between the query and a candidate
};

struct ProjectionMatch {
  int index = -1;  // feature index, -1 when nothing passes
  int distance = std::numeric_limits<int>::max();
};

// Best feature of `features` for a point predicted at uv_px with descriptor `descriptor`, seen at
// pyramid level `level`: the smallest Hamming distance inside the window, with the gates above.
// level_scale[l] is the scale of level l. Candidates with available[i] == 0 are skipped.
inline ProjectionMatch searchNearProjection(const FeatureGrid& grid,
                                            const std::vector<OrbFeature>& features,
                                            const std::vector<OrbDescriptor>& descriptors,
                                            const std::vector<std::uint8_t>& available,
                                            const double* level_scale, const Eigen::Vector2d& uv_px,
                                            int level, const OrbDescriptor& descriptor,
                                            const ProjectionSearchConfig& config) {
  const double radius = config.radius_px * level_scale[level];
  int best = std::numeric_limits<int>::max();
  int second = std::numeric_limits<int>::max();
  ProjectionMatch match;
  grid.forEachNear(uv_px.x(), uv_px.y(), radius, [&](int i) {
    const OrbFeature& f = features[i];
    if (!available[i] || std::abs(f.level - level) > config.max_level_difference) return;
    if (std::abs(f.u_px - uv_px.x()) > radius || std::abs(f.v_px - uv_px.y()) > radius) return;
    const int d = hammingDistance(descriptor, descriptors[i]);
    if (d < best) {
      second = best;
      best = d;
      match.index = i;
    } else if (d < second) {
      second = d;
    }
  });
  if (match.index < 0 || best > config.max_hamming) return ProjectionMatch();
  if (second != std::numeric_limits<int>::max() && best > config.ratio * second)
    return ProjectionMatch();
  match.distance = best;
  return match;
}

}  // namespace deepnav
