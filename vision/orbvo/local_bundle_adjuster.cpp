#include "vision/orbvo/local_bundle_adjuster.h"

#include <algorithm>
#include <cmath>

#include "base/so3.h"
#include "vision/orbvo/stereo_projection.h"

namespace deepnav {
namespace {

constexpr double kMinDepthM = 1e-3;
// Cost of an observation whose point went behind the camera
constexpr double kBehindCameraCost = 1e6;

// Huber's rho of a squared whitened residual e2.
double huberCost(double e2, double k) {
  const double e = std::sqrt(e2);
  return e <= k ? e2 : 2.0 * k * e - k * k;
}

}  // namespace

bool LocalBundleAdjuster::init(int max_cameras, int max_points, int max_observations) {
  if (max_cameras < 2 || max_points < 1 || max_observations < 1) return false;
  max_cameras_ = max_cameras;
  max_points_ = max_points;
  max_observations_ = max_observations;
  jc_.resize(max_observations);
  jp_.resize(max_observations);
  residual_.resize(max_observations);
  rows_.resize(max_observations);
  weight_.resize(max_observations);
  by_point_.resize(max_observations);
  y_.resize(max_observations);
  point_start_.resize(max_points + 1);
  v_inv_.resize(max_points);
  b_p_.resize(max_points);
  dp_.resize(max_points);
  point_backup_.resize(max_points);
  R_backup_.resize(max_cameras);
  t_backup_.resize(max_cameras);
  u_.resize(max_cameras);
  b_c_.resize(max_cameras);
  rhs_.setZero(6 * max_cameras);
  dc_.setZero(6 * max_cameras);
  // Sizes the factorisation's storage (LDLT's size constructor leaves its status unset: no copy).
  reduced_.setIdentity(6 * max_cameras, 6 * max_cameras);
  ldlt_.compute(reduced_);
  return true;
}

double LocalBundleAdjuster::linearise(const StereoRig& rig, const BundleAdjusterConfig& config,
                                      const Eigen::Matrix3d* R, const Eigen::Vector3d* t,
                                      const Eigen::Vector3d* points, int n_obs,
                                      const BaObservation* obs, bool with_jacobians) {
  double cost = 0.0;
  for (int k = 0; k < n_obs; ++k) {
    const BaObservation& o = obs[k];
    const Eigen::Vector3d p_in_cam_m = R[o.camera] * points[o.point] + t[o.camera];
    if (p_in_cam_m.z() < kMinDepthM) {
      if (with_jacobians) rows_[k] = 0;
      cost += kBehindCameraCost;
      continue;
    }
    const StereoProjection proj = projectStereo(rig, p_in_cam_m);
    const double inv_sigma = 1.0 / o.sigma_px;
    const int m = o.u_right_px < 0.0 ? 2 : 3;
    Eigen::Vector3d r;
    r.head<2>() = inv_sigma * (proj.uvr_px.head<2>() - o.uv_px);
    r(2) = m == 3 ? inv_sigma * (proj.uvr_px(2) - o.u_right_px) : 0.0;
    const double e2 = r.squaredNorm();
    cost += huberCost(e2, config.huber_k);
    if (!with_jacobians) continue;
    rows_[k] = m;
    residual_[k] = r;
    const double e = std::sqrt(e2);
    weight_[k] = e <= config.huber_k ? 1.0 : config.huber_k / e;
    Eigen::Matrix<double, 3, 6> d_p_d_xi;
    d_p_d_xi.leftCols<3>().setIdentity();
    d_p_d_xi.rightCols<3>() = -skew(p_in_cam_m);
    jc_[k] = inv_sigma * proj.d_uvr_d_p * d_p_d_xi;
    jp_[k] = inv_sigma * proj.d_uvr_d_p * R[o.camera];
    if (m == 2) {
      jc_[k].row(2).setZero();
      jp_[k].row(2).setZero();
    }
  }
  return cost;
}

// One damped Gauss-Newton step on the reduced camera system; fills dc_ and dp_.
bool LocalBundleAdjuster::solveStep(int n_cameras, int n_fixed, int n_points,
                                    const BaObservation* obs, double lambda) {
  const int n_free = n_cameras - n_fixed;
  for (int c = 0; c < n_free; ++c) {
    u_[c].setZero();
    b_c_[c].setZero();
  }
  reduced_.setZero();
  rhs_.setZero();
  for (int j = 0; j < n_points; ++j) {
    Eigen::Matrix3d V = Eigen::Matrix3d::Zero();
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    for (int a = point_start_[j]; a < point_start_[j + 1]; ++a) {
      const int k = by_point_[a];
      if (rows_[k] == 0) continue;
      V += weight_[k] * jp_[k].transpose() * jp_[k];
      b -= weight_[k] * jp_[k].transpose() * residual_[k];
      const int c = obs[k].camera - n_fixed;
      if (c < 0) continue;
      u_[c] += weight_[k] * jc_[k].transpose() * jc_[k];
      b_c_[c] -= weight_[k] * jc_[k].transpose() * residual_[k];
    }
    V.diagonal() *= 1.0 + lambda;
    V.diagonal().array() += 1e-9;
    v_inv_[j] = V.inverse();
    b_p_[j] = b;
    // Schur complement of point j: -W_a V^-1 W_b^T for every pair of its free cameras.
    for (int a = point_start_[j]; a < point_start_[j + 1]; ++a) {
      const int ka = by_point_[a];
      const int ca = obs[ka].camera - n_fixed;
      if (rows_[ka] == 0 || ca < 0) continue;
      const Eigen::Matrix<double, 6, 3> W_a = weight_[ka] * jc_[ka].transpose() * jp_[ka];
      y_[ka] = W_a * v_inv_[j];
      rhs_.segment<6>(6 * ca) -= y_[ka] * b;
      for (int bb = point_start_[j]; bb < point_start_[j + 1]; ++bb) {
        const int kb = by_point_[bb];
        const int cb = obs[kb].camera - n_fixed;
        if (rows_[kb] == 0 || cb < 0) continue;
        const Eigen::Matrix<double, 6, 3> W_b = weight_[kb] * jc_[kb].transpose() * jp_[kb];
        reduced_.block<6, 6>(6 * ca, 6 * cb) -= y_[ka] * W_b.transpose();
      }
    }
  }
  for (int c = 0; c < n_free; ++c) {
    Eigen::Matrix<double, 6, 6> U = u_[c];
    U.diagonal() *= 1.0 + lambda;
    U.diagonal().array() += 1e-9;
    reduced_.block<6, 6>(6 * c, 6 * c) += U;
    rhs_.segment<6>(6 * c) += b_c_[c];
  }
  for (int c = n_free; c < max_cameras_; ++c) reduced_.block<6, 6>(6 * c, 6 * c).setIdentity();
  ldlt_.compute(reduced_);
  if (ldlt_.info() != Eigen::Success) return false;
  dc_ = ldlt_.solve(rhs_);
  if (!dc_.allFinite()) return false;
  for (int j = 0; j < n_points; ++j) {
    Eigen::Vector3d b = b_p_[j];
    for (int a = point_start_[j]; a < point_start_[j + 1]; ++a) {
      const int k = by_point_[a];
      const int c = obs[k].camera - n_fixed;
      if (rows_[k] == 0 || c < 0) continue;
      b -= (weight_[k] * jc_[k].transpose() * jp_[k]).transpose() * dc_.segment<6>(6 * c);
    }
    dp_[j] = v_inv_[j] * b;
  }
  return true;
}

bool LocalBundleAdjuster::optimise(const StereoRig& rig, const BundleAdjusterConfig& config,
                                   int n_cameras, int n_fixed, Eigen::Matrix3d* R_cam_world,
                                   Eigen::Vector3d* p_world_in_cam_m, int n_points,
                                   Eigen::Vector3d* p_in_world_m, int n_observations,
                                   const BaObservation* observations, std::uint8_t* outlier,
                                   BundleAdjusterSummary* summary) {
  *summary = BundleAdjusterSummary();
  if (n_cameras < 1 || n_cameras > max_cameras_ || n_fixed < 1 || n_fixed > n_cameras ||
      n_points < 0 || n_points > max_points_ || n_observations < 0 ||
      n_observations > max_observations_) {
    return false;
  }
  // Group observations by point (counting sort).
  std::fill_n(point_start_.begin(), n_points + 1, 0);
  for (int k = 0; k < n_observations; ++k) ++point_start_[observations[k].point + 1];
  for (int j = 0; j < n_points; ++j) point_start_[j + 1] += point_start_[j];
  for (int k = 0; k < n_observations; ++k) by_point_[point_start_[observations[k].point]++] = k;
  for (int j = n_points; j > 0; --j) point_start_[j] = point_start_[j - 1];
  point_start_[0] = 0;

  double lambda = config.initial_lambda;
  double cost = linearise(rig, config, R_cam_world, p_world_in_cam_m, p_in_world_m, n_observations,
                          observations, true);
  summary->initial_cost = cost;
  for (int it = 0; it < config.iterations && n_cameras > n_fixed; ++it) {
    if (!solveStep(n_cameras, n_fixed, n_points, observations, lambda)) break;
    for (int c = n_fixed; c < n_cameras; ++c) {
      R_backup_[c] = R_cam_world[c];
      t_backup_[c] = p_world_in_cam_m[c];
      const Eigen::Matrix<double, 6, 1> xi = dc_.segment<6>(6 * (c - n_fixed));
      const Eigen::Matrix3d dR = expSo3(xi.tail<3>());
      R_cam_world[c] = dR * R_cam_world[c];
      p_world_in_cam_m[c] = dR * p_world_in_cam_m[c] + xi.head<3>();
    }
    for (int j = 0; j < n_points; ++j) {
      point_backup_[j] = p_in_world_m[j];
      p_in_world_m[j] += dp_[j];
    }
    const double new_cost = linearise(rig, config, R_cam_world, p_world_in_cam_m, p_in_world_m,
                                      n_observations, observations, false);
    if (new_cost < cost) {
      ++summary->accepted_steps;
      const double gain = (cost - new_cost) / std::max(cost, 1e-12);
      cost = new_cost;
      lambda = std::max(lambda / 10.0, 1e-9);
      linearise(rig, config, R_cam_world, p_world_in_cam_m, p_in_world_m, n_observations,
                observations, true);
      if (gain < 1e-6) break;
    } else {
      for (int c = n_fixed; c < n_cameras; ++c) {
        R_cam_world[c] = R_backup_[c];
        p_world_in_cam_m[c] = t_backup_[c];
      }
      for (int j = 0; j < n_points; ++j) p_in_world_m[j] = point_backup_[j];
      lambda *= 10.0;
    }
  }
  summary->final_cost = cost;
  // Classify at the final state.
  linearise(rig, config, R_cam_world, p_world_in_cam_m, p_in_world_m, n_observations, observations,
            true);
  for (int k = 0; k < n_observations; ++k) {
    const double gate = rows_[k] == 3 ? config.chi2_stereo : config.chi2_mono;
    outlier[k] = rows_[k] == 0 || residual_[k].squaredNorm() > gate;
    summary->outliers += outlier[k];
  }
  return true;
}

}  // namespace deepnav
