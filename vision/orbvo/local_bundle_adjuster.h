#pragma once
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "vision/orbvo/stereo_rig.h"

namespace deepnav {

struct BundleAdjusterConfig {
  int iterations = 6;            // Levenberg-Marquardt steps (accepted or not), >= 1
  double huber_k = 2.45;         // Huber threshold on the whitened residual norm
  double chi2_mono = 5.991;      // outlier gate of a left-only observation after the solve
  double chi2_stereo = 7.815;    // outlier gate of a stereo observation after the solve
  double initial_lambda = 1e-4;  // LM damping, relative to the diagonal
};

// One observation of point `point` by camera `camera` (left pixel, optional right column).
struct BaObservation {
  int camera = 0;
  int point = 0;
  Eigen::Vector2d uv_px = Eigen::Vector2d::Zero();
  double u_right_px = -1.0;  // < 0: left only
  double sigma_px = 1.0;
};

struct BundleAdjusterSummary {
  double initial_cost = 0.0;  // robust cost sum rho(|r|^2 / sigma^2)
  double final_cost = 0.0;
  int accepted_steps = 0;
  int outliers = 0;
};

// Windowed bundle adjustment of camera poses T_cam_world (left perturbation as in refineCameraPose)
// and world points, by Levenberg-Marquardt on the Huber-weighted stereo reprojection error. Each
// step eliminates the points with the Schur complement (Triggs et al., "Bundle adjustment - a
// modern synthesis", 2000): with the camera block U, point blocks V_j and cross blocks W,
//   (U - W V^-1 W^T) dc = b_c - W V^-1 b_p,    dp_j = V_j^-1 (b_pj - W_j^T dc),
// the reduced camera system being small and dense (6 per free camera). Cameras [0, n_fixed) stay
// fixed and hold the gauge. Every buffer is sized in init(); optimise() does not allocate.
class LocalBundleAdjuster {
 public:
  bool init(int max_cameras, int max_points, int max_observations);

  // Refines the poses of cameras [n_fixed, n_cameras) and every point in place; outlier[k] (n_obs
  // entries) flags the observations beyond their chi-square gate at the end. False for bad sizes.
  bool optimise(const StereoRig& rig, const BundleAdjusterConfig& config, int n_cameras,
                int n_fixed, Eigen::Matrix3d* R_cam_world, Eigen::Vector3d* p_world_in_cam_m,
                int n_points, Eigen::Vector3d* p_in_world_m, int n_observations,
                const BaObservation* observations, std::uint8_t* outlier,
                BundleAdjusterSummary* summary);

 private:
  double linearise(const StereoRig& rig, const BundleAdjusterConfig& config,
                   const Eigen::Matrix3d* R, const Eigen::Vector3d* t,
                   const Eigen::Vector3d* points, int n_obs, const BaObservation* obs,
                   bool with_jacobians);
  bool solveStep(int n_cameras, int n_fixed, int n_points, const BaObservation* obs, double lambda);

  int max_cameras_ = 0;
  int max_points_ = 0;
  int max_observations_ = 0;
  // Per observation.
  std::vector<Eigen::Matrix<double, 3, 6>> jc_;
  std::vector<Eigen::Matrix3d> jp_;
  std::vector<Eigen::Vector3d> residual_;
  std::vector<int> rows_;
  std::vector<double> weight_;
  std::vector<int> by_point_;     // observation indices grouped by point
  std::vector<int> point_start_;  // by_point_[point_start_[j] .. point_start_[j+1])
  // Per point.
  std::vector<Eigen::Matrix3d> v_inv_;
  std::vector<Eigen::Vector3d> b_p_;
  std::vector<Eigen::Vector3d> dp_;
  std::vector<Eigen::Vector3d> point_backup_;
  std::vector<Eigen::Matrix<double, 6, 3>> y_;  // per observation: W V^-1
  // Per camera.
  std::vector<Eigen::Matrix3d> R_backup_;
  std::vector<Eigen::Vector3d> t_backup_;
  Eigen::MatrixXd reduced_;  // 6 max_cameras square; unused cameras carry the identity
  Eigen::VectorXd rhs_;
  Eigen::VectorXd dc_;
  Eigen::LDLT<Eigen::MatrixXd> ldlt_;
  std::vector<Eigen::Matrix<double, 6, 6>> u_;  // camera blocks of J^T W J
  std::vector<Eigen::Matrix<double, 6, 1>> b_c_;
};

}  // namespace deepnav
