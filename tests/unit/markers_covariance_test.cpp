// Marker pose uncertainty model and the robot PoseMeasurement built from a marker.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <string>

#include "nav/ekf/pose_updater.h"
#include "nav/markers/marker_frame_chain.h"
#include "nav/markers/marker_pose_covariance.h"
#include "nav/markers/marker_pose_measurement.h"

namespace deepnav {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

MarkerObservation observationAt(double distance_m, double obliqueness_rad,
                                double reprojection_px = 0.2, bool ambiguous = false) {
  MarkerObservation obs;
  obs.id = 1;
  obs.distance_m = distance_m;
  obs.obliqueness_rad = obliqueness_rad;
  obs.reprojection_error_px = reprojection_px;
  obs.ambiguous = ambiguous;
  // A marker straight ahead, facing the camera (consistent pose, used by the measurement tests).
  obs.q_cam_marker =
      Eigen::Quaterniond(Eigen::Matrix3d(Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal()) *
                         Eigen::AngleAxisd(obliqueness_rad, Eigen::Vector3d::UnitY()));
  obs.p_marker_in_cam_m = Eigen::Vector3d(0.0, 0.0, distance_m);
  return obs;
}

TEST(MarkersCovariance, DefaultsMatchTheDocumentedModel) {
  // GIVEN the default model WHEN a marker is seen head-on at 1.5 m with a good fit
  const MarkerCovarianceConfig c;
  ASSERT_TRUE(validateMarkerCovarianceConfig(c, nullptr));
  const MarkerPoseSigmas s = markerPoseSigmas(observationAt(1.5, 0.0), c);
  // THEN eqs. (2) and (3): 0.01 + 0.01 * 2.25 m and 0.0087 * (1 + 1.5) rad
  EXPECT_NEAR(s.position_m, 0.0325, 1e-12);
  EXPECT_NEAR(s.rotation_rad, 0.0087 * 2.5, 1e-12);
}

TEST(MarkersCovariance, GrowsWithDistanceObliquenessErrorAndAmbiguity) {
  const MarkerCovarianceConfig c;
  // GIVEN increasing distances THEN both sigmas increase strictly, position like d^2
  double last_pos = 0.0, last_rot = 0.0;
  for (double d : {0.5, 1.0, 1.5, 2.0, 3.0, 4.0}) {
    const MarkerPoseSigmas s = markerPoseSigmas(observationAt(d, 0.0), c);
    EXPECT_GT(s.position_m, last_pos) << d;
    EXPECT_GT(s.rotation_rad, last_rot) << d;
    last_pos = s.position_m;
    last_rot = s.rotation_rad;
  }
  const double growth = markerPoseSigmas(observationAt(4.0, 0.0), c).position_m - c.pos_floor_m;
  EXPECT_NEAR(growth / (markerPoseSigmas(observationAt(2.0, 0.0), c).position_m - c.pos_floor_m),
              4.0, 1e-9);
  // GIVEN increasing obliqueness at 2 m THEN both increase, like 1 / cos, and stop at the clamp
  last_pos = last_rot = 0.0;
  for (double a_deg : {0.0, 20.0, 40.0, 60.0, 75.0}) {
    const MarkerPoseSigmas s = markerPoseSigmas(observationAt(2.0, a_deg * kDeg), c);
    EXPECT_GT(s.position_m, last_pos) << a_deg;
    EXPECT_GT(s.rotation_rad, last_rot) << a_deg;
    last_pos = s.position_m;
    last_rot = s.rotation_rad;
  }
  const MarkerPoseSigmas at60 = markerPoseSigmas(observationAt(2.0, 60.0 * kDeg), c);
  EXPECT_NEAR(at60.position_m - c.pos_floor_m, 2.0 * c.pos_per_d2_per_m * 4.0,
              1e-12);  // 1 / cos 60 = 2
  const MarkerPoseSigmas clamp = markerPoseSigmas(observationAt(2.0, 85.0 * kDeg), c);
  EXPECT_NEAR(clamp.position_m, markerPoseSigmas(observationAt(2.0, 75.0 * kDeg), c).position_m,
              1e-3);
  // GIVEN a bad fit (2 px vs 0.5 px nominal) THEN the distance terms are 4 times larger
  const MarkerPoseSigmas good = markerPoseSigmas(observationAt(2.0, 0.0, 0.4), c);
  const MarkerPoseSigmas bad = markerPoseSigmas(observationAt(2.0, 0.0, 2.0), c);
  EXPECT_NEAR(bad.position_m - c.pos_floor_m, 4.0 * (good.position_m - c.pos_floor_m), 1e-12);
  // GIVEN an ambiguous pose THEN everything times ambiguous_scale
  const MarkerPoseSigmas amb = markerPoseSigmas(observationAt(2.0, 0.0, 0.4, true), c);
  EXPECT_NEAR(amb.position_m, c.ambiguous_scale * good.position_m, 1e-12);
  EXPECT_NEAR(amb.rotation_rad, c.ambiguous_scale * good.rotation_rad, 1e-12);
}

TEST(MarkersCovariance, ConfigValidationNamesTheKey) {
  std::string error;
  MarkerCovarianceConfig c;
  c.pos_floor_m = -1.0;
  EXPECT_FALSE(validateMarkerCovarianceConfig(c, &error));
  EXPECT_NE(error.find("pos_floor_m"), std::string::npos);
  c = MarkerCovarianceConfig{};
  c.max_obliqueness_rad = 1.6;
  EXPECT_FALSE(validateMarkerCovarianceConfig(c, &error));
  EXPECT_NE(error.find("max_obliqueness_rad"), std::string::npos);
  c = MarkerCovarianceConfig{};
  c.ambiguous_scale = 0.5;
  EXPECT_FALSE(validateMarkerCovarianceConfig(c, &error));
  EXPECT_NE(error.find("ambiguous_scale"), std::string::npos);
  c = MarkerCovarianceConfig{};
  c.nominal_reprojection_px = 0.0;
  EXPECT_FALSE(validateMarkerCovarianceConfig(c, &error));
  EXPECT_NE(error.find("nominal_reprojection_px"), std::string::npos);
}

TEST(MarkersPoseMeasurement, DiagonalValidAndFromTheFrameChain) {
  // GIVEN a panel with a known pose and a front marker seen 2 m ahead, camera with a 0.65 m lever
  // arm
  PanelPoseInOdom panel;
  panel.T_odom_panel =
      isometryOf(Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ())),
                 Eigen::Vector3d(3.0, 4.0, -20.0));
  PanelMarker marker;
  marker.id = 1;
  marker.p_marker_in_panel_m = Eigen::Vector3d(1.0, 0.0, 0.8);
  Eigen::Matrix3d R_panel_marker;
  R_panel_marker << 0, 0, 1, 1, 0, 0, 0, 1, 0;  // columns: x_M = y_P, y_M = z_P, z_M = x_P
  marker.q_panel_marker = Eigen::Quaterniond(R_panel_marker);
  Eigen::Matrix3d R_robot_cam;
  R_robot_cam << 0, 0, 1, -1, 0, 0, 0, -1, 0;  // z_C = x_R, x_C = -y_R, y_C = -z_R
  const Eigen::Isometry3d T_robot_cam =
      isometryOf(Eigen::Quaterniond(R_robot_cam), Eigen::Vector3d(0.6, 0.15, -0.2));
  const MarkerObservation obs = observationAt(2.0, 0.0);
  const MarkerCovarianceConfig config;
  // WHEN the measurement is built at t = 5 s
  PoseMeasurement m;
  ASSERT_TRUE(markerPoseMeasurement(5'000'000, obs, marker, panel, T_robot_cam, config, &m));
  // THEN time, source and pose are those of the frame chain
  EXPECT_EQ(m.t_us, 5'000'000);
  EXPECT_EQ(m.source, kSrcMarkers);
  const Eigen::Isometry3d expected = robotPoseFromMarker(
      panel.T_odom_panel, panelMarkerPose(marker), cameraMarkerPose(obs), T_robot_cam);
  EXPECT_LT((m.p_robot_in_odom_m - expected.translation()).norm(), 1e-12);
  EXPECT_LT(m.q_odom_robot.angularDistance(Eigen::Quaterniond(expected.linear())), 1e-12);
  // AND the covariance is diagonal, isotropic per block, what the EKF accepts, and equal to the
  // model plus the lever-arm term (no panel uncertainty given)
  EXPECT_TRUE(isValidPose(m));
  Eigen::Matrix<double, 6, 6> off = m.cov_pose;
  off.diagonal().setZero();
  EXPECT_EQ(off.norm(), 0.0);
  const MarkerPoseSigmas s = markerPoseSigmas(obs, config);
  const double lever = std::hypot(0.6, 0.15, -0.2);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(m.cov_pose(i, i), s.position_m * s.position_m + std::pow(s.rotation_rad * lever, 2),
                1e-15);
    EXPECT_NEAR(m.cov_pose(3 + i, 3 + i), s.rotation_rad * s.rotation_rad, 1e-15);
  }
  // GIVEN the panel's own uncertainty THEN it adds: its position sigma, its rotation sigma (also
  // times the robot's distance from the panel origin)
  PanelPoseInOdom uncertain = panel;
  uncertain.sigma_position_m = 0.02;
  uncertain.sigma_rotation_rad = 0.01;
  PoseMeasurement mu;
  ASSERT_TRUE(markerPoseMeasurement(5'000'000, obs, marker, uncertain, T_robot_cam, config, &mu));
  const double r = (mu.p_robot_in_odom_m - panel.T_odom_panel.translation()).norm();
  EXPECT_NEAR(mu.cov_pose(0, 0) - m.cov_pose(0, 0), 0.02 * 0.02 + std::pow(0.01 * r, 2), 1e-15);
  EXPECT_NEAR(mu.cov_pose(5, 5) - m.cov_pose(5, 5), 0.01 * 0.01, 1e-15);
  // AND a farther, more oblique view gives a larger covariance
  PoseMeasurement far;
  ASSERT_TRUE(markerPoseMeasurement(5'000'000, observationAt(3.0, 40.0 * kDeg), marker, panel,
                                    T_robot_cam, config, &far));
  EXPECT_GT(far.cov_pose(0, 0), m.cov_pose(0, 0));
  EXPECT_GT(far.cov_pose(3, 3), m.cov_pose(3, 3));
}

TEST(MarkersPoseMeasurement, NonFiniteInputIsRefused) {
  // GIVEN an observation with a NaN position THEN no measurement and *out untouched
  MarkerObservation obs = observationAt(2.0, 0.0);
  obs.p_marker_in_cam_m.x() = std::nan("");
  PoseMeasurement m;
  m.t_us = 17;
  EXPECT_FALSE(markerPoseMeasurement(1, obs, PanelMarker{}, PanelPoseInOdom{},
                                     Eigen::Isometry3d::Identity(), MarkerCovarianceConfig{}, &m));
  EXPECT_EQ(m.t_us, 17);
}

}  // namespace
}  // namespace deepnav
