#include "vision/orbvo/pose_refiner.h"

#include <Eigen/Cholesky>
#include <cmath>

#include "base/so3.h"
#include "vision/orbvo/stereo_projection.h"

namespace deepnav {
namespace {

constexpr double kMinDepthM = 1e-3;

// H += w J^T J and g += w J^T r for one observation, on H's lower triangle (the caller mirrors it):
// 21 of the 36 entries. Each entry is the same sum of the same products as Eigen's full
// w * J^T * J, so the lower triangle, which the LDLT reads, keeps its bits.
void addToNormalEquations(const Eigen::Vector3d& r, const Eigen::Matrix<double, 3, 6>& J, double w,
                          Eigen::Matrix<double, 6, 6>* H, Eigen::Matrix<double, 6, 1>* g) {
  const Eigen::Matrix<double, 3, 6> wJ = w * J;
  for (int c = 0; c < 6; ++c) {
    (*g)(c) += wJ.col(c).dot(r);
    for (int k = 0; k <= c; ++k) (*H)(c, k) += wJ.col(c).dot(J.col(k));
  }
}

// Normal equations of the current inliers; returns the number of residual rows and the cost sum w
// e^2.
int accumulate(const StereoRig& rig, const PoseRefinerConfig& config,
               const PoseObservation* observations, int count, const std::uint8_t* inlier,
               const CameraPoseEstimate& pose, Eigen::Matrix<double, 6, 6>* H,
               Eigen::Matrix<double, 6, 1>* g, double* weighted_cost, double* squared_px) {
  H->setZero();
  g->setZero();
  *weighted_cost = 0.0;
  *squared_px = 0.0;
  int rows = 0;
  Eigen::Vector3d r;
  Eigen::Matrix<double, 3, 6> J;
  for (int i = 0; i < count; ++i) {
    if (!inlier[i]) continue;
    const int m =
        poseResidual(rig, observations[i], pose.R_cam_world, pose.p_world_in_cam_m, &r, &J);
    if (m == 0) continue;
    // A left-only observation has r(2) = 0 and a zero third Jacobian row: the full 3 rows are
    // exact.
    const double e = r.norm();
    const double w = e <= config.huber_k ? 1.0 : config.huber_k / e;
    addToNormalEquations(r, J, w, H, g);
    *weighted_cost += w * e * e;
    *squared_px += e * e * observations[i].sigma_px * observations[i].sigma_px;
    rows += m;
  }
  *H = H->selfadjointView<Eigen::Lower>();
  return rows;
}

}  // namespace

int poseResidual(const StereoRig& rig, const PoseObservation& observation,
                 const Eigen::Matrix3d& R_cam_world, const Eigen::Vector3d& p_world_in_cam_m,
                 Eigen::Vector3d* residual, Eigen::Matrix<double, 3, 6>* jacobian) {
  const Eigen::Vector3d p_in_cam_m = R_cam_world * observation.p_in_world_m + p_world_in_cam_m;
  if (p_in_cam_m.z() < kMinDepthM) return 0;
  const StereoProjection proj = projectStereo(rig, p_in_cam_m);
  const double inv_sigma = 1.0 / observation.sigma_px;
  // J = D [I, -[p]x] / sigma, D = d(u, v, u_r)/dp (stereo_projection.h). Each row d of D gives
  // (d, d (-[p]x)) with d (-[p]x) = (d_z y - d_y z, d_x z - d_z x, d_y x - d_x y); D's zeros (u and u_r
  // do not depend on y, v not on x) are left out.
  const double x = p_in_cam_m.x(), y = p_in_cam_m.y(), z = p_in_cam_m.z();
  const Eigen::Matrix3d& D = proj.d_uvr_d_p;
  const double du_dx = inv_sigma * D(0, 0), du_dz = inv_sigma * D(0, 2);
  const double dv_dy = inv_sigma * D(1, 1), dv_dz = inv_sigma * D(1, 2);
  const double dr_dx = inv_sigma * D(2, 0), dr_dz = inv_sigma * D(2, 2);
  jacobian->row(0) << du_dx, 0.0, du_dz, du_dz * y, du_dx * z - du_dz * x, -du_dx * y;
  jacobian->row(1) << 0.0, dv_dy, dv_dz, dv_dz * y - dv_dy * z, -dv_dz * x, dv_dy * x;
  jacobian->row(2) << dr_dx, 0.0, dr_dz, dr_dz * y, dr_dx * z - dr_dz * x, -dr_dx * y;
  residual->head<2>() = inv_sigma * (proj.uvr_px.head<2>() - observation.uv_px);
  if (observation.u_right_px < 0.0) {
    (*residual)(2) = 0.0;
    jacobian->row(2).setZero();
    return 2;
  }
  (*residual)(2) = inv_sigma * (proj.uvr_px(2) - observation.u_right_px);
  return 3;
}

bool refineCameraPose(const StereoRig& rig, const PoseRefinerConfig& config,
                      const PoseObservation* observations, int count, std::uint8_t* inlier,
                      CameraPoseEstimate* pose) {
  for (int i = 0; i < count; ++i) inlier[i] = 1;
  Eigen::Matrix<double, 6, 6> H;
  Eigen::Matrix<double, 6, 1> g;
  double cost = 0.0;
  double squared_px = 0.0;
  Eigen::Vector3d r;
  Eigen::Matrix<double, 3, 6> J;
  for (int round = 0; round < config.rounds; ++round) {
    for (int it = 0; it < config.iterations; ++it) {
      if (accumulate(rig, config, observations, count, inlier, *pose, &H, &g, &cost, &squared_px) <
          6)
        return false;
      const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(H);
      if (ldlt.info() != Eigen::Success || !ldlt.isPositive()) return false;
      const Eigen::Matrix<double, 6, 1> xi = -ldlt.solve(g);
      if (!xi.allFinite()) return false;
      const Eigen::Matrix3d dR = expSo3(xi.tail<3>());
      pose->R_cam_world = dR * pose->R_cam_world;
      pose->p_world_in_cam_m = dR * pose->p_world_in_cam_m + xi.head<3>();
      if (xi.squaredNorm() < 1e-16) break;
    }
    // Classify every observation, including those set aside, against its chi-square gate.
    int inliers = 0;
    for (int i = 0; i < count; ++i) {
      const int m =
          poseResidual(rig, observations[i], pose->R_cam_world, pose->p_world_in_cam_m, &r, &J);
      const double gate = m == 3 ? config.chi2_stereo : config.chi2_mono;
      inlier[i] = m > 0 && r.squaredNorm() <= gate;
      inliers += inlier[i];
    }
    if (inliers < config.min_inliers) return false;
  }
  const int rows =
      accumulate(rig, config, observations, count, inlier, *pose, &H, &g, &cost, &squared_px);
  if (rows <= 6) return false;
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(H);
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive()) return false;
  int inliers = 0;
  for (int i = 0; i < count; ++i) inliers += inlier[i];
  pose->inliers = inliers;
  // The gates keep only the residuals below them: for 2 dof and gate g, E[chi2 | chi2 <= g] / 2 =
  // (1 - e^(-g/2) (1 + g/2)) / (1 - e^(-g/2)) (0.84 for the 95 % gate), which would shrink s^2
  // below 1 for a right noise model. Dividing by it keeps the covariance consistent.
  const double tail = std::exp(-0.5 * config.chi2_mono);
  const double truncation = (1.0 - tail * (1.0 + 0.5 * config.chi2_mono)) / (1.0 - tail);
  pose->residual_variance = cost / (rows - 6) / truncation;
  pose->rms_px = std::sqrt(squared_px / rows);
  pose->cov_xi = pose->residual_variance * ldlt.solve(Eigen::Matrix<double, 6, 6>::Identity());
  return pose->cov_xi.allFinite();
}

}  // namespace deepnav
