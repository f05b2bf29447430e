// Frame chains of marker navigation: robot from marker, panel from marker, exact on random poses,
// on a hand-worked geometry, and end to end through a rendered image and the detector.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <random>

#include "nav/markers/marker_frame_chain.h"
#include "tests/support/synthetic_marker_image.h"
#include "vision/markers/marker_detector.h"

namespace deepnav {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

Eigen::Quaterniond randomRotation(std::mt19937* rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Quaterniond q(n(*rng), n(*rng), n(*rng), n(*rng));
  return q.normalized();
}

Eigen::Isometry3d randomPose(std::mt19937* rng, double scale_m) {
  std::uniform_real_distribution<double> u(-scale_m, scale_m);
  return isometryOf(randomRotation(rng), Eigen::Vector3d(u(*rng), u(*rng), u(*rng)));
}

double rotationErrorRad(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::Quaterniond(a.linear()).angularDistance(Eigen::Quaterniond(b.linear()));
}

// The panel's front-face marker: M's x right (= panel +y as seen from the front), y up (= panel
// +z), z out of the face (= panel +x).
PanelMarker frontMarker(int id, const Eigen::Vector3d& p_marker_in_panel_m) {
  Eigen::Matrix3d R_panel_marker;
  R_panel_marker.col(0) = Eigen::Vector3d::UnitY();
  R_panel_marker.col(1) = Eigen::Vector3d::UnitZ();
  R_panel_marker.col(2) = Eigen::Vector3d::UnitX();
  PanelMarker m;
  m.id = id;
  m.face = 0;
  m.p_marker_in_panel_m = p_marker_in_panel_m;
  m.q_panel_marker = Eigen::Quaterniond(R_panel_marker);
  return m;
}

// Camera optical frame C in the robot frame R (FLU) for a forward-looking camera: z_C = x_R, x_C =
// -y_R, y_C = -z_R.
Eigen::Isometry3d forwardCamera(const Eigen::Vector3d& p_cam_in_robot_m) {
  Eigen::Matrix3d R_robot_cam;
  R_robot_cam.col(0) = -Eigen::Vector3d::UnitY();
  R_robot_cam.col(1) = -Eigen::Vector3d::UnitZ();
  R_robot_cam.col(2) = Eigen::Vector3d::UnitX();
  return isometryOf(Eigen::Quaterniond(R_robot_cam), p_cam_in_robot_m);
}

TEST(MarkersFrameChain, RobotAndPanelFromMarkerAreExactOnRandomPoses) {
  // GIVEN random odom-panel, panel-marker, camera mounting and robot poses, and the marker's pose
  // in the camera that they imply
  std::mt19937 rng(42);
  for (int i = 0; i < 200; ++i) {
    const Eigen::Isometry3d T_odom_panel = randomPose(&rng, 50.0);
    const Eigen::Isometry3d T_panel_marker = randomPose(&rng, 2.0);
    const Eigen::Isometry3d T_robot_cam = randomPose(&rng, 1.0);
    const Eigen::Isometry3d T_odom_robot = randomPose(&rng, 50.0);
    const Eigen::Isometry3d T_cam_marker =
        T_robot_cam.inverse() * T_odom_robot.inverse() * T_odom_panel * T_panel_marker;
    // WHEN either chain is evaluated
    const Eigen::Isometry3d robot =
        robotPoseFromMarker(T_odom_panel, T_panel_marker, T_cam_marker, T_robot_cam);
    const Eigen::Isometry3d panel =
        panelPoseFromMarker(T_odom_robot, T_robot_cam, T_cam_marker, T_panel_marker);
    // THEN it gives back the truth
    EXPECT_LT((robot.translation() - T_odom_robot.translation()).norm(), 1e-9);
    EXPECT_LT(rotationErrorRad(robot, T_odom_robot), 1e-9);
    EXPECT_LT((panel.translation() - T_odom_panel.translation()).norm(), 1e-9);
    EXPECT_LT(rotationErrorRad(panel, T_odom_panel), 1e-9);
    // AND the two chains are inverse to each other
    const Eigen::Isometry3d back =
        panelPoseFromMarker(robot, T_robot_cam, T_cam_marker, T_panel_marker);
    EXPECT_LT((back.matrix() - T_odom_panel.matrix()).norm(), 1e-9);
  }
}

TEST(MarkersFrameChain, ObservationAndKnowledgeBaseConversions) {
  // GIVEN an observation with distinct best and alternative poses and a marker of the panel
  MarkerObservation obs;
  obs.q_cam_marker = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
  obs.p_marker_in_cam_m = Eigen::Vector3d(0.1, 0.2, 1.5);
  obs.q_cam_marker_alt = Eigen::Quaterniond(Eigen::AngleAxisd(-0.3, Eigen::Vector3d::UnitX()));
  obs.p_marker_in_cam_alt_m = Eigen::Vector3d(0.1, 0.2, 1.6);
  const PanelMarker marker = frontMarker(4, Eigen::Vector3d(1.0, 0.3, 0.7));
  // THEN the isometries map marker-frame points as x_cam = R x_marker + p
  const Eigen::Vector3d x_m(0.05, -0.02, 0.0);
  EXPECT_LT((cameraMarkerPose(obs) * x_m - (obs.q_cam_marker * x_m + obs.p_marker_in_cam_m)).norm(),
            1e-12);
  EXPECT_LT((cameraMarkerPoseAlternative(obs) * x_m -
             (obs.q_cam_marker_alt * x_m + obs.p_marker_in_cam_alt_m))
                .norm(),
            1e-12);
  // AND the front marker's normal is the panel's +x, its "up" the panel's +z
  const Eigen::Isometry3d T_panel_marker = panelMarkerPose(marker);
  EXPECT_LT((T_panel_marker.linear() * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitX()).norm(),
            1e-12);
  EXPECT_LT((T_panel_marker.linear() * Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitZ()).norm(),
            1e-12);
  EXPECT_LT((T_panel_marker.translation() - marker.p_marker_in_panel_m).norm(), 1e-12);
}

TEST(MarkersFrameChain, HandWorkedGeometryFacingTheFrontFace) {
  // GIVEN a panel at (10, 20, -50) in odom whose front normal points north (yaw +90 deg), a marker
  // on its front face 1 m from the origin at 0.8 m height, and a robot 2 m north of the marker at
  // its height, facing south (yaw -90 deg), with a forward camera at its origin.
  const Eigen::Isometry3d T_odom_panel =
      isometryOf(Eigen::Quaterniond(Eigen::AngleAxisd(90.0 * kDeg, Eigen::Vector3d::UnitZ())),
                 Eigen::Vector3d(10.0, 20.0, -50.0));
  const PanelMarker marker = frontMarker(0, Eigen::Vector3d(1.0, 0.0, 0.8));
  const Eigen::Isometry3d T_robot_cam = forwardCamera(Eigen::Vector3d::Zero());
  // The camera sees the marker straight ahead 2 m away, upright: x_M = x_C, y_M = -y_C, z_M = -z_C.
  MarkerObservation obs;
  obs.q_cam_marker =
      Eigen::Quaterniond(Eigen::Matrix3d(Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal()));
  obs.p_marker_in_cam_m = Eigen::Vector3d(0.0, 0.0, 2.0);
  // WHEN the robot pose is computed
  const Eigen::Isometry3d T_odom_robot = robotPoseFromMarker(T_odom_panel, panelMarkerPose(marker),
                                                             cameraMarkerPose(obs), T_robot_cam);
  // THEN the robot is 3 m north of the panel origin at 0.8 m above its base, facing south
  EXPECT_LT((T_odom_robot.translation() - Eigen::Vector3d(10.0, 23.0, -49.2)).norm(), 1e-12);
  const Eigen::Vector3d forward = T_odom_robot.linear() * Eigen::Vector3d::UnitX();
  const Eigen::Vector3d up = T_odom_robot.linear() * Eigen::Vector3d::UnitZ();
  EXPECT_LT((forward - Eigen::Vector3d(0.0, -1.0, 0.0)).norm(), 1e-12);
  EXPECT_LT((up - Eigen::Vector3d::UnitZ()).norm(), 1e-12);
  // AND with a camera lever arm of 0.6 m forward, the robot sits 0.6 m farther back (north)
  const Eigen::Isometry3d T_robot_cam_fwd = forwardCamera(Eigen::Vector3d(0.6, 0.0, 0.0));
  const Eigen::Isometry3d T_odom_robot_fwd = robotPoseFromMarker(
      T_odom_panel, panelMarkerPose(marker), cameraMarkerPose(obs), T_robot_cam_fwd);
  EXPECT_LT((T_odom_robot_fwd.translation() - Eigen::Vector3d(10.0, 23.6, -49.2)).norm(), 1e-12);
  // AND a marker seen 0.5 m to the camera's right (x_C: west, as the robot faces south) puts the
  // robot 0.5 m east of the marker's normal line
  obs.p_marker_in_cam_m = Eigen::Vector3d(0.5, 0.0, 2.0);
  const Eigen::Isometry3d T_odom_robot_side = robotPoseFromMarker(
      T_odom_panel, panelMarkerPose(marker), cameraMarkerPose(obs), T_robot_cam);
  EXPECT_LT((T_odom_robot_side.translation() - Eigen::Vector3d(10.5, 23.0, -49.2)).norm(), 1e-12);
  // AND the panel pose from that first observation and the robot's true pose is the panel's truth
  obs.p_marker_in_cam_m = Eigen::Vector3d(0.0, 0.0, 2.0);
  const Eigen::Isometry3d panel = panelPoseFromMarker(
      T_odom_robot, T_robot_cam, cameraMarkerPose(obs), panelMarkerPose(marker));
  EXPECT_LT((panel.matrix() - T_odom_panel.matrix()).norm(), 1e-12);
}

TEST(MarkersFrameChain, EndToEndThroughARenderedImage) {
  // GIVEN a robot whose camera is 1.7 m from a front marker, 25 deg off the marker's normal, the
  // robot turned to face the marker and pitched 5 deg, with the simulator's camera mounting (0.6,
  // 0.15, -0.2) m, and the image its camera sees
  const Eigen::Isometry3d T_odom_panel =
      isometryOf(Eigen::Quaterniond(Eigen::AngleAxisd(30.0 * kDeg, Eigen::Vector3d::UnitZ())),
                 Eigen::Vector3d(5.0, -3.0, -100.0));
  const PanelMarker marker = frontMarker(9, Eigen::Vector3d(1.0, 0.2, 0.9));
  const Eigen::Isometry3d T_robot_cam = forwardCamera(Eigen::Vector3d(0.6, 0.15, -0.2));
  const Eigen::Isometry3d T_panel_marker = panelMarkerPose(marker);
  const double bearing = 25.0 * kDeg;
  const Eigen::Vector3d p_cam_in_panel =
      marker.p_marker_in_panel_m + 1.7 * Eigen::Vector3d(std::cos(bearing), std::sin(bearing), 0.0);
  const Eigen::Quaterniond q_panel_robot(
      Eigen::AngleAxisd(std::numbers::pi + bearing, Eigen::Vector3d::UnitZ()) *
      Eigen::AngleAxisd(5.0 * kDeg, Eigen::Vector3d::UnitY()));
  const Eigen::Isometry3d T_odom_robot =
      T_odom_panel *
      isometryOf(q_panel_robot, p_cam_in_panel - q_panel_robot * T_robot_cam.translation());
  const Eigen::Isometry3d T_cam_marker =
      T_robot_cam.inverse() * T_odom_robot.inverse() * T_odom_panel * T_panel_marker;
  const PinholeIntrinsics cam{700.0, 700.0, 343.5, 257.5};
  SyntheticMarker drawn;
  drawn.id = marker.id;
  drawn.q_cam_marker = Eigen::Quaterniond(T_cam_marker.linear());
  drawn.p_marker_in_cam_m = T_cam_marker.translation();
  ASSERT_GT(drawn.p_marker_in_cam_m.z(), 1.0);
  cv::Mat image(516, 688, CV_8UC1, cv::Scalar(90));
  ASSERT_TRUE(drawSyntheticMarker("DICT_4X4_50", drawn, cam, 4, &image));
  cv::GaussianBlur(image, image, cv::Size(5, 5), 0.6);
  // WHEN detected and chained to the robot
  MarkerDetector detector;
  MarkerDetectorConfig config;
  config.camera = cam;
  ASSERT_TRUE(detector.init(config, nullptr));
  MarkerObservations out;
  ASSERT_TRUE(detector.detect(image, &out));
  ASSERT_EQ(out.count, 1);
  ASSERT_FALSE(out.items[0].ambiguous)
      << out.items[0].reprojection_error_px << " " << out.items[0].reprojection_error_alt_px << " "
      << out.items[0].distance_m << " " << out.items[0].obliqueness_rad / kDeg;
  const Eigen::Isometry3d robot = robotPoseFromMarker(T_odom_panel, T_panel_marker,
                                                      cameraMarkerPose(out.items[0]), T_robot_cam);
  // THEN the robot pose is the truth within 2 cm and 1 deg (the marker's own accuracy, carried over
  // a 1.9 m lever)
  EXPECT_LT((robot.translation() - T_odom_robot.translation()).norm(), 0.02);
  EXPECT_LT(rotationErrorRad(robot, T_odom_robot) / kDeg, 1.0);
}

}  // namespace
}  // namespace deepnav
