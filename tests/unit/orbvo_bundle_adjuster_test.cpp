// LocalBundleAdjuster: a window of stereo keyframes with perturbed poses and points comes back to
// the truth; the fixed keyframe holds the gauge; gross observations are flagged.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <vector>

#include "base/so3.h"
#include "vision/orbvo/local_bundle_adjuster.h"
#include "vision/orbvo/stereo_projection.h"

namespace deepnav {
namespace {

struct Problem {
  std::vector<Eigen::Matrix3d> R_true, R;
  std::vector<Eigen::Vector3d> t_true, t;
  std::vector<Eigen::Vector3d> points_true, points;
  std::vector<BaObservation> observations;
};

// Draws in a fixed order: the order in which a function's arguments are evaluated is unspecified
// (g++ evaluates Eigen::Vector3d(n(rng), n(rng), n(rng)) right to left on x86-64 and left to right
// on aarch64), so draws inside one constructor call would make a different problem per architecture.
template <int N, class Distribution>
Eigen::Matrix<double, N, 1> draw(Distribution& d, std::mt19937* rng) {
  Eigen::Matrix<double, N, 1> v;
  for (int i = 0; i < N; ++i) v(i) = d(*rng);
  return v;
}

// 5 keyframes 8 cm apart looking at 300 points at 1-3 m; each keyframe observes the points in its
// view with 0.5 px noise; poses (except the first) and points start perturbed by about 1 cm and 0.5
// deg.
Problem makeProblem(std::mt19937* rng) {
  const StereoRig rig;
  Problem p;
  std::normal_distribution<double> n01(0.0, 1.0);
  std::uniform_real_distribution<double> x(-1.2, 1.2), y(-0.9, 0.9), z(1.0, 3.0);
  for (int c = 0; c < 5; ++c) {
    const Eigen::Matrix3d R = expSo3(Eigen::Vector3d(0.0, 0.02 * c, 0.01 * c));
    const Eigen::Vector3d p_cam_in_world(0.08 * c, 0.01 * c, 0.02 * c);
    p.R_true.push_back(R);
    p.t_true.push_back(-R * p_cam_in_world);
    const double scale = c == 0 ? 0.0 : 1.0;
    const Eigen::Vector3d dphi = scale * 0.005 * draw<3>(n01, rng);
    const Eigen::Vector3d dt = scale * 0.01 * draw<3>(n01, rng);
    p.R.push_back(expSo3(dphi) * R);
    p.t.push_back(p.t_true.back() + dt);
  }
  for (int j = 0; j < 300; ++j) {
    Eigen::Vector3d point;
    point.x() = x(*rng);
    point.y() = y(*rng);
    point.z() = z(*rng);
    p.points_true.push_back(point);
    p.points.push_back(point + draw<3>(n01, rng) * 0.01);
    for (int c = 0; c < 5; ++c) {
      const Eigen::Vector3d p_in_cam = p.R_true[c] * point + p.t_true[c];
      const StereoProjection proj = projectStereo(rig, p_in_cam);
      if (proj.uvr_px(0) < 0 || proj.uvr_px(0) > rig.width_px || proj.uvr_px(1) < 0 ||
          proj.uvr_px(1) > rig.height_px) {
        continue;
      }
      BaObservation o;
      o.camera = c;
      o.point = j;
      o.uv_px = proj.uvr_px.head<2>() + draw<2>(n01, rng) * 0.5;
      o.u_right_px = (j + c) % 4 == 0 ? -1.0 : proj.uvr_px(2) + 0.5 * n01(*rng);
      o.sigma_px = 0.5;
      p.observations.push_back(o);
    }
  }
  return p;
}

TEST(OrbVoBundleAdjuster, RecoversPerturbedWindow) {
  std::mt19937 rng(5);
  Problem p = makeProblem(&rng);
  // A few gross observations (wrong associations).
  for (std::size_t k = 7; k < p.observations.size(); k += 97)
    p.observations[k].uv_px += Eigen::Vector2d(25.0, -18.0);
  LocalBundleAdjuster ba;
  ASSERT_TRUE(ba.init(5, 300, static_cast<int>(p.observations.size())));
  std::vector<std::uint8_t> outlier(p.observations.size(), 0);
  BundleAdjusterSummary summary;
  const Eigen::Matrix3d R0 = p.R[0];
  const Eigen::Vector3d t0 = p.t[0];
  BundleAdjusterConfig config;
  config.iterations = 10;
  ASSERT_TRUE(ba.optimise(StereoRig{}, config, 5, 1, p.R.data(), p.t.data(), 300, p.points.data(),
                          static_cast<int>(p.observations.size()), p.observations.data(),
                          outlier.data(), &summary));
  EXPECT_LT(summary.final_cost, 0.05 * summary.initial_cost);
  std::printf("cost %.1f -> %.1f in %d steps\n", summary.initial_cost, summary.final_cost,
              summary.accepted_steps);
  EXPECT_GT(summary.accepted_steps, 1);
  // The fixed keyframe did not move; the others came back from about 1.7 cm and 0.5 deg to within
  // 1.5 mm and 0.06 deg (the precision of 0.5 px observations of points at 1-3 m).
  EXPECT_EQ((p.R[0] - R0).norm(), 0.0);
  EXPECT_EQ((p.t[0] - t0).norm(), 0.0);
  for (int c = 1; c < 5; ++c) {
    EXPECT_LT(logSo3(p.R[c] * p.R_true[c].transpose()).norm(), 1e-3) << "camera " << c;
    EXPECT_LT((p.t[c] - p.t_true[c]).norm(), 1.5e-3) << "camera " << c;
  }
  // Every gross observation of a point seen by two or more keyframes is flagged, few good ones are.
  // A point's only observation has no redundancy: the point moves onto it, wrong or not, so a gross
  // one there cannot be told from a good one (one of the 10 in this problem).
  std::vector<int> views(300, 0);
  for (const BaObservation& o : p.observations) ++views[o.point];
  int flagged_gross = 0, flagged_good = 0, gross = 0;
  for (std::size_t k = 0; k < p.observations.size(); ++k) {
    const bool is_gross = k >= 7 && (k - 7) % 97 == 0;
    if (is_gross && views[p.observations[k].point] < 2) continue;
    gross += is_gross;
    flagged_gross += is_gross && outlier[k];
    flagged_good += !is_gross && outlier[k];
  }
  EXPECT_GE(gross, 8);
  EXPECT_EQ(flagged_gross, gross);
  EXPECT_LT(flagged_good, static_cast<int>(p.observations.size()) / 10);
}

TEST(OrbVoBundleAdjuster, RejectsBadSizes) {
  LocalBundleAdjuster ba;
  ASSERT_TRUE(ba.init(3, 10, 10));
  Eigen::Matrix3d R[4];
  Eigen::Vector3d t[4], points[1];
  BaObservation obs[1];
  std::uint8_t outlier[1];
  BundleAdjusterSummary summary;
  EXPECT_FALSE(ba.optimise(StereoRig{}, BundleAdjusterConfig(), 4, 1, R, t, 1, points, 1, obs,
                           outlier, &summary));
  EXPECT_FALSE(ba.optimise(StereoRig{}, BundleAdjusterConfig(), 3, 0, R, t, 1, points, 1, obs,
                           outlier, &summary));
  EXPECT_FALSE(ba.optimise(StereoRig{}, BundleAdjusterConfig(), 3, 1, R, t, 11, points, 1, obs,
                           outlier, &summary));
}

}  // namespace
}  // namespace deepnav
