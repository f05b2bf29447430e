// MarkerDetector on synthetic images: a marker drawn by the exact homography of a known camera pose
// (white quiet zone, grey background, blur, noise) must come back with its id, corners and pose.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "tests/support/synthetic_marker_image.h"
#include "vision/markers/aruco_dictionary.h"
#include "vision/markers/marker_detector.h"
#include "vision/markers/square_marker_pose.h"

namespace deepnav {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr int kWidthPx = 688;
constexpr int kHeightPx = 516;

PinholeIntrinsics camera() { return PinholeIntrinsics{700.0, 700.0, 343.5, 257.5}; }

MarkerDetectorConfig detectorConfig() {
  MarkerDetectorConfig c;
  c.dictionary = "DICT_4X4_50";
  c.marker_size_m = 0.15;
  c.camera = camera();
  return c;
}

// A marker facing the camera (M: x right, y up, z towards the camera is R = diag(1, -1, -1) in C),
// turned by yaw about its own vertical axis y_M, tilted by pitch about x_M and spun by roll about
// z_M.
SyntheticMarker markerAt(int id, const Eigen::Vector3d& p_marker_in_cam_m, double yaw_rad,
                         double pitch_rad = 0.0, double roll_rad = 0.0) {
  SyntheticMarker m;
  m.id = id;
  m.marker_size_m = 0.15;
  m.quiet_zone_m = 0.04;
  const Eigen::Matrix3d facing = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
  m.q_cam_marker =
      Eigen::Quaterniond(facing * Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitY()) *
                         Eigen::AngleAxisd(pitch_rad, Eigen::Vector3d::UnitX()) *
                         Eigen::AngleAxisd(roll_rad, Eigen::Vector3d::UnitZ()));
  m.p_marker_in_cam_m = p_marker_in_cam_m;
  return m;
}

// Grey background with a gentle gradient, the markers, optics blur and sensor noise (fixed seed).
cv::Mat renderScene(const SyntheticMarker* markers, int n, double noise_sigma = 2.0,
                    std::uint64_t seed = 1) {
  cv::Mat image(kHeightPx, kWidthPx, CV_8UC1);
  for (int r = 0; r < image.rows; ++r) {
    for (int c = 0; c < image.cols; ++c)
      image.at<std::uint8_t>(r, c) = static_cast<std::uint8_t>(100 + c / 20);
  }
  for (int i = 0; i < n; ++i)
    EXPECT_TRUE(drawSyntheticMarker("DICT_4X4_50", markers[i], camera(), 4, &image));
  cv::GaussianBlur(image, image, cv::Size(5, 5), 0.6);
  cv::RNG rng(seed);
  addGaussianNoise(noise_sigma, &rng, &image);
  return image;
}

double angleDeg(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return a.angularDistance(b) / kDeg;
}

TEST(MarkersDictionary, NamesMapToOpenCvIds) {
  // GIVEN the enum spellings WHEN looked up THEN known ones resolve with their sizes, others fail
  int id = -1;
  ASSERT_TRUE(arucoDictionaryFromName("DICT_4X4_50", &id));
  EXPECT_EQ(id, 0);
  EXPECT_EQ(arucoDictionarySize(id), 50);
  ASSERT_TRUE(arucoDictionaryFromName("DICT_APRILTAG_36h11", &id));
  EXPECT_EQ(arucoDictionarySize(id), 587);
  EXPECT_FALSE(arucoDictionaryFromName("DICT_4x4_50", &id));  // case matters, as in the enum
  EXPECT_FALSE(arucoDictionaryFromName("", &id));
}

TEST(MarkersDetector, InitRejectsBadConfigNamingTheKey) {
  // GIVEN configs with one bad field each WHEN init THEN false and the key is named
  MarkerDetector detector;
  std::string error;
  MarkerDetectorConfig c = detectorConfig();
  c.dictionary = "DICT_9X9_1";
  EXPECT_FALSE(detector.init(c, &error));
  EXPECT_NE(error.find("dictionary"), std::string::npos);
  c = detectorConfig();
  c.marker_size_m = 0.0;
  EXPECT_FALSE(detector.init(c, &error));
  EXPECT_NE(error.find("marker_size_m"), std::string::npos);
  c = detectorConfig();
  c.camera.fy_px = -1.0;
  EXPECT_FALSE(detector.init(c, &error));
  EXPECT_NE(error.find("fx_px"), std::string::npos);
  c = detectorConfig();
  c.corner_refinement.max_half_window_px = 0;
  EXPECT_FALSE(detector.init(c, &error));
  EXPECT_NE(error.find("corner_refinement.max_half_window_px"), std::string::npos);
  c = detectorConfig();
  c.ambiguity.corner_sigma_px = 0.0;
  EXPECT_FALSE(detector.init(c, &error));
  EXPECT_NE(error.find("corner_sigma_px"), std::string::npos);
  EXPECT_FALSE(detector.initialised());
  // AND an uninitialised detector refuses to detect
  MarkerObservations out;
  EXPECT_FALSE(detector.detect(cv::Mat(10, 10, CV_8UC1, cv::Scalar(0)), &out));
  EXPECT_EQ(out.count, 0);
}

TEST(MarkersDetector, RejectsEmptyAndWrongTypeImages) {
  MarkerDetector detector;
  ASSERT_TRUE(detector.init(detectorConfig(), nullptr));
  MarkerObservations out;
  out.count = 3;
  EXPECT_FALSE(detector.detect(cv::Mat(), &out));
  EXPECT_EQ(out.count, 0);
  EXPECT_FALSE(detector.detect(cv::Mat(20, 20, CV_16UC1, cv::Scalar(0)), &out));
  // GIVEN a blank image THEN true with no marker
  EXPECT_TRUE(detector.detect(cv::Mat(kHeightPx, kWidthPx, CV_8UC1, cv::Scalar(128)), &out));
  EXPECT_EQ(out.count, 0);
}

TEST(MarkersSquarePose, ExactCornersGiveTheExactPoseInTheArucoFrame) {
  // GIVEN the exact projections of the 4 corners of markers in many poses (frame convention check:
  // M has x right, y up, z towards the camera; corners in ArUco order)
  const double yaws[] = {-50.0, -20.0, 25.0, 55.0};
  const double rolls[] = {0.0, 30.0, 120.0, -100.0};
  for (double yaw : yaws) {
    for (double roll : rolls) {
      const SyntheticMarker m =
          markerAt(3, Eigen::Vector3d(0.2, -0.1, 1.5), yaw * kDeg, 10.0 * kDeg, roll * kDeg);
      std::array<Eigen::Vector2d, 4> corners;
      for (int k = 0; k < 4; ++k) corners[k] = projectMarkerCorner(m, camera(), k);
      // WHEN the pose is estimated
      MarkerObservation obs;
      ASSERT_TRUE(estimateSquareMarkerPose(corners, 0.15, camera(), MarkerAmbiguityConfig{}, &obs));
      // THEN it is the truth, with zero reprojection error, and the other solution fits worse
      EXPECT_LT((obs.p_marker_in_cam_m - m.p_marker_in_cam_m).norm(), 1e-9) << yaw << " " << roll;
      EXPECT_LT(angleDeg(obs.q_cam_marker, m.q_cam_marker), 1e-6) << yaw << " " << roll;
      EXPECT_LT(obs.reprojection_error_px, 1e-6);
      EXPECT_GT(obs.reprojection_error_alt_px, obs.reprojection_error_px);
      EXPECT_NEAR(obs.distance_m, m.p_marker_in_cam_m.norm(), 1e-9);
      const Eigen::Vector3d n = m.q_cam_marker * Eigen::Vector3d::UnitZ();
      EXPECT_NEAR(obs.obliqueness_rad, std::acos(-n.dot(m.p_marker_in_cam_m.normalized())), 1e-9);
    }
  }
}

TEST(MarkersSquarePose, UprightHeadOnMarkerIsARotationOfPiAndStillExact) {
  // GIVEN the exact corners of upright markers facing the camera, turned about their vertical axis
  // only: R_cam_marker = diag(1, -1, -1) * Ry(a) is a rotation by exactly pi for every a, where
  // OpenCV 4.6's IPPE returns a wrong rotation (its rotation-vector conversion divides by sin(pi))
  for (double a_deg : {0.0, 10.0, 25.0, -40.0}) {
    const SyntheticMarker m = markerAt(1, Eigen::Vector3d(0.0, 0.0, 1.5), a_deg * kDeg);
    ASSERT_NEAR(Eigen::AngleAxisd(m.q_cam_marker).angle(), std::numbers::pi, 1e-9);
    std::array<Eigen::Vector2d, 4> corners;
    for (int k = 0; k < 4; ++k) corners[k] = projectMarkerCorner(m, camera(), k);
    // WHEN the pose is estimated
    MarkerObservation obs;
    ASSERT_TRUE(estimateSquareMarkerPose(corners, 0.15, camera(), MarkerAmbiguityConfig{}, &obs));
    // THEN it is exact (solved again in a slightly rotated virtual camera)
    EXPECT_LT((obs.p_marker_in_cam_m - m.p_marker_in_cam_m).norm(), 1e-9) << a_deg;
    EXPECT_LT(angleDeg(obs.q_cam_marker, m.q_cam_marker), 1e-6) << a_deg;
    EXPECT_LT(obs.reprojection_error_px, 1e-6) << a_deg;
  }
}

TEST(MarkersSquarePose, ObliquenessIsTheAngleBetweenNormalAndRay) {
  // GIVEN a marker on the optical axis turned by a about its vertical axis THEN obliqueness = a
  for (double a_deg : {0.0, 15.0, 45.0, 80.0}) {
    const SyntheticMarker m = markerAt(0, Eigen::Vector3d(0.0, 0.0, 2.0), a_deg * kDeg);
    EXPECT_NEAR(markerObliquenessRad(m.q_cam_marker, m.p_marker_in_cam_m), a_deg * kDeg, 1e-12);
  }
  // AND a head-on marker off the axis has the angle of its ray
  const SyntheticMarker off = markerAt(0, Eigen::Vector3d(1.0, 0.0, 1.0), 0.0);
  EXPECT_NEAR(markerObliquenessRad(off.q_cam_marker, off.p_marker_in_cam_m), 45.0 * kDeg, 1e-12);
}

TEST(MarkersDetector, PoseWithinOneCentimetreAndOneDegreeAt1_5m) {
  // GIVEN single markers at 1.5 m seen at various angles, in noisy rendered images
  MarkerDetector detector;
  ASSERT_TRUE(detector.init(detectorConfig(), nullptr));
  struct Case {
    Eigen::Vector3d p;
    double yaw_deg, pitch_deg, roll_deg;
  };
  const Case cases[] = {
      {{0.0, 0.0, 1.5}, 25.0, 0.0, 0.0},
      {{0.2, -0.1, 1.48}, -35.0, 10.0, 20.0},
      {{-0.3, 0.15, 1.45}, 45.0, -15.0, 95.0},
      {{0.1, 0.2, 1.48}, 15.0, 25.0, -150.0},
  };
  int seed = 1;
  for (const Case& k : cases) {
    const SyntheticMarker m =
        markerAt(7, k.p, k.yaw_deg * kDeg, k.pitch_deg * kDeg, k.roll_deg * kDeg);
    const cv::Mat image = renderScene(&m, 1, 2.0, seed++);
    // WHEN detected
    MarkerObservations out;
    ASSERT_TRUE(detector.detect(image, &out));
    // THEN one marker, right id, corners within 0.4 px (cv::cornerSubPix pulls a corner of an
    // area-sampled square inwards by 0.1-0.3 px), pose within 1 cm and 1 deg, not ambiguous
    ASSERT_EQ(out.count, 1) << k.yaw_deg;
    const MarkerObservation& obs = out.items[0];
    EXPECT_EQ(obs.id, 7);
    for (int c = 0; c < 4; ++c) {
      EXPECT_LT((obs.corners_px[c] - projectMarkerCorner(m, camera(), c)).norm(), 0.4)
          << k.yaw_deg << " " << c;
    }
    EXPECT_LT((obs.p_marker_in_cam_m - m.p_marker_in_cam_m).norm(), 0.01) << k.yaw_deg;
    EXPECT_LT(angleDeg(obs.q_cam_marker, m.q_cam_marker), 1.0) << k.yaw_deg;
    EXPECT_LT(obs.reprojection_error_px, 0.3);
    EXPECT_FALSE(obs.ambiguous) << k.yaw_deg << " alt " << obs.reprojection_error_alt_px;
    EXPECT_NEAR(obs.distance_m, m.p_marker_in_cam_m.norm(), 0.01);
    EXPECT_NEAR(obs.obliqueness_rad, markerObliquenessRad(m.q_cam_marker, m.p_marker_in_cam_m),
                1.0 * kDeg);
  }
}

TEST(MarkersDetector, FarHeadOnMarkerIsFlaggedAmbiguous) {
  // GIVEN a small marker far away seen head-on: the two IPPE tilts explain its corners equally well
  MarkerDetector detector;
  ASSERT_TRUE(detector.init(detectorConfig(), nullptr));
  const SyntheticMarker m = markerAt(2, Eigen::Vector3d(0.0, 0.0, 4.0), 0.0);
  MarkerObservations out;
  ASSERT_TRUE(detector.detect(renderScene(&m, 1), &out));
  ASSERT_EQ(out.count, 1);
  // THEN it is flagged, and the alternative is the other tilt with a similar error
  EXPECT_TRUE(out.items[0].ambiguous)
      << out.items[0].reprojection_error_px << " " << out.items[0].reprojection_error_alt_px;
  // AND the same marker close and oblique is not
  const SyntheticMarker near = markerAt(2, Eigen::Vector3d(0.0, 0.0, 1.0), 40.0 * kDeg);
  ASSERT_TRUE(detector.detect(renderScene(&near, 1), &out));
  ASSERT_EQ(out.count, 1);
  EXPECT_FALSE(out.items[0].ambiguous);
}

TEST(MarkersDetector, FourMarkersInOneColourImage) {
  // GIVEN four markers in one BGR image
  MarkerDetector detector;
  ASSERT_TRUE(detector.init(detectorConfig(), nullptr));
  const SyntheticMarker markers[] = {
      markerAt(0, Eigen::Vector3d(-0.45, -0.3, 1.6), 20.0 * kDeg),
      markerAt(11, Eigen::Vector3d(0.45, -0.3, 1.6), -20.0 * kDeg),
      markerAt(22, Eigen::Vector3d(-0.45, 0.3, 1.6), 25.0 * kDeg, 10.0 * kDeg),
      markerAt(33, Eigen::Vector3d(0.45, 0.3, 1.6), -25.0 * kDeg, -10.0 * kDeg),
  };
  cv::Mat bgr;
  cv::cvtColor(renderScene(markers, 4), bgr, cv::COLOR_GRAY2BGR);
  // WHEN detected
  MarkerObservations out;
  ASSERT_TRUE(detector.detect(bgr, &out));
  // THEN all four, each with its own pose
  ASSERT_EQ(out.count, 4);
  EXPECT_EQ(out.dropped, 0);
  for (int i = 0; i < out.count; ++i) {
    const MarkerObservation& obs = out.items[i];
    const SyntheticMarker* truth = nullptr;
    for (const auto& m : markers) {
      if (m.id == obs.id) truth = &m;
    }
    ASSERT_NE(truth, nullptr) << obs.id;
    EXPECT_LT((obs.p_marker_in_cam_m - truth->p_marker_in_cam_m).norm(), 0.015) << obs.id;
    EXPECT_LT(angleDeg(obs.q_cam_marker, truth->q_cam_marker), 1.5) << obs.id;
  }
}

TEST(MarkersDetector, MoreMarkersThanCapacityAreCountedNotReported) {
  // GIVEN a 6 x 6 grid of 36 markers in one image (capacity 32)
  MarkerDetector detector;
  ASSERT_TRUE(detector.init(detectorConfig(), nullptr));
  std::vector<SyntheticMarker> grid;
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 6; ++c) {
      const Eigen::Vector3d p((c - 2.5) * 0.26, (r - 2.5) * 0.18, 1.6);
      SyntheticMarker m = markerAt(6 * r + c, p, 0.0);
      m.quiet_zone_m = 0.02;
      grid.push_back(m);
    }
  }
  MarkerObservations out;
  ASSERT_TRUE(detector.detect(renderScene(grid.data(), static_cast<int>(grid.size())), &out));
  // THEN 32 reported and 4 counted as dropped
  EXPECT_EQ(out.count, MarkerObservations::kCapacity);
  EXPECT_EQ(out.dropped, 4);
}

}  // namespace
}  // namespace deepnav
