#pragma once
#include <cstddef>
#include <span>
#include <vector>

#include "nav/metrics/stamped_pose.h"
#include "nav/metrics/trajectory_errors.h"

namespace deepnav {

// Relative pose error over segments of fixed travelled distance, in the conventions of
// `evo_rpe --delta D --delta_unit m` (consecutive pairs, not all pairs): the pairs (i, j) start at the
// first pose, and j is the first pose at which the path length of the TRUE trajectory travelled since i
// reaches D; the next pair starts at j. Per pair the error relation is
//   E_ij = (T_true_i^-1 T_true_j)^-1 (T_est_i^-1 T_est_j),
// translation error |t(E_ij)| (m), rotation error the angle of R(E_ij). Beyond evo, each is also divided
// by the pair's true path length: the drift per metre travelled (translation in % of the distance, as
// the KITTI odometry benchmark, rotation in deg/m). The estimate and the truth must be associated pose
// by pose (trajectory_association.h). No alignment is needed: the relation is invariant to a rigid
// transform of either trajectory.
struct RelativePoseErrors {
  double delta_m = 0.0;
  std::vector<double> length_m;         // true path length of each pair (>= delta_m)
  std::vector<double> translation_m;
  std::vector<double> rotation_rad;
  ErrorStats translation;               // of translation_m (rms: evo's rmse)
  ErrorStats rotation;                  // of rotation_rad
  ErrorStats translation_percent;       // of 100 translation_m / length_m
  ErrorStats rotation_rad_per_m;        // of rotation_rad / length_m
};
RelativePoseErrors relativePoseErrors(std::span<const StampedPose> estimate, std::span<const StampedPose> truth,
                                      double delta_m);

}  // namespace deepnav
