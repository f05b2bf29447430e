// Pathak registration of noisy synthetic plane sets with known rotation AND translation: full 6-DoF from
// three planes spanning 3D, and (PlaneRegistrationConfig::subspace) the directions that degenerate sets
// constrain: two planes the rotation and the translation in their span, one plane two rotation axes and
// the translation along its normal. Estimates are checked against their stated sigma, and the covariance
// by the mean NEES over many draws.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "base/so3.h"
#include "nav/ekf/relative_pose_updater.h"
#include "vision/planes/plane_registration.h"

namespace deepnav {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kSigmaN = 0.3 * kDeg;  // per tangent axis of each normal
constexpr double kSigmaD = 0.003;       // m

struct TruePlane {
  Eigen::Vector3d n;
  double d;
};

// Panel face, seabed and a side face (camera optical frame: z forward, y down), normals to the camera.
const TruePlane kFace{Eigen::Vector3d(0.05, 0.1, -1.0).normalized(), -1.6};
const TruePlane kSeabed{Eigen::Vector3d(0.0, -0.95, -0.3).normalized(), -1.2};
const TruePlane kSide{Eigen::Vector3d(0.8, 0.05, -0.6).normalized(), -1.4};

Eigen::Isometry3d motion() {
  Eigen::Isometry3d T_a_b = Eigen::Isometry3d::Identity();
  T_a_b.linear() = Eigen::AngleAxisd(2.0 * kDeg, Eigen::Vector3d(0.2, 1.0, -0.3).normalized()).toRotationMatrix();
  T_a_b.translation() = Eigen::Vector3d(0.06, -0.03, 0.05);
  return T_a_b;
}

// A plane drawn from its covariance: normal tilted on its tangent by N(0, sigma_n^2) per axis, offset
// by N(0, sigma_d^2); the stored covariance is that of the draw.
Plane noisyPlane(const Eigen::Vector3d& n, double d, std::mt19937_64& rng, bool noisy) {
  std::normal_distribution<double> g(0.0, 1.0);
  const Eigen::Vector3d t1 = n.unitOrthogonal();
  const Eigen::Vector3d t2 = n.cross(t1);
  Plane p;
  p.n_in_cam = noisy ? (n + kSigmaN * (g(rng) * t1 + g(rng) * t2)).normalized() : n;
  p.d_m = d + (noisy ? kSigmaD * g(rng) : 0.0);
  p.point_count = 5000;
  p.covariance.topLeftCorner<3, 3>() = kSigmaN * kSigmaN * (t1 * t1.transpose() + t2 * t2.transpose());
  p.covariance(3, 3) = kSigmaD * kSigmaD;
  p.log_pdet_hessian = 30.0;
  return p;
}

// Image a sees the planes as given, image b from T_a_b: n_b = R^T n_a, d_b = d_a - n_a . t.
void makeSets(const std::vector<TruePlane>& planes, const Eigen::Isometry3d& T_a_b, std::mt19937_64& rng,
              bool noisy, PlaneSet* a, PlaneSet* b) {
  ASSERT_TRUE(a->allocate(8, 1, 1));
  ASSERT_TRUE(b->allocate(8, 1, 1));
  for (const TruePlane& p : planes) {
    *a->addPlane() = noisyPlane(p.n, p.d, rng, noisy);
    *b->addPlane() =
        noisyPlane(T_a_b.linear().transpose() * p.n, p.d - p.n.dot(T_a_b.translation()), rng, noisy);
  }
}

PlaneRegistrationConfig subspaceConfig() {
  PlaneRegistrationConfig c;
  c.subspace = true;
  return c;
}

// [t_est - t_true; Log(R_true^T R_est)] and its NEES on the constrained directions (k of them).
struct Score {
  Eigen::Matrix<double, 6, 1> error;
  double nees = 0.0;
  int dof = 0;
  MeasMatrix basis;
};

Score score(const PlaneRegistrationResult& r, const Eigen::Isometry3d& T_a_b) {
  Score s;
  s.error.head<3>() = r.p_camb_in_cama_m - T_a_b.translation();
  s.error.tail<3>() = logSo3(T_a_b.linear().transpose() * r.q_cama_camb.toRotationMatrix());
  MeasVector var;
  s.dof = relativePoseConstrainedBasis(r.cov, &s.basis, &var);
  const MeasVector e = s.basis.transpose() * s.error;
  for (int i = 0; i < s.dof; ++i) s.nees += e(i) * e(i) / var(i);
  return s;
}

// Mean NEES of n draws of a k-dof chi-square: within 3.5 sigma of k (sigma = sqrt(2k / n)).
void expectMeanNeesConsistent(const std::vector<TruePlane>& planes, int expected_dof, int draws) {
  std::mt19937_64 rng(11);
  PlaneRegistrar registrar;
  ASSERT_TRUE(registrar.init(subspaceConfig()));
  double sum = 0.0;
  for (int i = 0; i < draws; ++i) {
    PlaneSet a, b;
    makeSets(planes, motion(), rng, true, &a, &b);
    PlaneRegistrationResult r;
    ASSERT_TRUE(registrar.registerPlanes(a, b, &r));
    const Score s = score(r, motion());
    ASSERT_EQ(s.dof, expected_dof);
    sum += s.nees;
  }
  const double mean = sum / draws;
  EXPECT_NEAR(mean, expected_dof, 3.5 * std::sqrt(2.0 * expected_dof / draws)) << planes.size() << " planes";
}

TEST(PlaneSubspaceRegistration, ThreePlanesGiveTheFullPoseWithinItsSigma) {
  // GIVEN the panel face, the seabed and a side face seen from two poses, with noise
  std::mt19937_64 rng(1);
  PlaneSet a, b;
  makeSets({kFace, kSeabed, kSide}, motion(), rng, true, &a, &b);
  PlaneRegistrar registrar;
  ASSERT_TRUE(registrar.init(subspaceConfig()));
  // WHEN registered
  PlaneRegistrationResult r;
  ASSERT_TRUE(registrar.registerPlanes(a, b, &r));
  // THEN rotation and translation are both fully constrained and within 4 sigma per axis
  EXPECT_TRUE(r.valid);
  EXPECT_TRUE(r.has_translation);
  EXPECT_EQ(r.rotation_dims, 3);
  EXPECT_EQ(r.translation_dims, 3);
  const Score s = score(r, motion());
  ASSERT_EQ(s.dof, 6);
  for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(s.error(i)), 4.0 * std::sqrt(r.cov(i, i))) << i;
  EXPECT_LT(s.error.tail<3>().norm(), 1.0 * kDeg);
  EXPECT_LT(s.error.head<3>().norm(), 0.02);
}

TEST(PlaneSubspaceRegistration, TwoPlanesGiveRotationAndTheTranslationInTheirSpan) {
  // GIVEN the panel face and the seabed, without noise
  std::mt19937_64 rng(2);
  PlaneSet a, b;
  makeSets({kFace, kSeabed}, motion(), rng, false, &a, &b);
  PlaneRegistrar registrar;
  ASSERT_TRUE(registrar.init(subspaceConfig()));
  PlaneRegistrationResult r;
  ASSERT_TRUE(registrar.registerPlanes(a, b, &r));
  // THEN the rotation is exact and the translation along both normals too
  EXPECT_EQ(r.rotation_dims, 3);
  EXPECT_EQ(r.translation_dims, 2);
  EXPECT_TRUE(r.has_translation);
  EXPECT_LT(r.q_cama_camb.angularDistance(Eigen::Quaterniond(motion().linear())), 1e-9);
  for (const TruePlane& p : {kFace, kSeabed}) {
    EXPECT_NEAR(p.n.dot(r.p_camb_in_cama_m), p.n.dot(motion().translation()), 1e-9);
  }
  // AND the unconstrained translation is the intersection line of the two planes (no component there)
  const Eigen::Vector3d line = kFace.n.cross(kSeabed.n).normalized();
  EXPECT_NEAR(line.dot(r.p_camb_in_cama_m), 0.0, 1e-9);
  const Score s = score(r, motion());
  ASSERT_EQ(s.dof, 5);
  Eigen::Matrix<double, 6, 1> e_line = Eigen::Matrix<double, 6, 1>::Zero();
  e_line.head<3>() = line;
  const Eigen::Matrix<double, 6, 6> P = s.basis * s.basis.transpose();
  EXPECT_NEAR((P * e_line).norm(), 0.0, 1e-9);
  EXPECT_GT(line.dot(r.cov.topLeftCorner<3, 3>() * line), kRelativePoseUnconstrainedVariance);
}

TEST(PlaneSubspaceRegistration, OnePlaneGivesTwoRotationAxesAndTheTranslationAlongItsNormal) {
  // GIVEN the panel face alone, without noise
  std::mt19937_64 rng(3);
  PlaneSet a, b;
  makeSets({kFace}, motion(), rng, false, &a, &b);
  PlaneRegistrar registrar;
  ASSERT_TRUE(registrar.init(subspaceConfig()));
  PlaneRegistrationResult r;
  ASSERT_TRUE(registrar.registerPlanes(a, b, &r));
  // THEN not valid as a full rotation, but two rotation axes and one translation direction constrained
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.rotation_dims, 2);
  EXPECT_EQ(r.translation_dims, 1);
  // AND the rotation is the smallest one taking the normal of b onto that of a (nothing about it)
  EXPECT_LT((r.q_cama_camb * b[0].n_in_cam - a[0].n_in_cam).norm(), 1e-12);
  const Eigen::Vector3d n_b = b[0].n_in_cam;
  EXPECT_NEAR(Eigen::AngleAxisd(r.q_cama_camb).axis().dot(n_b), 0.0, 1e-9);
  // AND the constrained subspace: translation along n_a; rotation across n_b (about b's axes)
  const Score s = score(r, motion());
  ASSERT_EQ(s.dof, 3);
  const Eigen::Matrix<double, 6, 6> P = s.basis * s.basis.transpose();
  Eigen::Matrix<double, 6, 1> t_n = Eigen::Matrix<double, 6, 1>::Zero(), r_n = t_n;
  t_n.head<3>() = kFace.n;
  r_n.tail<3>() = n_b;
  EXPECT_NEAR((P * t_n - t_n).norm(), 0.0, 1e-9);
  EXPECT_NEAR((P * r_n).norm(), 0.0, 1e-9);
  EXPECT_NEAR(kFace.n.dot(r.p_camb_in_cama_m), kFace.n.dot(motion().translation()), 1e-9);
}

TEST(PlaneSubspaceRegistration, WithoutSubspaceTwoPlanesKeepThePapersRotationOnlyResult) {
  std::mt19937_64 rng(4);
  PlaneSet a, b;
  makeSets({kFace, kSeabed}, motion(), rng, false, &a, &b);
  PlaneRegistrar registrar;
  ASSERT_TRUE(registrar.init(PlaneRegistrationConfig{}));
  PlaneRegistrationResult r;
  ASSERT_TRUE(registrar.registerPlanes(a, b, &r));
  EXPECT_TRUE(r.valid);
  EXPECT_FALSE(r.has_translation);
  EXPECT_EQ(r.translation_dims, 0);
}

TEST(PlaneSubspaceRegistration, CovarianceIsConsistentOverManyDraws) {
  // GIVEN 400 noisy draws of each set, WHEN registered, THEN the mean NEES on the constrained directions
  // is that of a chi-square with as many dof: 6 (three planes), 5 (two planes), 3 (one plane)
  expectMeanNeesConsistent({kFace, kSeabed, kSide}, 6, 400);
  expectMeanNeesConsistent({kFace, kSeabed}, 5, 400);
  expectMeanNeesConsistent({kFace}, 3, 400);
}

}  // namespace
}  // namespace deepnav
