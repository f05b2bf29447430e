#include "vision/orbvo/motion_prior.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>
#include <numbers>

#include "base/so3.h"
#include "vision/orbvo/stereo_projection.h"

namespace deepnav {

CameraPoseEstimate predictCameraPose(const CameraPoseEstimate& a, const Eigen::Isometry3d& T_a_b) {
  // x_b = R_ba (x_a - p_ab) with x_a = R_aw X + t_a.
  const Eigen::Matrix3d R_ba = T_a_b.linear().transpose();
  CameraPoseEstimate b = a;
  b.R_cam_world = R_ba * a.R_cam_world;
  b.p_world_in_cam_m = R_ba * (a.p_world_in_cam_m - T_a_b.translation());
  return b;
}

double priorDisagreement(const RelativeCameraPose& vo, const Eigen::Isometry3d& T_a_b_prior,
                         const OrbMotionPriorConfig& config) {
  Eigen::Matrix<double, 6, 1> e;
  e.head<3>() = vo.p_camb_in_cama_m - T_a_b_prior.translation();
  e.tail<3>() = logSo3(T_a_b_prior.linear().transpose() * vo.q_cama_camb.toRotationMatrix());
  const double var_t = config.translation_sigma_m * config.translation_sigma_m;
  const double sigma_r = config.rotation_sigma_deg * std::numbers::pi / 180.0;
  Eigen::Matrix<double, 6, 6> S = vo.cov;
  S.diagonal().head<3>().array() += var_t;
  S.diagonal().tail<3>().array() += sigma_r * sigma_r;
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(S);
  if (ldlt.info() != Eigen::Success) return std::numeric_limits<double>::infinity();
  return e.dot(ldlt.solve(e));
}

bool withinPriorGate(const StereoRig& rig, const CameraPoseEstimate& predicted, const Eigen::Vector3d& p_in_world_m,
                     const Eigen::Vector2d& uv_px, double sigma_px, const OrbMotionPriorConfig& config) {
  const Eigen::Vector3d p_in_cam_m = predicted.R_cam_world * p_in_world_m + predicted.p_world_in_cam_m;
  if (p_in_cam_m.z() <= 1e-3) return false;
  const double f_px = 0.5 * (rig.fx_px + rig.fy_px);
  const double sigma_t_px = f_px * config.translation_sigma_m / p_in_cam_m.z();
  const double sigma_r_px = f_px * config.rotation_sigma_deg * std::numbers::pi / 180.0;
  const double var_px2 = sigma_px * sigma_px + sigma_t_px * sigma_t_px + sigma_r_px * sigma_r_px;
  return (projectLeft(rig, p_in_cam_m) - uv_px).squaredNorm() <= config.gate_chi2 * var_px2;
}

}  // namespace deepnav
