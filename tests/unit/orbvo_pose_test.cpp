// Camera pose from 2D-3D stereo correspondences: the residual's analytic Jacobian against numeric
// differentiation, PnP RANSAC and the Huber Gauss-Newton refinement under outliers, the covariance
// against Monte Carlo, and the relative pose covariance propagation.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <vector>

#include "base/so3.h"
#include "vision/orbvo/pnp_ransac.h"
#include "vision/orbvo/pose_refiner.h"
#include "vision/orbvo/relative_camera_pose.h"
#include "vision/orbvo/stereo_projection.h"

namespace deepnav {
namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

CameraPoseEstimate truePose() {
  CameraPoseEstimate pose;
  pose.R_cam_world = expSo3(Eigen::Vector3d(0.05, -0.2, 0.03));
  pose.p_world_in_cam_m = Eigen::Vector3d(0.1, -0.05, 0.3);
  return pose;
}

// Applies the left perturbation xi = (dt, phi): p_in_cam' = Exp(phi) p_in_cam + dt.
CameraPoseEstimate perturbed(const CameraPoseEstimate& pose, const Vector6d& xi) {
  CameraPoseEstimate out = pose;
  const Eigen::Matrix3d dR = expSo3(xi.tail<3>());
  out.R_cam_world = dR * pose.R_cam_world;
  out.p_world_in_cam_m = dR * pose.p_world_in_cam_m + xi.head<3>();
  return out;
}

// Points at 1-3 m spread over the view, observed with N(0, sigma^2) pixel noise; every third has no
// right observation.
std::vector<PoseObservation> observe(const CameraPoseEstimate& pose, int n, double sigma_px,
                                     std::mt19937* rng) {
  const StereoRig rig;
  std::uniform_real_distribution<double> u(30.0, rig.width_px - 30.0),
      v(30.0, rig.height_px - 30.0), z(1.0, 3.0);
  std::normal_distribution<double> noise(0.0, sigma_px);
  std::vector<PoseObservation> out;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d p_in_cam =
        z(*rng) *
        Eigen::Vector3d((u(*rng) - rig.cx_px) / rig.fx_px, (v(*rng) - rig.cy_px) / rig.fy_px, 1.0);
    PoseObservation o;
    o.p_in_world_m = pose.R_cam_world.transpose() * (p_in_cam - pose.p_world_in_cam_m);
    const StereoProjection proj = projectStereo(rig, p_in_cam);
    o.uv_px = proj.uvr_px.head<2>() + Eigen::Vector2d(noise(*rng), noise(*rng));
    o.u_right_px = i % 3 == 2 ? -1.0 : proj.uvr_px(2) + noise(*rng);
    o.sigma_px = sigma_px;
    out.push_back(o);
  }
  return out;
}

TEST(OrbVoPose, ResidualJacobianMatchesNumericDifferentiation) {
  std::mt19937 rng(1);
  const CameraPoseEstimate pose = truePose();
  const StereoRig rig;
  for (const PoseObservation& o : observe(pose, 6, 1.0, &rng)) {
    Eigen::Vector3d r0;
    Eigen::Matrix<double, 3, 6> J;
    const int rows = poseResidual(rig, o, pose.R_cam_world, pose.p_world_in_cam_m, &r0, &J);
    ASSERT_GT(rows, 0);
    constexpr double kStep = 1e-6;
    for (int k = 0; k < 6; ++k) {
      Vector6d xi = Vector6d::Zero();
      xi(k) = kStep;
      const CameraPoseEstimate plus = perturbed(pose, xi);
      const CameraPoseEstimate minus = perturbed(pose, -xi);
      Eigen::Vector3d rp, rm;
      Eigen::Matrix<double, 3, 6> unused;
      poseResidual(rig, o, plus.R_cam_world, plus.p_world_in_cam_m, &rp, &unused);
      poseResidual(rig, o, minus.R_cam_world, minus.p_world_in_cam_m, &rm, &unused);
      const Eigen::Vector3d numeric = (rp - rm) / (2.0 * kStep);
      EXPECT_LT((numeric - J.col(k)).norm(), 1e-4 * std::max(1.0, numeric.norm()))
          << "column " << k;
    }
  }
}

TEST(OrbVoPose, RansacAndHuberRefinementRejectOutliers) {
  std::mt19937 rng(2);
  const CameraPoseEstimate truth = truePose();
  std::vector<PoseObservation> obs = observe(truth, 300, 0.7, &rng);
  // 25 % gross outliers: wrong pixels anywhere in the image.
  std::uniform_real_distribution<double> u(0.0, 688.0), v(0.0, 516.0);
  for (std::size_t i = 0; i < obs.size(); i += 4) obs[i].uv_px = {u(rng), v(rng)};
  const StereoRig rig;
  PnpRansac pnp;
  ASSERT_TRUE(pnp.init(static_cast<int>(obs.size())));
  for (const PoseObservation& o : obs) ASSERT_TRUE(pnp.add(o.p_in_world_m, o.uv_px));
  CameraPoseEstimate pose;
  std::vector<std::uint8_t> inlier(obs.size(), 0);
  ASSERT_TRUE(pnp.solve(rig, PnpRansacConfig(), &pose, inlier.data()));
  EXPECT_LT((pose.p_world_in_cam_m - truth.p_world_in_cam_m).norm(), 0.02);
  ASSERT_TRUE(refineCameraPose(rig, PoseRefinerConfig(), obs.data(), static_cast<int>(obs.size()),
                               inlier.data(), &pose));
  int false_inliers = 0;
  int missed_inliers = 0;
  for (std::size_t i = 0; i < obs.size(); ++i) {
    if (i % 4 == 0) false_inliers += inlier[i];
    if (i % 4 != 0) missed_inliers += !inlier[i];
  }
  EXPECT_LE(false_inliers, 1);
  EXPECT_LT(missed_inliers, 20);  // about 5 % of the good ones fall beyond a 95 % gate
  const Eigen::Vector3d p_err = pose.p_world_in_cam_m - truth.p_world_in_cam_m;
  const double rot_err = logSo3(pose.R_cam_world * truth.R_cam_world.transpose()).norm();
  EXPECT_LT(p_err.norm(), 0.003);
  EXPECT_LT(rot_err, 0.001);
  EXPECT_NEAR(pose.residual_variance, 1.0, 0.25);
}

TEST(OrbVoPose, CovarianceAgreesWithMonteCarlo) {
  // GIVEN many independent noisy observation sets of the same geometry
  std::mt19937 rng(3);
  const CameraPoseEstimate truth = truePose();
  const StereoRig rig;
  constexpr int kTrials = 200;
  double nees = 0.0;
  Matrix6d cov_mean = Matrix6d::Zero();
  Matrix6d scatter = Matrix6d::Zero();
  for (int t = 0; t < kTrials; ++t) {
    std::mt19937 geometry(42);  // same points every trial (noise-free), new noise below
    std::vector<PoseObservation> obs = observe(truth, 80, 1e-12, &geometry);
    std::normal_distribution<double> noise(0.0, 1.0);
    for (PoseObservation& o : obs) {
      o.sigma_px = 1.0;
      o.uv_px += Eigen::Vector2d(noise(rng), noise(rng));
      if (o.u_right_px >= 0.0) o.u_right_px += noise(rng);
    }
    CameraPoseEstimate pose = perturbed(truth, Vector6d::Constant(0.01));
    std::vector<std::uint8_t> inlier(obs.size());
    ASSERT_TRUE(refineCameraPose(rig, PoseRefinerConfig(), obs.data(), static_cast<int>(obs.size()),
                                 inlier.data(), &pose));
    // Error as a left perturbation of the truth: pose = Exp(xi) truth.
    Vector6d xi;
    const Eigen::Matrix3d dR = pose.R_cam_world * truth.R_cam_world.transpose();
    xi.tail<3>() = logSo3(dR);
    xi.head<3>() = pose.p_world_in_cam_m - dR * truth.p_world_in_cam_m;
    nees += xi.dot(pose.cov_xi.ldlt().solve(xi));
    cov_mean += pose.cov_xi / kTrials;
    scatter += xi * xi.transpose() / kTrials;
  }
  // THEN the normalised error is about 6 and the spreads agree.
  nees /= kTrials;
  EXPECT_GT(nees, 4.5);
  EXPECT_LT(nees, 8.0);
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(std::sqrt(scatter(i, i) / cov_mean(i, i)), 1.0, 0.2) << "axis " << i;
  }
}

TEST(OrbVoPose, RelativePoseCovarianceFollowsBothPoses) {
  // GIVEN two camera poses with arbitrary covariances
  CameraPoseEstimate a = truePose();
  CameraPoseEstimate b =
      perturbed(a, (Vector6d() << 0.05, -0.02, 0.1, 0.01, 0.03, -0.02).finished());
  std::mt19937 rng(4);
  std::normal_distribution<double> n01(0.0, 1.0);
  Matrix6d La = Matrix6d::Zero(), Lb = Matrix6d::Zero();
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j <= i; ++j) {
      La(i, j) = (i == j ? 1.0 : 0.3) * 1e-3 * n01(rng);
      Lb(i, j) = (i == j ? 1.0 : 0.3) * 1e-3 * n01(rng);
    }
  }
  a.cov_xi = La * La.transpose();
  b.cov_xi = Lb * Lb.transpose();
  const RelativeCameraPose rel = relativeCameraPose(a, b);
  // The relative pose itself.
  const Eigen::Matrix3d R_ab = a.R_cam_world * b.R_cam_world.transpose();
  EXPECT_LT((rel.q_cama_camb.toRotationMatrix() - R_ab).norm(), 1e-12);
  // WHEN both poses are sampled from their covariances (small: first order holds)
  constexpr int kSamples = 4000;
  Matrix6d scatter = Matrix6d::Zero();
  for (int s = 0; s < kSamples; ++s) {
    Vector6d za, zb;
    for (int i = 0; i < 6; ++i) {
      za(i) = n01(rng);
      zb(i) = n01(rng);
    }
    const RelativeCameraPose sample =
        relativeCameraPose(perturbed(a, La * za), perturbed(b, Lb * zb));
    Vector6d e;
    e.head<3>() = sample.p_camb_in_cama_m - rel.p_camb_in_cama_m;
    // RelativePoseMeasurement convention: R_meas = R_true Exp(n).
    e.tail<3>() = logSo3(rel.q_cama_camb.toRotationMatrix().transpose() *
                         sample.q_cama_camb.toRotationMatrix());
    scatter += e * e.transpose() / kSamples;
  }
  // THEN the propagated covariance matches the sampled one
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(scatter(i, i) / rel.cov(i, i), 1.0, 0.1) << "axis " << i;
  }
  EXPECT_LT((scatter - rel.cov).norm() / rel.cov.norm(), 0.1);
}

}  // namespace
}  // namespace deepnav
