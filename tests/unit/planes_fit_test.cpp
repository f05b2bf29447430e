#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "vision/planes/davenport_q_method.h"
#include "vision/planes/plane_fit.h"

namespace deepnav {
namespace {

constexpr double kFb = 60.0;  // f B, px m
constexpr double kF = 400.0;

// One noisy view of the plane n . p = d over a rows x cols pixel window: the disparity of each
// pixel gets N(0, sigma_d) noise and the point is re-triangulated (noise along the ray).
void noisyPlaneCloud(const Eigen::Vector3d& n, double d, double sigma_d, std::mt19937* rng,
                     OrganizedCloud* cloud) {
  std::normal_distribution<double> noise(0.0, sigma_d);
  for (int r = 0; r < cloud->rows(); ++r) {
    for (int c = 0; c < cloud->cols(); ++c) {
      const Eigen::Vector3d ray((c - cloud->cols() / 2.0) / kF, (r - cloud->rows() / 2.0) / kF,
                                1.0);
      const double z = d / n.dot(ray);
      const double disparity = kFb / z + noise(*rng);
      const Eigen::Vector3d p = ray * (kFb / disparity);
      cloud->row(r)[c] = cv::Vec3f(p.x(), p.y(), p.z());
    }
  }
}

Plane fitAll(const OrganizedCloud& cloud, const PlaneNoiseModel& noise,
             std::vector<std::int32_t>* cells) {
  cells->clear();
  ScatterSums sums;
  const cv::Vec3f& o = cloud.row(0)[0];
  sums.reset(Eigen::Vector3d(o[0], o[1], o[2]));
  for (int r = 0; r < cloud.rows(); ++r) {
    for (int c = 0; c < cloud.cols(); ++c) {
      const cv::Vec3f& p = cloud.row(r)[c];
      sums.add(p[0] - sums.origin.x(), p[1] - sums.origin.y(), p[2] - sums.origin.z());
      cells->push_back(r * cloud.cols() + c);
    }
  }
  Plane plane;
  EXPECT_TRUE(fitPlaneWithUncertainty(cloud, cells->data(), static_cast<int>(cells->size()), sums,
                                      fitPlane(sums).normal, noise, &plane));
  return plane;
}

TEST(PlaneFit, PredictedCovarianceMatchesMonteCarloScatter) {
  // GIVEN a slanted plane 2 m away seen by 60 x 40 pixels with 0.3 px disparity noise, and the
  // matching noise model (no floor)
  const Eigen::Vector3d n_true = Eigen::Vector3d(0.3, 0.4, -1.0).normalized();
  const double d_true = -2.0;
  PlaneNoiseModel noise;
  noise.disparity_noise_per_fb = 0.3 / kFb;
  noise.floor_m = 1e-6;
  OrganizedCloud cloud;
  ASSERT_TRUE(cloud.allocate(40, 60, 1));
  std::mt19937 rng(3);
  std::vector<std::int32_t> cells;
  // tangent basis of the true normal: the covariance is compared on (t1.n, t2.n, d)
  const Eigen::Vector3d t1 = n_true.unitOrthogonal();
  const Eigen::Vector3d t2 = n_true.cross(t1);
  Eigen::Matrix<double, 4, 3> B = Eigen::Matrix<double, 4, 3>::Zero();
  B.block<3, 1>(0, 0) = t1;
  B.block<3, 1>(0, 1) = t2;
  B(3, 2) = 1.0;
  // WHEN fitted over many noisy views
  constexpr int kTrials = 400;
  Eigen::Matrix3d empirical = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d predicted = Eigen::Matrix3d::Zero();
  for (int k = 0; k < kTrials; ++k) {
    noisyPlaneCloud(n_true, d_true, 0.3, &rng, &cloud);
    const Plane plane = fitAll(cloud, noise, &cells);
    const Eigen::Vector3d e(t1.dot(plane.n_in_cam), t2.dot(plane.n_in_cam), plane.d_m - d_true);
    empirical += e * e.transpose() / kTrials;
    predicted += B.transpose() * plane.covariance * B / kTrials;
  }
  // THEN the predicted standard deviations agree with the scatter of the estimates (sampling
  // error of a variance from 400 trials ~7 %)
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(std::sqrt(empirical(i, i)), std::sqrt(predicted(i, i)),
                0.12 * std::sqrt(predicted(i, i)))
        << i;
  }
}

TEST(DavenportQMethod, RecoversRotationAndAnalyticCovarianceOfTwoOrthogonalVectors) {
  // GIVEN x and y of frame b seen in frame a rotated by a known R_a_b, each with weight w
  const Eigen::Quaterniond q_true(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()));
  const double w = 400.0;  // 1 / sigma^2 per axis
  const Eigen::Vector3d v_b[2] = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()};
  const Eigen::Vector3d v_a[2] = {q_true * v_b[0], q_true * v_b[1]};
  const double weights[2] = {w, w};
  // WHEN solved
  QMethodResult result;
  ASSERT_TRUE(davenportQMethod(v_a, v_b, weights, 2, 1e4, &result));
  // THEN the rotation is exact, and the covariance about b's axes is the inverse information
  // diag(w, w, 2 w): a turn about z moves both vectors, about x or y only one
  EXPECT_LT(result.q_a_b.angularDistance(q_true), 1e-9);
  EXPECT_EQ(result.observable_dims, 3);
  const Eigen::Matrix3d expected = Eigen::Vector3d(1.0 / w, 1.0 / w, 0.5 / w).asDiagonal();
  EXPECT_TRUE(result.cov_rotvec_rad2.isApprox(expected, 1e-6)) << result.cov_rotvec_rad2;
}

TEST(DavenportQMethod, OneVectorLeavesTheTurnAboutItUnobservable) {
  const Eigen::Vector3d v_b[1] = {Eigen::Vector3d(0, 0, 1)};
  const Eigen::Vector3d v_a[1] = {Eigen::Vector3d(0, 1, 1).normalized()};
  const double weights[1] = {100.0};
  QMethodResult result;
  ASSERT_TRUE(davenportQMethod(v_a, v_b, weights, 1, 1e4, &result));
  EXPECT_EQ(result.observable_dims, 2);
  EXPECT_LT((result.q_a_b * v_b[0] - v_a[0]).norm(), 1e-9);  // the normal is aligned
  // the variance about the vector itself (in frame b: z) is the unobservable one
  EXPECT_NEAR(v_b[0].dot(result.cov_rotvec_rad2 * v_b[0]), 1e4, 1.0);
}

TEST(PlaneFit, RunsInSimdBlocksMatchTheCellByCellFitNearANeighbour) {
  // GIVEN a slanted noisy plane over 63 x 20 cells (rows are runs of 15 blocks of four and a tail
  // of three) and a neighbouring plane cutting it near the middle column, so that the band test
  // drops some cells of every row
  const Eigen::Vector3d n_true = Eigen::Vector3d(0.3, 0.4, -1.0).normalized();
  PlaneNoiseModel noise;
  noise.disparity_noise_per_fb = 0.3 / kFb;
  OrganizedCloud cloud;
  ASSERT_TRUE(cloud.allocate(20, 63, 1));
  std::mt19937 rng(7);
  noisyPlaneCloud(n_true, -2.0, 0.3, &rng, &cloud);
  std::vector<std::int32_t> cells;
  const Plane reference = fitAll(cloud, noise, &cells);
  ScatterSums sums;
  const cv::Vec3f& o = cloud.row(0)[0];
  sums.reset(Eigen::Vector3d(o[0], o[1], o[2]));
  for (int r = 0; r < cloud.rows(); ++r) {
    for (int c = 0; c < cloud.cols(); ++c) {
      const cv::Vec3f& p = cloud.row(r)[c];
      sums.add(p[0] - sums.origin.x(), p[1] - sums.origin.y(), p[2] - sums.origin.z());
    }
  }
  const cv::Vec3f& mid = cloud.row(10)[31];
  const Eigen::Vector3f n_other = Eigen::Vector3f(1.0f, 0.0f, 0.2f).normalized();
  const Eigen::Vector4f other(n_other.x(), n_other.y(), n_other.z(),
                              n_other.dot(Eigen::Vector3f(mid[0], mid[1], mid[2])));
  NeighbourBand band;
  band.planes = &other;
  band.count = 1;
  band.band_m = 0.01f;
  band.band_sigmas = 3.0f;

  // WHEN the cells are fed row by row as runs (SIMD blocks), and one by one (the scalar test)
  PlaneFitAccumulator runs, single;
  runs.reset(sums, reference.n_in_cam, noise, band);
  single.reset(sums, reference.n_in_cam, noise, band);
  for (int r = 0; r < cloud.rows(); ++r) {
    runs.addRun(cloud.row(r), cloud.cols());
    for (int c = 0; c < cloud.cols(); ++c) single.add(cloud.row(r)[c]);
  }
  Plane from_runs, from_single;
  ASSERT_TRUE(runs.solve(sums, 20 * 63, &from_runs));
  ASSERT_TRUE(single.solve(sums, 20 * 63, &from_single));

  // THEN both keep the same cells (some, not all) and give the same plane and covariance (the
  // sums differ only in their order of addition)
  EXPECT_EQ(from_runs.fit_point_count, from_single.fit_point_count);
  EXPECT_GT(from_runs.fit_point_count, 20 * 40);
  EXPECT_LT(from_runs.fit_point_count, 20 * 63 - 20);
  EXPECT_LT((from_runs.n_in_cam - from_single.n_in_cam).norm(), 1e-9);
  EXPECT_NEAR(from_runs.d_m, from_single.d_m, 1e-9);
  EXPECT_LT((from_runs.covariance - from_single.covariance).norm(),
            1e-6 * from_single.covariance.norm());
}

}  // namespace
}  // namespace deepnav
