// Planar pose ambiguity: the IPPE solution nearer a predicted rotation is kept.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "nav/markers/marker_ambiguity.h"
#include "nav/markers/marker_frame_chain.h"
#include "tests/support/synthetic_marker_image.h"
#include "vision/markers/marker_detector.h"

namespace deepnav {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

MarkerObservation twoSolutions(bool ambiguous) {
  MarkerObservation obs;
  obs.ambiguous = ambiguous;
  obs.q_cam_marker = Eigen::Quaterniond(Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()));
  obs.p_marker_in_cam_m = Eigen::Vector3d(0.0, 0.0, 3.0);
  obs.q_cam_marker_alt = Eigen::Quaterniond(Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitY()));
  obs.p_marker_in_cam_alt_m = Eigen::Vector3d(0.01, 0.0, 3.02);
  obs.reprojection_error_px = 0.1;
  obs.reprojection_error_alt_px = 0.15;
  return obs;
}

TEST(MarkersAmbiguity, SwapsOnlyAnAmbiguousPoseWhoseAlternativeIsNearer) {
  const Eigen::Quaterniond near_alt(Eigen::AngleAxisd(-0.15, Eigen::Vector3d::UnitY()));
  const Eigen::Quaterniond near_best(Eigen::AngleAxisd(0.18, Eigen::Vector3d::UnitY()));
  // GIVEN an ambiguous observation and a prediction near its alternative WHEN resolved THEN
  // swapped, with the alternative's position, errors and distance
  MarkerObservation obs = twoSolutions(true);
  EXPECT_TRUE(preferSolutionNear(near_alt, &obs));
  EXPECT_LT(obs.q_cam_marker.angularDistance(near_alt), 0.06);
  EXPECT_EQ(obs.p_marker_in_cam_m, Eigen::Vector3d(0.01, 0.0, 3.02));
  EXPECT_EQ(obs.reprojection_error_px, 0.15);
  EXPECT_EQ(obs.reprojection_error_alt_px, 0.1);
  EXPECT_DOUBLE_EQ(obs.distance_m, obs.p_marker_in_cam_m.norm());
  EXPECT_TRUE(obs.ambiguous);  // the prediction chose, not the image
  // The marker normal (z_M) turned by -0.2 rad about y_C points along -sin(0.2) x + cos(0.2) z:
  // away from the camera, whose ray to it is about -z. Obliqueness ~ pi - 0.2 - the small angle of
  // the ray.
  EXPECT_NEAR(obs.obliqueness_rad, std::numbers::pi - 0.2 - std::atan2(0.01, 3.02), 1e-9);
  // GIVEN a prediction near the best THEN unchanged
  MarkerObservation kept = twoSolutions(true);
  EXPECT_FALSE(preferSolutionNear(near_best, &kept));
  EXPECT_EQ(kept.p_marker_in_cam_m, Eigen::Vector3d(0.0, 0.0, 3.0));
  // GIVEN a non-ambiguous observation THEN never swapped
  MarkerObservation clear = twoSolutions(false);
  EXPECT_FALSE(preferSolutionNear(near_alt, &clear));
  EXPECT_EQ(clear.p_marker_in_cam_m, Eigen::Vector3d(0.0, 0.0, 3.0));
}

TEST(MarkersAmbiguity, PredictedPoseOfTheMarkerIsTheFrameChainInverse) {
  // GIVEN robot, mounting, panel and marker poses THEN the predicted T_cam_marker chains back to
  // the robot
  const Eigen::Isometry3d T_odom_robot =
      isometryOf(Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())),
                 Eigen::Vector3d(1.0, 2.0, -30.0));
  const Eigen::Isometry3d T_robot_cam =
      isometryOf(Eigen::Quaterniond(Eigen::AngleAxisd(-1.1, Eigen::Vector3d(0, 1, 1).normalized())),
                 Eigen::Vector3d(0.6, 0.15, -0.2));
  const Eigen::Isometry3d T_odom_panel =
      isometryOf(Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ())),
                 Eigen::Vector3d(4, 5, -31));
  const Eigen::Isometry3d T_panel_marker =
      isometryOf(Eigen::Quaterniond(Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, 0, 1).normalized())),
                 Eigen::Vector3d(1.0, 0.2, 0.9));
  const Eigen::Isometry3d T_cam_marker =
      predictedCameraMarkerPose(T_odom_robot, T_robot_cam, T_odom_panel, T_panel_marker);
  const Eigen::Isometry3d back =
      robotPoseFromMarker(T_odom_panel, T_panel_marker, T_cam_marker, T_robot_cam);
  EXPECT_LT((back.matrix() - T_odom_robot.matrix()).norm(), 1e-12);
}

TEST(MarkersAmbiguity, FarNearlyHeadOnMarkersAreResolvedByThePrediction) {
  // GIVEN a marker 4 m away tilted 6 deg, in 12 images with different noise: its two IPPE solutions
  // fit about equally and the lower-error one is sometimes the wrong tilt
  MarkerDetectorConfig config;
  config.camera = PinholeIntrinsics{700.0, 700.0, 343.5, 257.5};
  MarkerDetector detector;
  ASSERT_TRUE(detector.init(config, nullptr));
  SyntheticMarker m;
  m.id = 5;
  m.q_cam_marker = Eigen::Quaterniond(
      Eigen::Matrix3d(Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal()) *
      Eigen::AngleAxisd(6.0 * kDeg, Eigen::Vector3d(1.0, 1.0, 0.0).normalized()));
  m.p_marker_in_cam_m = Eigen::Vector3d(0.1, -0.05, 4.0);
  int ambiguous = 0;
  double worst_before_deg = 0.0, worst_after_deg = 0.0;
  for (int seed = 1; seed <= 12; ++seed) {
    cv::Mat image(516, 688, CV_8UC1, cv::Scalar(110));
    ASSERT_TRUE(drawSyntheticMarker("DICT_4X4_50", m, config.camera, 4, &image));
    cv::GaussianBlur(image, image, cv::Size(5, 5), 0.6);
    cv::RNG rng(seed);
    addGaussianNoise(3.0, &rng, &image);
    MarkerObservations out;
    ASSERT_TRUE(detector.detect(image, &out));
    ASSERT_EQ(out.count, 1);
    MarkerObservation obs = out.items[0];
    if (!obs.ambiguous) continue;
    ++ambiguous;
    worst_before_deg =
        std::max(worst_before_deg, obs.q_cam_marker.angularDistance(m.q_cam_marker) / kDeg);
    // WHEN resolved with a prediction 2 deg off the truth (a filter's orientation error)
    const Eigen::Quaterniond predicted =
        m.q_cam_marker *
        Eigen::Quaterniond(Eigen::AngleAxisd(2.0 * kDeg, Eigen::Vector3d::UnitZ()));
    preferSolutionNear(predicted, &obs);
    worst_after_deg =
        std::max(worst_after_deg, obs.q_cam_marker.angularDistance(m.q_cam_marker) / kDeg);
  }
  // THEN the ambiguity shows up, the raw choice is sometimes far off, the resolved one never is
  EXPECT_GE(ambiguous, 6);
  EXPECT_GT(worst_before_deg, 8.0);
  EXPECT_LT(worst_after_deg, 5.0);
}

}  // namespace
}  // namespace deepnav
