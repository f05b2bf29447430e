#pragma once
#include <span>

#include <Eigen/Geometry>

#include "nav/metrics/stamped_pose.h"
#include "nav/metrics/trajectory_errors.h"

namespace deepnav {

// Rigid alignment without scale of an estimated trajectory onto the truth, as `evo_ape --align` does
// (SE(3) Umeyama, S. Umeyama 1991, "Least-squares estimation of transformation parameters between two
// point patterns", IEEE PAMI 13(4), eq. 39-42 with c = 1): the T minimising sum_i |p_true_i - T p_est_i|^2
// over the positions. Identity when fewer than 3 poses or the positions are degenerate (all equal).
Eigen::Isometry3d alignRigid(std::span<const StampedPose> estimate, std::span<const StampedPose> truth);

// Absolute trajectory error after that alignment, in evo's APE conventions: per pose the relation
// E_i = T_true_i^-1 (T_align T_est_i); translation error |t(E_i)| (= |p_true_i - T_align p_est_i|),
// rotation error the angle of R(E_i). Both series summarised (rms is evo's "rmse").
struct AlignedTrajectoryErrors {
  Eigen::Isometry3d T_align = Eigen::Isometry3d::Identity();  // truth frame <- estimate frame
  TrajectoryErrors errors;
};
AlignedTrajectoryErrors alignedTrajectoryErrors(std::span<const StampedPose> estimate,
                                                std::span<const StampedPose> truth);

}  // namespace deepnav
