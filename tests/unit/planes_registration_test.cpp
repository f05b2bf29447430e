#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "tests/support/synthetic_scene.h"
#include "tests/unit/planes_test_scene.h"
#include "vision/cloud/cloud_from_disparity.h"
#include "vision/planes/plane_extractor.h"
#include "vision/planes/plane_registration.h"

namespace deepnav {
namespace {

using namespace planes_test;

void extractPlanes(const SyntheticScene& scene, const Eigen::Isometry3d& T_world_cam,
                   double sigma_px, int seed, PlaneSet* planes) {
  SyntheticView view;
  renderSyntheticView(scene, geometry(), kWidth, kHeight, T_world_cam, false, &view);
  cv::Mat noise(view.disparity_px.size(), CV_32FC1);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::NORMAL, 0.0, sigma_px);
  cv::add(view.disparity_px, noise, view.disparity_px, view.disparity_px > 0.0f);
  CloudFromDisparity builder;
  ASSERT_TRUE(builder.init(geometry(), CloudConfig{}, kWidth, kHeight));
  OrganizedCloud cloud;
  ASSERT_TRUE(builder.allocateCloud(&cloud));
  ASSERT_TRUE(builder.compute(view.disparity_px, &cloud));
  PlaneExtractionConfig config;
  config.min_area_px = 1500;
  config.disparity_noise_px = sigma_px;
  PlaneExtractor extractor;
  ASSERT_TRUE(extractor.init(config, geometry(), kHeight, kWidth, 1));
  ASSERT_TRUE(extractor.allocatePlaneSet(planes));
  const int count = extractor.extract(cloud, planes);
  ASSERT_EQ(count, 4);
}

// Which rectangle of the scene each extracted plane is (normal within 3 deg, offset within 5 cm).
std::vector<int> surfaceOf(const SyntheticScene& scene, const Eigen::Isometry3d& T_world_cam,
                           const PlaneSet& planes) {
  std::vector<int> surface(planes.size(), -1);
  const Eigen::Isometry3d T_cam_world = T_world_cam.inverse();
  for (int i = 0; i < planes.size(); ++i) {
    for (int id = 0; id < static_cast<int>(scene.rectangles.size()); ++id) {
      Eigen::Vector3d n = T_cam_world.linear() * scene.rectangles[id].normal();
      double d = n.dot(T_cam_world * scene.rectangles[id].centre_m);
      if (d > 0.0) {
        n = -n;
        d = -d;
      }
      if (planes[i].n_in_cam.dot(n) > std::cos(3.0 * kDeg) && std::abs(planes[i].d_m - d) < 0.05) {
        surface[i] = id;
      }
    }
    EXPECT_GE(surface[i], 0) << "plane " << i << " is no surface of the scene";
  }
  return surface;
}

// A plane with an isotropic normal uncertainty sigma_n (rad, on its tangent) and offset sigma_d.
Plane makePlane(const Eigen::Vector3d& n, double d, double sigma_n, double sigma_d,
                double log_size) {
  Plane p;
  p.n_in_cam = n.normalized();
  p.d_m = d;
  p.point_count = 5000;
  const Eigen::Vector3d t1 = p.n_in_cam.unitOrthogonal();
  const Eigen::Vector3d t2 = p.n_in_cam.cross(t1);
  p.covariance.topLeftCorner<3, 3>() =
      sigma_n * sigma_n * (t1 * t1.transpose() + t2 * t2.transpose());
  p.covariance(3, 3) = sigma_d * sigma_d;
  p.log_pdet_hessian = log_size;
  return p;
}

// The plane as seen from a camera at T_a_b (pose of b in a): n_b = R^T n_a, d_b = d_a - n_a . t.
Plane transformToB(const Plane& a, const Eigen::Isometry3d& T_a_b) {
  Plane b = a;
  b.n_in_cam = T_a_b.linear().transpose() * a.n_in_cam;
  b.d_m = a.d_m - a.n_in_cam.dot(T_a_b.translation());
  const Eigen::Matrix3d Rt = T_a_b.linear().transpose();
  b.covariance.topLeftCorner<3, 3>() = Rt * a.covariance.topLeftCorner<3, 3>() * Rt.transpose();
  return b;
}

void copyPlanes(const PlaneSet& from, const std::vector<int>& order, PlaneSet* to) {
  for (int i : order) *to->addPlane() = from[i];
}

Eigen::Isometry3d motion() {
  Eigen::Isometry3d T_a_b = Eigen::Isometry3d::Identity();
  T_a_b.linear() =
      Eigen::AngleAxisd(4.0 * kDeg, Eigen::Vector3d(0.3, 1.0, 0.2).normalized()).toRotationMatrix();
  T_a_b.translation() = Eigen::Vector3d(0.10, -0.06, 0.08);
  return T_a_b;
}

TEST(PlaneRegistration, RecoversMotionFromTwoNoisyViewsWithUnknownOrderAndSpuriousPlanes) {
  // GIVEN the planes of two noisy (0.15 px) views of a box on the floor, 4 deg and 14 cm apart,
  // in shuffled order, with spurious planes of plausible size added to both sets
  const SyntheticScene scene = boxOnFloor();
  const Eigen::Isometry3d T_world_a = cameraPitchedDown(30.0 * kDeg, Eigen::Vector3d(0.0, 0.0, 1.6));
  const Eigen::Isometry3d T_a_b = motion();
  PlaneSet extracted_a, extracted_b;
  extractPlanes(scene, T_world_a, 0.15, 1, &extracted_a);
  extractPlanes(scene, T_world_a * T_a_b, 0.15, 2, &extracted_b);
  const std::vector<int> surface_a = surfaceOf(scene, T_world_a, extracted_a);
  const std::vector<int> surface_b = surfaceOf(scene, T_world_a * T_a_b, extracted_b);
  PlaneSet a, b;
  ASSERT_TRUE(a.allocate(16, 1, 1));
  ASSERT_TRUE(b.allocate(16, 1, 1));
  std::mt19937 rng(7);
  std::vector<int> order_a(4), order_b(4);
  std::iota(order_a.begin(), order_a.end(), 0);
  std::iota(order_b.begin(), order_b.end(), 0);
  std::shuffle(order_b.begin(), order_b.end(), rng);
  copyPlanes(extracted_a, order_a, &a);
  copyPlanes(extracted_b, order_b, &b);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto spurious = [&](PlaneSet* set) {
    Plane p = (*set)[0];
    p.n_in_cam = Eigen::Vector3d(u(rng), u(rng), -1.5).normalized();
    p.d_m = -1.0 - std::abs(u(rng));
    *set->addPlane() = p;
  };
  spurious(&a);
  spurious(&a);
  for (int k = 0; k < 3; ++k) spurious(&b);
  PlaneRegistrar registrar;
  ASSERT_TRUE(registrar.init(PlaneRegistrationConfig{}));

  // WHEN registered
  PlaneRegistrationResult result;
  ASSERT_TRUE(registrar.registerPlanes(a, b, &result));

  // THEN the four real planes are matched to each other and the motion is recovered
  ASSERT_TRUE(result.valid);
  EXPECT_EQ(result.status, PlaneRegistrationStatus::kOk);
  ASSERT_EQ(result.matched_planes, 4);
  for (int i = 0; i < result.matched_planes; ++i) {
    const PlaneMatch m = result.matches[i];
    ASSERT_LT(m.a, 4);
    ASSERT_LT(m.b, 4);
    EXPECT_EQ(surface_a[order_a[m.a]], surface_b[order_b[m.b]])
        << "plane a " << m.a << " matched to b " << m.b;
  }
  const Eigen::Quaterniond q_true(T_a_b.linear());
  const double angle_error = result.q_cama_camb.angularDistance(q_true);
  EXPECT_LT(angle_error, 0.25 * kDeg);
  ASSERT_TRUE(result.has_translation);
  const Eigen::Vector3d t_error = result.p_camb_in_cama_m - T_a_b.translation();
  EXPECT_LT(t_error.norm(), 0.02) << t_error.transpose();
  // the reported covariance is of the size of the errors (independent-noise model)
  const double sigma_rot = std::sqrt(result.cov.bottomRightCorner<3, 3>().trace());
  EXPECT_LT(sigma_rot, 0.3 * kDeg);
  EXPECT_GT(sigma_rot, 0.005 * kDeg);
}

TEST(PlaneRegistration, CovarianceShrinksWithMorePlanes) {
  // GIVEN four exact planes (floor, two walls, a tilted panel) seen from two poses
  const Eigen::Isometry3d T_a_b = motion();
  const Plane planes[4] = {makePlane(Eigen::Vector3d(0, -0.9, -0.4), -1.5, 0.002, 0.002, 30.0),
                           makePlane(Eigen::Vector3d(0.8, 0.1, -0.6), -1.8, 0.002, 0.002, 30.0),
                           makePlane(Eigen::Vector3d(-0.7, 0.1, -0.7), -2.0, 0.002, 0.002, 30.0),
                           makePlane(Eigen::Vector3d(0.2, -0.3, -0.9), -2.5, 0.002, 0.002, 30.0)};
  PlaneRegistrar registrar;
  ASSERT_TRUE(registrar.init(PlaneRegistrationConfig{}));
  double previous_rot = std::numeric_limits<double>::infinity();
  double previous_trans = std::numeric_limits<double>::infinity();
  for (int count = 1; count <= 4; ++count) {
    PlaneSet a, b;
    ASSERT_TRUE(a.allocate(4, 1, 1));
    ASSERT_TRUE(b.allocate(4, 1, 1));
    for (int i = 0; i < count; ++i) {
      *a.addPlane() = planes[i];
      *b.addPlane() = transformToB(planes[i], T_a_b);
    }
    // WHEN registered with the first `count` planes
    PlaneRegistrationResult result;
    ASSERT_TRUE(registrar.registerPlanes(a, b, &result));
    ASSERT_EQ(result.matched_planes, count);
    const double rot = result.cov.bottomRightCorner<3, 3>().trace();
    const double trans = result.cov.topLeftCorner<3, 3>().trace();
    if (count == 1) {
      // THEN one plane: the normal is aligned, but the turn about it is unobservable
      EXPECT_FALSE(result.valid);
      EXPECT_EQ(result.status, PlaneRegistrationStatus::kRotationUnobservable);
      EXPECT_LT((result.q_cama_camb * b[0].n_in_cam - a[0].n_in_cam).norm(), 1e-9);
      EXPECT_GT(rot, 1e3);
      continue;
    }
    // THEN from two planes on the rotation is exact and its covariance shrinks with each plane
    EXPECT_TRUE(result.valid) << count;
    EXPECT_LT(result.q_cama_camb.angularDistance(Eigen::Quaterniond(T_a_b.linear())), 1e-9);
    EXPECT_LT(rot, previous_rot) << count;
    previous_rot = rot;
    EXPECT_EQ(result.has_translation, count >= 3) << count;
    if (count >= 3) {
      EXPECT_LT((result.p_camb_in_cama_m - T_a_b.translation()).norm(), 1e-9);
      EXPECT_LT(trans, previous_trans) << count;
      previous_trans = trans;
    }
  }
}

TEST(PlaneRegistration, RotationCovarianceMatchesMonteCarloScatter) {
  // GIVEN three planes whose parameters are drawn from their covariances in both views
  const Eigen::Isometry3d T_a_b = motion();
  const Plane truth[3] = {makePlane(Eigen::Vector3d(0, -0.9, -0.4), -1.5, 0.01, 0.005, 30.0),
                          makePlane(Eigen::Vector3d(0.8, 0.1, -0.6), -1.8, 0.004, 0.005, 30.0),
                          makePlane(Eigen::Vector3d(-0.7, 0.1, -0.7), -2.0, 0.006, 0.005, 30.0)};
  std::mt19937 rng(11);
  std::normal_distribution<double> gauss(0.0, 1.0);
  auto perturb = [&](const Plane& p) {
    Plane q = p;
    const Eigen::Matrix4d L = (p.covariance + 1e-18 * Eigen::Matrix4d::Identity()).llt().matrixL();
    const Eigen::Vector4d e = L * Eigen::Vector4d(gauss(rng), gauss(rng), gauss(rng), gauss(rng));
    q.n_in_cam = (p.n_in_cam + e.head<3>()).normalized();
    q.d_m = p.d_m + e(3);
    return q;
  };
  PlaneRegistrar registrar;
  PlaneRegistrationConfig config;
  config.max_residual_angle_deg = 10.0;
  ASSERT_TRUE(registrar.init(config));
  // WHEN registered many times
  constexpr int kTrials = 400;
  Eigen::Matrix3d empirical = Eigen::Matrix3d::Zero(), predicted = Eigen::Matrix3d::Zero();
  for (int k = 0; k < kTrials; ++k) {
    PlaneSet a, b;
    ASSERT_TRUE(a.allocate(3, 1, 1));
    ASSERT_TRUE(b.allocate(3, 1, 1));
    for (const Plane& p : truth) {
      *a.addPlane() = perturb(p);
      *b.addPlane() = perturb(transformToB(p, T_a_b));
    }
    PlaneRegistrationResult result;
    ASSERT_TRUE(registrar.registerPlanes(a, b, &result));
    ASSERT_TRUE(result.valid);
    // right perturbation: q = q_true Exp(e)
    const Eigen::AngleAxisd err(Eigen::Quaterniond(T_a_b.linear()).inverse() * result.q_cama_camb);
    const Eigen::Vector3d e = err.angle() * err.axis();
    empirical += e * e.transpose() / kTrials;
    predicted += result.cov.bottomRightCorner<3, 3>() / kTrials;
  }
  // THEN the predicted rotation covariance agrees with the scatter (per axis, ~7 % sampling error)
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(std::sqrt(empirical(i, i)), std::sqrt(predicted(i, i)),
                0.15 * std::sqrt(predicted(i, i)))
        << i;
  }
}

TEST(PlaneRegistration, SizeTestRejectsPlanesOfDifferentSize) {
  PlaneSet a, b;
  ASSERT_TRUE(a.allocate(2, 1, 1));
  ASSERT_TRUE(b.allocate(2, 1, 1));
  *a.addPlane() = makePlane(Eigen::Vector3d(0, 0, -1), -2.0, 0.01, 0.01, 30.0);
  *b.addPlane() = makePlane(Eigen::Vector3d(0, 0, -1), -2.0, 0.01, 0.01, 40.0);  // e^10 larger
  PlaneRegistrar registrar;
  ASSERT_TRUE(registrar.init(PlaneRegistrationConfig{}));
  PlaneRegistrationResult result;
  ASSERT_TRUE(registrar.registerPlanes(a, b, &result));
  EXPECT_FALSE(result.valid);
  EXPECT_EQ(result.status, PlaneRegistrationStatus::kNoCandidates);
  EXPECT_EQ(result.matched_planes, 0);
}

TEST(PlaneRegistration, ParallelPlanesWithInconsistentOffsetsAreNotMatchedTogether) {
  // GIVEN two parallel planes 0.5 m apart in a, and in b two parallel planes 1.0 m apart plus a
  // wall: the parallel-consistency test allows only one of the parallel pairs
  PlaneSet a, b;
  ASSERT_TRUE(a.allocate(3, 1, 1));
  ASSERT_TRUE(b.allocate(3, 1, 1));
  *a.addPlane() = makePlane(Eigen::Vector3d(0, -1, -0.3), -1.0, 0.002, 0.002, 30.0);
  *a.addPlane() = makePlane(Eigen::Vector3d(0, -1, -0.3), -1.5, 0.002, 0.002, 30.0);
  *a.addPlane() = makePlane(Eigen::Vector3d(1, 0, -0.5), -2.0, 0.002, 0.002, 30.0);
  *b.addPlane() = a[0];
  *b.addPlane() = makePlane(Eigen::Vector3d(0, -1, -0.3), -2.0, 0.002, 0.002, 30.0);
  *b.addPlane() = a[2];
  PlaneRegistrar registrar;
  ASSERT_TRUE(registrar.init(PlaneRegistrationConfig{}));
  PlaneRegistrationResult result;
  ASSERT_TRUE(registrar.registerPlanes(a, b, &result));
  EXPECT_TRUE(result.valid);
  EXPECT_EQ(result.matched_planes, 2);
  EXPECT_FALSE(result.has_translation);  // two directions only
}

}  // namespace
}  // namespace deepnav

namespace deepnav {
namespace {

// A turn about an axis close to both normals barely moves them, so each pair passes the normal-change
// prior; the fitted rotation must respect the prior as well.
TEST(PlaneRegistration, FittedRotationBeyondThePriorIsRejected) {
  // GIVEN two planes 15 deg either side of the camera's -z axis, seen again after a 30 deg turn about z
  Eigen::Isometry3d T_a_b = Eigen::Isometry3d::Identity();
  T_a_b.linear() = Eigen::AngleAxisd(30.0 * kDeg, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Plane p1 = makePlane(Eigen::Vector3d(std::sin(15.0 * kDeg), 0, -std::cos(15.0 * kDeg)), -1.5, 0.002, 0.002, 30.0);
  const Plane p2 = makePlane(Eigen::Vector3d(0, std::sin(15.0 * kDeg), -std::cos(15.0 * kDeg)), -2.0, 0.002, 0.002, 30.0);
  PlaneSet a, b;
  ASSERT_TRUE(a.allocate(2, 1, 1));
  ASSERT_TRUE(b.allocate(2, 1, 1));
  *a.addPlane() = p1;
  *a.addPlane() = p2;
  *b.addPlane() = transformToB(p1, T_a_b);
  *b.addPlane() = transformToB(p2, T_a_b);
  // WHEN registered with a 10 deg prior (each normal moves by under 8 deg)
  PlaneRegistrationConfig config;
  config.max_normal_change_deg = 10.0;
  PlaneRegistrar registrar;
  ASSERT_TRUE(registrar.init(config));
  PlaneRegistrationResult result;
  ASSERT_TRUE(registrar.registerPlanes(a, b, &result));
  // THEN the 30 deg fit is refused as a wrong correspondence
  EXPECT_FALSE(result.valid);
  EXPECT_TRUE(result.rejected_by_prior);
  EXPECT_EQ(result.status, PlaneRegistrationStatus::kNoMatches);
  // and with the default 45 deg prior the same planes give the true turn
  ASSERT_TRUE(registrar.init(PlaneRegistrationConfig{}));
  ASSERT_TRUE(registrar.registerPlanes(a, b, &result));
  ASSERT_TRUE(result.valid);
  EXPECT_FALSE(result.rejected_by_prior);
  EXPECT_LT(result.q_cama_camb.angularDistance(Eigen::Quaterniond(T_a_b.linear())), 1e-6);
}

}  // namespace
}  // namespace deepnav
