#pragma once
#include <Eigen/Core>
#include <cstdint>

#include "vision/orbvo/stereo_rig.h"

namespace deepnav {

// A map point seen in the current stereo pair.
struct PoseObservation {
  Eigen::Vector3d p_in_world_m = Eigen::Vector3d::Zero();
  Eigen::Vector2d uv_px = Eigen::Vector2d::Zero();  // left pixel
  double u_right_px = -1.0;  // right column; < 0 when the corner has no stereo match
  double sigma_px = 1.0;     // 1-sigma pixel noise of this corner (its level), > 0
};

struct PoseRefinerConfig {
  int rounds = 4;              // outlier-classification rounds, >= 1
  int iterations = 8;          // Gauss-Newton iterations per round, >= 1
  double huber_k = 2.45;       // Huber threshold on the whitened residual norm (sqrt(chi2_mono))
  double chi2_mono = 5.991;    // outlier gate of a left-only residual (95 %, 2 dof)
  double chi2_stereo = 7.815;  // outlier gate of a stereo residual (95 %, 3 dof)
  int min_inliers = 8;         // fewer inliers: the pose is rejected
};

// Pose of the left camera, T_cam_world: p_in_cam = R_cam_world p_in_world + p_world_in_cam_m.
// Its uncertainty is expressed as the left perturbation xi = (dt, phi) with
//   p_in_cam' = Exp(phi) p_in_cam + dt      (dt, phi in the camera frame, order [dt, phi]).
struct CameraPoseEstimate {
  Eigen::Matrix3d R_cam_world = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p_world_in_cam_m = Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 6, 6> cov_xi = Eigen::Matrix<double, 6, 6>::Identity();
  int inliers = 0;
  double rms_px = 0.0;             // RMS of the inlier residuals, px
  double residual_variance = 0.0;  // s^2 below (1 when the pixel noise model is right)
};

// Refines *pose (initial value in, result out) by iteratively reweighted Gauss-Newton on the stereo
// reprojection error r = (u, v, u_r)_predicted - measured, whitened by sigma_px, with a Huber loss:
// weight w = 1 for |r|/sigma <= k, k sigma / |r| beyond (Huber 1964). After each round every
// observation is classified against its chi-square gate (inlier[i] = 1 or 0); outliers sit out the
// next round. The covariance is the Gauss-Newton one scaled by the residual variance,
//   cov_xi = s^2 (J^T W J)^-1,  s^2 = sum w |r|^2 / sigma^2 / (m - 6) / c,  m = residual rows,
// c < 1 the mean of a chi-square truncated at the gate (the gates drop the tail of the inliers
// too). Returns false (pose left at its last iterate) when fewer than min_inliers remain or the
// normal equations are singular. Does not allocate.
bool refineCameraPose(const StereoRig& rig, const PoseRefinerConfig& config,
                      const PoseObservation* observations, int count, std::uint8_t* inlier,
                      CameraPoseEstimate* pose);

// Whitened residual of one observation and its 3x6 (or 2x6 without u_r) Jacobian with respect to
// xi. Returns the number of rows (2 or 3), 0 when the point lies behind the camera.
int poseResidual(const StereoRig& rig, const PoseObservation& observation,
                 const Eigen::Matrix3d& R_cam_world, const Eigen::Vector3d& p_world_in_cam_m,
                 Eigen::Vector3d* residual, Eigen::Matrix<double, 3, 6>* jacobian);

}  // namespace deepnav
