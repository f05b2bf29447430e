// Stage 1: the panel pose from marker observations (PanelPoseEstimator) and the quaternion average.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "base/so3.h"
#include "nav/markers/marker_frame_chain.h"
#include "nav/markers/panel_pose_estimator.h"
#include "nav/markers/quaternion_average.h"

namespace deepnav {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// --- QuaternionAverage ---

TEST(MarkersQuaternionAverage, EmptyIsIdentityAndSignsDoNotMatter) {
  QuaternionAverage avg;
  EXPECT_TRUE(avg.mean().isApprox(Eigen::Quaterniond::Identity()));
  EXPECT_EQ(avg.scatter().norm(), 0.0);
  // GIVEN the same rotation added with both signs THEN the mean is that rotation, with no scatter
  const Eigen::Quaterniond q(Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, -2, 0.5).normalized()));
  avg.add(q);
  Eigen::Quaterniond neg = q;
  neg.coeffs() = -q.coeffs();
  avg.add(neg);
  EXPECT_LT(avg.mean().angularDistance(q), 1e-12);
  EXPECT_LT(avg.scatter().norm(), 1e-12);
  EXPECT_EQ(avg.count(), 2);
}

TEST(MarkersQuaternionAverage, SymmetricPerturbationsAverageToTheCentre) {
  // GIVEN rotations Exp(+-d_k) q0 about the odom axes (left perturbations)
  const Eigen::Quaterniond q0(Eigen::AngleAxisd(2.5, Eigen::Vector3d(0.3, 0.2, 1.0).normalized()));
  QuaternionAverage avg;
  for (const Eigen::Vector3d& d : {Eigen::Vector3d(0.1, 0, 0), Eigen::Vector3d(0, 0.05, 0.02),
                                   Eigen::Vector3d(0.01, 0.01, 0.08)}) {
    avg.add(expSo3Quat(d) * q0);
    avg.add(expSo3Quat(-d) * q0);
  }
  // THEN the mean is q0
  EXPECT_LT(avg.mean().angularDistance(q0), 1e-12);
}

TEST(MarkersQuaternionAverage, ScatterRecoversTheRotationCovarianceAboutOdomAxes) {
  // GIVEN 20000 rotations Exp(n) q0 with n ~ N(0, diag(0.01, 0.02, 0.04)^2) rad^2 in odom axes
  std::mt19937 rng(3);
  std::normal_distribution<double> g(0.0, 1.0);
  const Eigen::Quaterniond q0(Eigen::AngleAxisd(-1.2, Eigen::Vector3d(1.0, 1.0, 0.0).normalized()));
  const Eigen::Vector3d sigma(0.01, 0.02, 0.04);
  QuaternionAverage avg;
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector3d n(sigma.x() * g(rng), sigma.y() * g(rng), sigma.z() * g(rng));
    avg.add(expSo3Quat(n) * q0);
  }
  // THEN the mean is q0 within 3 standard errors, and the scatter is diag(sigma^2) within 3 %
  EXPECT_LT(avg.mean().angularDistance(q0), 3.0 * 0.04 / std::sqrt(20000.0));
  const Eigen::Matrix3d S = avg.scatter();
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(S(i, i) / (sigma(i) * sigma(i)), 1.0, 0.03) << i;
  EXPECT_LT(std::abs(S(0, 2)), 0.05 * sigma(0) * sigma(2));
}

TEST(MarkersQuaternionAverage, WeightsPullTheMean) {
  // GIVEN two rotations about z, 0 and 0.3 rad, weighted 3:1 THEN the mean is close to 0.075 rad
  QuaternionAverage avg;
  avg.add(Eigen::Quaterniond::Identity(), 3.0);
  avg.add(Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ())), 1.0);
  const Eigen::AngleAxisd aa(avg.mean());
  EXPECT_NEAR(aa.angle() * aa.axis().z(), 0.075, 0.002);
  EXPECT_DOUBLE_EQ(avg.weightSum(), 4.0);
}

// --- PanelPoseEstimator ---

// A panel with markers on its front (+x) and left (+y) faces, per panel_description.h conventions.
PanelDescription testPanel() {
  PanelDescription p;
  Eigen::Matrix3d front;  // x_M = y_P, y_M = z_P, z_M = x_P
  front << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  Eigen::Matrix3d left;  // seen from +y: x_M = -x_P, y_M = z_P, z_M = y_P
  left << -1, 0, 0, 0, 0, 1, 0, 1, 0;
  for (int i = 0; i < 3; ++i) {
    PanelMarker m;
    m.id = i;
    m.face = 0;
    m.p_marker_in_panel_m = Eigen::Vector3d(1.0, -0.6 + 0.6 * i, 0.9);
    m.q_panel_marker = Eigen::Quaterniond(front);
    p.markers.push_back(m);
  }
  PanelMarker l;
  l.id = 10;
  l.face = 1;
  l.p_marker_in_panel_m = Eigen::Vector3d(0.0, 1.0, 0.9);
  l.q_panel_marker = Eigen::Quaterniond(left);
  p.markers.push_back(l);
  return p;
}

Eigen::Isometry3d truePanel() {
  return isometryOf(Eigen::Quaterniond(Eigen::AngleAxisd(40.0 * kDeg, Eigen::Vector3d::UnitZ())),
                    Eigen::Vector3d(12.0, -7.0, -95.0));
}

Eigen::Isometry3d cameraMounting() {
  Eigen::Matrix3d R_robot_cam;  // forward camera: z_C = x_R, x_C = -y_R, y_C = -z_R
  R_robot_cam << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  return isometryOf(Eigen::Quaterniond(R_robot_cam), Eigen::Vector3d(0.6, 0.15, -0.2));
}

// Synthetic observations: a robot on an arc in front of the panel, looking at it; per frame every
// marker, with the camera-marker pose perturbed (position sigma_m, rotation sigma_rad about the
// camera axes).
class ObservationMaker {
 public:
  ObservationMaker(double sigma_m, double sigma_rad, std::uint32_t seed)
      : sigma_m_(sigma_m), sigma_rad_(sigma_rad), rng_(seed) {}

  // Robot pose k of the arc, in odom (the filter's pose: the truth here).
  Eigen::Isometry3d robotPose(int k) const {
    const double bearing = (-30.0 + 6.0 * (k % 11)) * kDeg;  // around the front face's normal
    const Eigen::Vector3d p_in_panel(1.0 + 2.2 * std::cos(bearing), 2.2 * std::sin(bearing), 1.1);
    const Eigen::Quaterniond q_panel_robot(
        Eigen::AngleAxisd(std::numbers::pi + bearing, Eigen::Vector3d::UnitZ()));
    return truePanel() * isometryOf(q_panel_robot, p_in_panel);
  }

  // A robot 2.2 m off the left face (+y of the panel), looking at it.
  static Eigen::Isometry3d robotPoseFacingLeftFace() {
    const Eigen::Quaterniond q_panel_robot(
        Eigen::AngleAxisd(-0.5 * std::numbers::pi, Eigen::Vector3d::UnitZ()));
    return truePanel() * isometryOf(q_panel_robot, Eigen::Vector3d(0.15, 1.0 + 2.2 + 0.6, 1.1));
  }

  MarkerObservation observe(const Eigen::Isometry3d& T_odom_robot, const PanelMarker& marker) {
    const Eigen::Isometry3d T_cam_marker =
        cameraMounting().inverse() * T_odom_robot.inverse() * truePanel() * panelMarkerPose(marker);
    std::normal_distribution<double> g(0.0, 1.0);
    MarkerObservation obs;
    obs.id = marker.id;
    const Eigen::Vector3d dr(g(rng_), g(rng_), g(rng_));
    const Eigen::Vector3d dp(g(rng_), g(rng_), g(rng_));
    obs.q_cam_marker = expSo3Quat(sigma_rad_ * dr) * Eigen::Quaterniond(T_cam_marker.linear());
    obs.p_marker_in_cam_m = T_cam_marker.translation() + sigma_m_ * dp;
    obs.q_cam_marker_alt = obs.q_cam_marker;
    obs.p_marker_in_cam_alt_m = obs.p_marker_in_cam_m;
    obs.distance_m = obs.p_marker_in_cam_m.norm();
    const Eigen::Vector3d n = obs.q_cam_marker * Eigen::Vector3d::UnitZ();
    obs.obliqueness_rad =
        std::acos(std::clamp(-n.dot(obs.p_marker_in_cam_m) / obs.distance_m, -1.0, 1.0));
    obs.reprojection_error_px = 0.2;
    obs.reprojection_error_alt_px = 3.0;
    return obs;
  }

 private:
  double sigma_m_, sigma_rad_;
  std::mt19937 rng_;
};

PanelPoseEstimator makeEstimator(const PanelPoseConfig& config = PanelPoseConfig{}) {
  PanelPoseEstimator e;
  std::string error;
  EXPECT_TRUE(e.init(config, &error)) << error;
  return e;
}

double positionError(const PanelPoseEstimator& e) {
  return (e.estimate().p_panel_in_odom_m - truePanel().translation()).norm();
}
double angleErrorDeg(const PanelPoseEstimator& e) {
  return e.estimate().q_odom_panel.angularDistance(Eigen::Quaterniond(truePanel().linear())) / kDeg;
}

TEST(MarkersPanelPose, ConvergesToTruthAndIsFixedWhenThresholdsAreMet) {
  // GIVEN noisy observations (1 cm, 0.5 deg) of the three front markers from an arc at 2.2 m
  PanelPoseEstimator est = makeEstimator();
  ObservationMaker maker(0.01, 0.5 * kDeg, 1);
  const PanelDescription panel = testPanel();
  int accepted = 0;
  for (int k = 0; k < 40 && !est.fixed(); ++k) {
    const Eigen::Isometry3d T_odom_robot = maker.robotPose(k);
    for (int id = 0; id < 3; ++id) {
      const auto v = est.addObservation(k * 100'000, maker.observe(T_odom_robot, panel.markers[id]),
                                        panel.markers[id], T_odom_robot, cameraMounting());
      ASSERT_TRUE(v == PanelObservationVerdict::kAccepted ||
                  v == PanelObservationVerdict::kIgnoredFixed);
      if (v == PanelObservationVerdict::kAccepted) ++accepted;
      // THEN it is not fixed before min_observations accepted observations
      if (accepted < PanelPoseConfig{}.min_observations) {
        EXPECT_FALSE(est.fixed()) << accepted;
      }
    }
  }
  // THEN it is fixed exactly at the 30th observation, near the truth, with a plausible scatter
  ASSERT_TRUE(est.fixed());
  EXPECT_EQ(est.estimate().observations, 30);
  EXPECT_EQ(est.estimate().distinct_markers, 3);
  EXPECT_EQ(est.estimate().t_fixed_us, 9 * 100'000);
  EXPECT_LT(positionError(est), 0.015);
  EXPECT_LT(angleErrorDeg(est), 0.3);
  // Per observation: 1 cm of position plus 0.5 deg over the 2.2 m camera-marker lever, ~2.2 cm in
  // all.
  const double pos_std = std::sqrt(est.estimate().scatter_position_m2.trace());
  EXPECT_GT(pos_std, 0.01);
  EXPECT_LT(pos_std, 0.05);
  const double ang_std_deg = std::sqrt(est.estimate().scatter_rotation_rad2.trace()) / kDeg;
  EXPECT_GT(ang_std_deg, 0.5);
  EXPECT_LT(ang_std_deg, 1.5);
  EXPECT_TRUE(est.estimate().cov_position_m2.isApprox(est.estimate().scatter_position_m2 / 30.0));
  // AND the isotropic bounds for markerPoseMeasurement are the largest standard errors
  const PanelPoseInOdom in_odom = est.estimate().inOdom();
  EXPECT_GT(in_odom.sigma_position_m, 0.0);
  EXPECT_LE(in_odom.sigma_position_m, std::sqrt(est.estimate().cov_position_m2.trace()) + 1e-12);
  EXPECT_LT((in_odom.T_odom_panel.matrix() - est.estimate().T_odom_panel().matrix()).norm(), 1e-12);
}

TEST(MarkersPanelPose, MoreObservationsMeanSmallerError) {
  // GIVEN the same noise and thresholds that cannot be met (so it never fixes)
  PanelPoseConfig c;
  c.min_observations = 100000;
  PanelPoseEstimator est = makeEstimator(c);
  ObservationMaker maker(0.02, 1.0 * kDeg, 2);
  const PanelDescription panel = testPanel();
  double error_at_10 = 0.0;
  for (int k = 0; k < 400; ++k) {
    const Eigen::Isometry3d T = maker.robotPose(k);
    est.addObservation(k, maker.observe(T, panel.markers[k % 3]), panel.markers[k % 3], T,
                       cameraMounting());
    if (k == 9) error_at_10 = positionError(est);
  }
  // THEN after 400 the error is small and the standard error shrank like 1 / sqrt(n)
  EXPECT_FALSE(est.fixed());
  EXPECT_LT(positionError(est), 0.01);
  EXPECT_LT(angleErrorDeg(est), 0.2);
  EXPECT_GT(error_at_10, 0.0);
  const double se = std::sqrt(est.estimate().cov_position_m2.trace());
  EXPECT_NEAR(se * std::sqrt(400.0), std::sqrt(est.estimate().scatter_position_m2.trace()), 1e-12);
}

TEST(MarkersPanelPose, NotFixedWithTooFewDistinctMarkers) {
  // GIVEN only marker 0 is ever seen (min_distinct_markers = 2)
  PanelPoseEstimator est = makeEstimator();
  ObservationMaker maker(0.005, 0.2 * kDeg, 3);
  const PanelDescription panel = testPanel();
  for (int k = 0; k < 100; ++k) {
    const Eigen::Isometry3d T = maker.robotPose(k);
    est.addObservation(k, maker.observe(T, panel.markers[0]), panel.markers[0], T,
                       cameraMounting());
  }
  // THEN never fixed
  EXPECT_FALSE(est.fixed());
  EXPECT_EQ(est.estimate().observations, 100);
  EXPECT_EQ(est.estimate().distinct_markers, 1);
  // WHEN the left-face marker is seen once THEN fixed at that observation
  const Eigen::Isometry3d T = ObservationMaker::robotPoseFacingLeftFace();
  EXPECT_EQ(est.addObservation(777, maker.observe(T, panel.markers[3]), panel.markers[3], T,
                               cameraMounting()),
            PanelObservationVerdict::kAccepted);
  EXPECT_TRUE(est.fixed());
  EXPECT_EQ(est.estimate().t_fixed_us, 777);
}

TEST(MarkersPanelPose, NotFixedWhileObservationsDisagree) {
  // GIVEN observations scattered by 6 cm per axis (max_position_std_m = 5 cm)
  PanelPoseEstimator est = makeEstimator();
  ObservationMaker maker(0.06, 0.2 * kDeg, 4);
  const PanelDescription panel = testPanel();
  for (int k = 0; k < 200; ++k) {
    const Eigen::Isometry3d T = maker.robotPose(k);
    est.addObservation(k, maker.observe(T, panel.markers[k % 3]), panel.markers[k % 3], T,
                       cameraMounting());
  }
  // THEN not fixed, though the mean is good
  EXPECT_FALSE(est.fixed());
  EXPECT_GT(est.estimate().observations, 180);
  EXPECT_LT(positionError(est), 0.03);
  // AND with rotations scattered by 3 deg (max 2 deg) neither
  PanelPoseEstimator est2 = makeEstimator();
  ObservationMaker maker2(0.002, 3.0 * kDeg, 5);
  for (int k = 0; k < 200; ++k) {
    const Eigen::Isometry3d T = maker2.robotPose(k);
    // Zero lever: rotation noise of the camera-marker pose about the marker (keeps the position
    // tight).
    est2.addObservation(k, maker2.observe(T, panel.markers[k % 3]), panel.markers[k % 3], T,
                        cameraMounting());
  }
  EXPECT_FALSE(est2.fixed());
}

TEST(MarkersPanelPose, RejectsOutliersWithoutMovingTheMean) {
  // GIVEN 10 good observations
  PanelPoseConfig c;
  c.min_observations = 1000;
  PanelPoseEstimator est = makeEstimator(c);
  ObservationMaker maker(0.01, 0.3 * kDeg, 6);
  const PanelDescription panel = testPanel();
  for (int k = 0; k < 10; ++k) {
    const Eigen::Isometry3d T = maker.robotPose(k);
    ASSERT_EQ(est.addObservation(k, maker.observe(T, panel.markers[k % 3]), panel.markers[k % 3], T,
                                 cameraMounting()),
              PanelObservationVerdict::kAccepted);
  }
  const PanelPoseEstimate before = est.estimate();
  // WHEN an observation puts the panel 0.5 m off (e.g. a wrong robot pose)
  const Eigen::Isometry3d T = maker.robotPose(3);
  Eigen::Isometry3d T_wrong = T;
  T_wrong.translation() += Eigen::Vector3d(0.3, -0.4, 0.0);
  EXPECT_EQ(est.addObservation(11, maker.observe(T, panel.markers[1]), panel.markers[1], T_wrong,
                               cameraMounting()),
            PanelObservationVerdict::kRejectedOutlier);
  // AND one turns it by 15 deg
  const Eigen::Isometry3d T_turned =
      T * isometryOf(Eigen::Quaterniond(Eigen::AngleAxisd(15.0 * kDeg, Eigen::Vector3d::UnitZ())),
                     Eigen::Vector3d::Zero());
  EXPECT_EQ(est.addObservation(12, maker.observe(T, panel.markers[1]), panel.markers[1], T_turned,
                               cameraMounting()),
            PanelObservationVerdict::kRejectedOutlier);
  // THEN both are counted and the estimate has not moved
  EXPECT_EQ(est.counters().rejected_outlier, 2u);
  EXPECT_EQ(est.estimate().observations, 10);
  EXPECT_EQ(est.estimate().p_panel_in_odom_m, before.p_panel_in_odom_m);
  EXPECT_EQ(est.estimate().q_odom_panel.coeffs(), before.q_odom_panel.coeffs());
  // AND a good one after them is accepted
  EXPECT_EQ(est.addObservation(13, maker.observe(T, panel.markers[1]), panel.markers[1], T,
                               cameraMounting()),
            PanelObservationVerdict::kAccepted);
}

TEST(MarkersPanelPose, RestartsWhenTheFirstObservationWasTheOutlier) {
  // GIVEN a first observation 1 m off, then good ones
  PanelPoseEstimator est = makeEstimator();
  ObservationMaker maker(0.01, 0.3 * kDeg, 7);
  const PanelDescription panel = testPanel();
  Eigen::Isometry3d T_wrong = maker.robotPose(0);
  T_wrong.translation().x() += 1.0;
  ASSERT_EQ(est.addObservation(0, maker.observe(maker.robotPose(0), panel.markers[0]),
                               panel.markers[0], T_wrong, cameraMounting()),
            PanelObservationVerdict::kAccepted);
  int rejected = 0;
  for (int k = 1; k < 200 && !est.fixed(); ++k) {
    const Eigen::Isometry3d T = maker.robotPose(k);
    if (est.addObservation(k, maker.observe(T, panel.markers[k % 3]), panel.markers[k % 3], T,
                           cameraMounting()) == PanelObservationVerdict::kRejectedOutlier) {
      ++rejected;
    }
  }
  // THEN restart_after_rejections - 1 are rejected, the accumulation restarts once, and it
  // converges
  EXPECT_EQ(rejected, PanelPoseConfig{}.restart_after_rejections - 1);
  EXPECT_EQ(est.counters().restarts, 1u);
  EXPECT_TRUE(est.fixed());
  EXPECT_LT(positionError(est), 0.015);
}

TEST(MarkersPanelPose, AmbiguousPosesUseTheSolutionNearerTheMean) {
  PanelPoseEstimator est = makeEstimator();
  ObservationMaker maker(0.005, 0.2 * kDeg, 8);
  const PanelDescription panel = testPanel();
  // A wrong tilt: the marker turned by 20 deg about its own vertical axis.
  const auto flipped = [](const MarkerObservation& good) {
    MarkerObservation obs = good;
    obs.ambiguous = true;
    obs.q_cam_marker = good.q_cam_marker *
                       Eigen::Quaterniond(Eigen::AngleAxisd(20.0 * kDeg, Eigen::Vector3d::UnitY()));
    obs.q_cam_marker_alt = good.q_cam_marker;  // the truth is the alternative
    obs.reprojection_error_alt_px = obs.reprojection_error_px;
    return obs;
  };
  const Eigen::Isometry3d T0 = maker.robotPose(0);
  // GIVEN no running mean WHEN an ambiguous pose arrives THEN it is rejected
  EXPECT_EQ(est.addObservation(0, flipped(maker.observe(T0, panel.markers[0])), panel.markers[0],
                               T0, cameraMounting()),
            PanelObservationVerdict::kRejectedAmbiguous);
  for (int k = 1; k <= 10; ++k) {
    const Eigen::Isometry3d T = maker.robotPose(k);
    est.addObservation(k, maker.observe(T, panel.markers[k % 3]), panel.markers[k % 3], T,
                       cameraMounting());
  }
  // GIVEN a running mean WHEN ambiguous poses whose best solution is the wrong tilt arrive
  for (int k = 11; k <= 15; ++k) {
    const Eigen::Isometry3d T = maker.robotPose(k);
    EXPECT_EQ(est.addObservation(k, flipped(maker.observe(T, panel.markers[1])), panel.markers[1],
                                 T, cameraMounting()),
              PanelObservationVerdict::kAccepted);
  }
  // THEN they were resolved to the true tilt: the orientation stays right
  EXPECT_EQ(est.counters().ambiguous_resolved, 5u);
  EXPECT_EQ(est.counters().rejected_ambiguous, 1u);
  EXPECT_LT(angleErrorDeg(est), 0.2);
  // AND with use_ambiguous off they are all rejected
  PanelPoseConfig c;
  c.use_ambiguous = false;
  PanelPoseEstimator strict = makeEstimator(c);
  strict.addObservation(0, maker.observe(T0, panel.markers[0]), panel.markers[0], T0,
                        cameraMounting());
  EXPECT_EQ(strict.addObservation(1, flipped(maker.observe(T0, panel.markers[0])), panel.markers[0],
                                  T0, cameraMounting()),
            PanelObservationVerdict::kRejectedAmbiguous);
}

TEST(MarkersPanelPose, QualityAndValidityRejections) {
  PanelPoseEstimator est = makeEstimator();
  ObservationMaker maker(0.0, 0.0, 9);
  const PanelDescription panel = testPanel();
  const Eigen::Isometry3d T = maker.robotPose(0);
  const MarkerObservation good = maker.observe(T, panel.markers[0]);
  MarkerObservation far = good;
  far.distance_m = 5.0;
  MarkerObservation oblique = good;
  oblique.obliqueness_rad = 80.0 * kDeg;
  MarkerObservation blurred = good;
  blurred.reprojection_error_px = 3.0;
  MarkerObservation nan = good;
  nan.p_marker_in_cam_m.y() = std::nan("");
  // GIVEN observations failing one test each THEN each is rejected with its verdict and counted
  EXPECT_EQ(est.addObservation(0, far, panel.markers[0], T, cameraMounting()),
            PanelObservationVerdict::kRejectedQuality);
  EXPECT_EQ(est.addObservation(0, oblique, panel.markers[0], T, cameraMounting()),
            PanelObservationVerdict::kRejectedQuality);
  EXPECT_EQ(est.addObservation(0, blurred, panel.markers[0], T, cameraMounting()),
            PanelObservationVerdict::kRejectedQuality);
  EXPECT_EQ(est.addObservation(0, nan, panel.markers[0], T, cameraMounting()),
            PanelObservationVerdict::kRejectedInvalid);
  EXPECT_EQ(est.addObservation(0, good, panel.markers[1], T, cameraMounting()),  // id mismatch
            PanelObservationVerdict::kRejectedInvalid);
  EXPECT_EQ(est.counters().rejected_quality, 3u);
  EXPECT_EQ(est.counters().rejected_invalid, 2u);
  EXPECT_EQ(est.estimate().observations, 0);
  // AND an uninitialised estimator accepts nothing
  PanelPoseEstimator raw;
  EXPECT_EQ(raw.addObservation(0, good, panel.markers[0], T, cameraMounting()),
            PanelObservationVerdict::kRejectedInvalid);
}

TEST(MarkersPanelPose, AddFrameSkipsUnknownIds) {
  PanelPoseEstimator est = makeEstimator();
  ObservationMaker maker(0.005, 0.2 * kDeg, 10);
  const PanelDescription panel = testPanel();
  const Eigen::Isometry3d T = maker.robotPose(2);
  MarkerObservations frame;
  frame.items[frame.count++] = maker.observe(T, panel.markers[0]);
  frame.items[frame.count++] = maker.observe(T, panel.markers[2]);
  MarkerObservation stranger = maker.observe(T, panel.markers[1]);
  stranger.id = 42;
  frame.items[frame.count++] = stranger;
  // WHEN a frame with two panel markers and one unknown id is added THEN two accepted, one counted
  // unknown
  EXPECT_EQ(est.addFrame(5, frame, panel, T, cameraMounting()), 2);
  EXPECT_EQ(est.counters().unknown_markers, 1u);
  EXPECT_EQ(est.estimate().distinct_markers, 2);
}

TEST(MarkersPanelPose, FixedStaysFixedAndRoundTripsThroughARecord) {
  // GIVEN a fixed panel
  PanelPoseEstimator est = makeEstimator();
  ObservationMaker maker(0.005, 0.2 * kDeg, 11);
  const PanelDescription panel = testPanel();
  PanelPoseRecord record;
  EXPECT_FALSE(est.record(&record));
  for (int k = 0; k < 60 && !est.fixed(); ++k) {
    const Eigen::Isometry3d T = maker.robotPose(k);
    est.addObservation(k, maker.observe(T, panel.markers[k % 3]), panel.markers[k % 3], T,
                       cameraMounting());
  }
  ASSERT_TRUE(est.fixed());
  const PanelPoseEstimate fixed = est.estimate();
  // WHEN more observations arrive, even wild ones THEN they are ignored and counted
  Eigen::Isometry3d T_wild = maker.robotPose(1);
  T_wild.translation().z() += 3.0;
  EXPECT_EQ(est.addObservation(1000, maker.observe(maker.robotPose(1), panel.markers[0]),
                               panel.markers[0], T_wild, cameraMounting()),
            PanelObservationVerdict::kIgnoredFixed);
  EXPECT_EQ(est.counters().ignored_fixed, 1u);
  EXPECT_EQ(est.estimate().p_panel_in_odom_m, fixed.p_panel_in_odom_m);
  // WHEN saved as plain numbers and restored into a fresh estimator
  ASSERT_TRUE(est.record(&record));
  PanelPoseEstimator restored = makeEstimator();
  std::string error;
  ASSERT_TRUE(restored.restore(record, &error)) << error;
  // THEN it is fixed at the same pose with the same covariance and bookkeeping
  EXPECT_TRUE(restored.fixed());
  EXPECT_LT((restored.estimate().p_panel_in_odom_m - fixed.p_panel_in_odom_m).norm(), 1e-15);
  EXPECT_LT(restored.estimate().q_odom_panel.angularDistance(fixed.q_odom_panel), 1e-12);
  EXPECT_EQ(restored.estimate().cov_position_m2, fixed.cov_position_m2);
  EXPECT_EQ(restored.estimate().cov_rotation_rad2, fixed.cov_rotation_rad2);
  EXPECT_EQ(restored.estimate().observations, fixed.observations);
  EXPECT_EQ(restored.estimate().distinct_markers, fixed.distinct_markers);
  EXPECT_EQ(restored.estimate().t_fixed_us, fixed.t_fixed_us);
  // AND reset() forgets it
  restored.reset();
  EXPECT_FALSE(restored.fixed());
  EXPECT_EQ(restored.estimate().observations, 0);
}

TEST(MarkersPanelPose, RestoreRefusesBadRecordsNamingTheField) {
  PanelPoseEstimator est = makeEstimator();
  std::string error;
  PanelPoseRecord r;
  r.q_odom_panel_xyzw = {0.0, 0.0, 0.5, 0.5};
  EXPECT_FALSE(est.restore(r, &error));
  EXPECT_NE(error.find("q_odom_panel_xyzw"), std::string::npos);
  r = PanelPoseRecord{};
  r.p_panel_in_odom_m[1] = std::nan("");
  EXPECT_FALSE(est.restore(r, &error));
  EXPECT_NE(error.find("p_panel_in_odom_m"), std::string::npos);
  r = PanelPoseRecord{};
  r.cov_position_m2 = {1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 1.0};
  EXPECT_FALSE(est.restore(r, &error));
  EXPECT_NE(error.find("cov_position_m2"), std::string::npos);
  r = PanelPoseRecord{};
  r.cov_rotation_rad2 = {1.0, 0.5, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  EXPECT_FALSE(est.restore(r, &error));
  EXPECT_NE(error.find("cov_rotation_rad2"), std::string::npos);
  EXPECT_FALSE(est.fixed());
  // AND the default record (identity, zero covariance) is acceptable
  EXPECT_TRUE(est.restore(PanelPoseRecord{}, &error));
}

TEST(MarkersPanelPose, ConfigValidationNamesTheKey) {
  PanelPoseEstimator est;
  std::string error;
  PanelPoseConfig c;
  c.min_observations = 0;
  EXPECT_FALSE(est.init(c, &error));
  EXPECT_NE(error.find("min_observations"), std::string::npos);
  c = PanelPoseConfig{};
  c.max_obliqueness_rad = 2.0;
  EXPECT_FALSE(est.init(c, &error));
  EXPECT_NE(error.find("max_obliqueness_rad"), std::string::npos);
  c = PanelPoseConfig{};
  c.outlier_floor_m = 0.0;
  EXPECT_FALSE(est.init(c, &error));
  EXPECT_NE(error.find("outlier_floor_m"), std::string::npos);
}

}  // namespace
}  // namespace deepnav
