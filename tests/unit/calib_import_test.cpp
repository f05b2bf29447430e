// `deepnav import calibration` (issue 19 item 3): Kalibr camchain.yaml, OpenCV stereo_calib YAML and a pair
// of ROS camera_info YAMLs into deepnav's calibration file. The example files are written by hand from the
// formats' documentation (Kalibr wiki "yaml formats"; OpenCV's FileStorage as stereo_calib writes it; the
// camera_info YAML of camera_calibration_parsers). The round trip from a real calibration is in
// calib_checkerboard_test.cpp (CheckerboardOpencvDoc, its check EachImportFormatGivesBackTheCalibration).
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>

#include "board/cli/import_calibration_command.h"
#include "board/config/calibration_import_camera_info.h"
#include "board/config/calibration_import_kalibr.h"
#include "board/config/calibration_import_opencv.h"
#include "board/config/stereo_calibration_file.h"
#include "tests/unit/calib_import_writers.h"
#include "tests/support/temp_path.h"

namespace deepnav {
namespace {

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = deepnav::testing::tempPath("calib_import_" + name);
  std::ofstream(path) << text;
  return path;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// EuRoC's cam0/cam1 (their sensor.yaml intrinsics; T_cn_cnm1 = T_BS(cam1)^-1 T_BS(cam0)), as Kalibr writes
// a camchain: T_cam_imu and rostopic are there too and ignored.
const std::string kEurocCamchain = R"(cam0:
  T_cam_imu:
  - [0.0148655429818, 0.999557249008, -0.0257744366974, 0.065222909883]
  - [-0.999880929698, 0.0149672133247, 0.00375618835797, -0.0207064052384]
  - [0.00414029679422, 0.025715529948, 0.999660727178, -0.00805460246003]
  - [0.0, 0.0, 0.0, 1.0]
  cam_overlaps: [1]
  camera_model: pinhole
  distortion_coeffs: [-0.28340811, 0.07395907, 0.00019359, 1.76187114e-05]
  distortion_model: radtan
  intrinsics: [458.654, 457.296, 367.215, 248.375]
  resolution: [752, 480]
  rostopic: /cam0/image_raw
cam1:
  T_cn_cnm1:
  - [0.9999972565, 0.002312067192, 0.0003760081024, -0.1100738081]
  - [-0.002317135723, 0.9998980485, 0.01408983585, 0.000399121547]
  - [-0.0003433931205, -0.01409066845, 0.9999006626, -0.0008537025034]
  - [0.0, 0.0, 0.0, 1.0]
  cam_overlaps: [0]
  camera_model: pinhole
  distortion_coeffs: [-0.28368365, 0.07451284, -0.00010473, -3.55590700e-05]
  distortion_model: radtan
  intrinsics: [457.587, 456.134, 379.999, 255.238]
  resolution: [752, 480]
  rostopic: /cam1/image_raw
)";

TEST(CalibImportKalibr, ReadsAHandWrittenEurocCamchain) {
  ImportedCalibration got;
  std::string error;
  ASSERT_TRUE(importKalibrCamchain(writeTemp("camchain.yaml", kEurocCamchain), &got, &error)) << error;
  const StereoCalibration& c = got.calibration;
  EXPECT_EQ(c.image_size, cv::Size(752, 480));
  EXPECT_DOUBLE_EQ(c.left.K(0, 0), 458.654);
  EXPECT_DOUBLE_EQ(c.left.K(1, 1), 457.296);
  EXPECT_DOUBLE_EQ(c.left.K(0, 2), 367.215);
  EXPECT_DOUBLE_EQ(c.right.K(1, 2), 255.238);
  ASSERT_EQ(c.left.dist.total(), 5u);  // radtan k1 k2 p1 p2, k3 = 0
  EXPECT_DOUBLE_EQ(c.left.dist.at<double>(3), 1.76187114e-05);
  EXPECT_DOUBLE_EQ(c.left.dist.at<double>(4), 0.0);
  EXPECT_DOUBLE_EQ(c.R(1, 2), 0.01408983585);
  EXPECT_DOUBLE_EQ(c.T[0], -0.1100738081);
  EXPECT_NEAR(cv::norm(c.T), 0.110078, 1e-6);
  EXPECT_TRUE(got.notes.empty());
}

TEST(CalibImportKalibr, RewritesAnEquidistantLensAsTheRationalModel) {
  // A wide-angle lens calibrated with Kalibr's equidistant model (58 deg from the axis to the image corners).
  const std::string camchain =
      replaced(replaced(kEurocCamchain,
                        "distortion_coeffs: [-0.28340811, 0.07395907, 0.00019359, 1.76187114e-05]\n"
                        "  distortion_model: radtan",
                        "distortion_coeffs: [-0.0118, 0.0213, -0.0301, 0.0124]\n  distortion_model: equidistant"),
               "distortion_coeffs: [-0.28368365, 0.07451284, -0.00010473, -3.55590700e-05]\n  distortion_model: radtan",
               "distortion_coeffs: [-0.0102, 0.0187, -0.0266, 0.0110]\n  distortion_model: equidistant");
  ImportedCalibration got;
  std::string error;
  ASSERT_TRUE(importKalibrCamchain(writeTemp("equi.yaml", camchain), &got, &error)) << error;
  ASSERT_EQ(got.notes.size(), 2u);
  std::printf("%s\n%s\n", got.notes[0].c_str(), got.notes[1].c_str());
  EXPECT_TRUE(has(got.notes[0], "cam0: equidistant lens rewritten as OpenCV's rational model")) << got.notes[0];
  // Every pixel of the image lands where cv::fisheye (the equidistant model) puts it, within 0.1 px.
  const CameraCalibration& cam = got.calibration.left;
  ASSERT_EQ(cam.dist.total(), 8u);
  const cv::Vec4d k(-0.0118, 0.0213, -0.0301, 0.0124);
  std::vector<cv::Point2d> pixels;
  for (int v = 0; v <= 480; v += 16)
    for (int u = 0; u <= 752; u += 16) pixels.emplace_back(u, v);
  std::vector<cv::Point2d> normalised, fisheye_px, rational_px;
  cv::fisheye::undistortPoints(pixels, normalised, cam.K, k);
  std::vector<cv::Point3d> rays;
  for (const auto& p : normalised) rays.emplace_back(p.x, p.y, 1.0);
  cv::fisheye::projectPoints(rays, fisheye_px, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), cam.K, k);
  cv::projectPoints(rays, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), cam.K, cam.dist, rational_px);
  double worst = 0.0;
  for (std::size_t i = 0; i < rays.size(); ++i) worst = std::max(worst, cv::norm(fisheye_px[i] - rational_px[i]));
  std::printf("equidistant -> rational: worst difference %.4f px over %zu pixels\n", worst, rays.size());
  EXPECT_LT(worst, kMaxEquidistantFitErrorPx);
}

TEST(CalibImportKalibr, ALensWithoutDistortionNeedsNoCoefficients) {
  const std::string camchain =
      replaced(kEurocCamchain,
               "distortion_coeffs: [-0.28340811, 0.07395907, 0.00019359, 1.76187114e-05]\n  distortion_model: radtan",
               "distortion_model: none");
  ImportedCalibration got;
  std::string error;
  ASSERT_TRUE(importKalibrCamchain(writeTemp("none.yaml", camchain), &got, &error)) << error;
  EXPECT_EQ(cv::norm(got.calibration.left.dist, cv::NORM_INF), 0.0);
  EXPECT_DOUBLE_EQ(got.calibration.right.dist.at<double>(0), -0.28368365);
}

TEST(CalibImportKalibr, RefusesAFisheyeWiderThanAPinholeHolds) {
  // TUM-VI-like 512 x 512 fisheye: its corners lie past 90 deg from the axis.
  std::string camchain = replaced(kEurocCamchain, "intrinsics: [458.654, 457.296, 367.215, 248.375]",
                                  "intrinsics: [190.978, 190.973, 254.932, 256.897]");
  camchain = replaced(camchain,
                      "distortion_coeffs: [-0.28340811, 0.07395907, 0.00019359, 1.76187114e-05]\n"
                      "  distortion_model: radtan",
                      "distortion_coeffs: [0.0034824, 0.00071503, -0.0020532, 0.00020294]\n"
                      "  distortion_model: equidistant");
  camchain = replaced(camchain, "resolution: [752, 480]", "resolution: [512, 512]");
  ImportedCalibration got;
  std::string error;
  const std::string path = writeTemp("tumvi.yaml", camchain);
  EXPECT_FALSE(importKalibrCamchain(path, &got, &error));
  EXPECT_TRUE(has(error, path + ": key 'cam0.distortion_coeffs' (equidistant): the image corners lie 115.6 deg from "
                                "the axis; a pinhole rectification holds rays under 89 deg only"))
      << error;
}

// The ROS stereo calibrator's pair for a 640 x 480 rig: R = Rodrigues(0.002, 0.009, -0.003),
// T = (-0.12, 0.001, 0.002) m, rectified by OpenCV (alpha 0); numbers to 10 digits as printed.
const std::string kLeftInfo = R"(image_width: 640
image_height: 480
camera_name: narrow_stereo/left
camera_matrix:
  rows: 3
  cols: 3
  data: [700, 0, 320, 0, 700, 240, 0, 0, 1]
distortion_model: plumb_bob
distortion_coefficients:
  rows: 1
  cols: 5
  data: [-0.1, 0.05, 0.001, -0.0005, 0]
rectification_matrix:
  rows: 3
  cols: 3
  data: [0.9999563841, -0.005356504182, -0.007650992228, 0.00534889876, 0.9999851803, -0.00101416086, 0.007656311199, 0.0009731922435, 0.9999702165]
projection_matrix:
  rows: 3
  cols: 4
  data: [710.7039808, 0, 335.7009659, 0, 0, 710.7039808, 238.0627785, 0, 0, 0, 1, 0]
)";

const std::string kRightInfo = R"(image_width: 640
image_height: 480
camera_name: narrow_stereo/right
camera_matrix:
  rows: 3
  cols: 3
  data: [705, 0, 330, 0, 704, 236, 0, 0, 1]
distortion_model: plumb_bob
distortion_coefficients:
  rows: 1
  cols: 5
  data: [-0.11, 0.06, -0.0008, 0.0003, 0]
rectification_matrix:
  rows: 3
  cols: 3
  data: [0.9998264341, -0.008331886951, -0.0166637739, 0.008348442137, 0.9999647241, 0.0009241661941, 0.01665548602, -0.001063122343, 0.9998607226]
projection_matrix:
  rows: 3
  cols: 4
  data: [710.7039808, 0, 335.7009659, -85.29928274, 0, 710.7039808, 238.0627785, 0, 0, 0, 1, 0]
)";

TEST(CalibImportCameraInfo, RecoversTheExtrinsicsFromTheRectification) {
  ImportedCalibration got;
  std::string error;
  ASSERT_TRUE(
      importCameraInfoPair(writeTemp("left.yaml", kLeftInfo), writeTemp("right.yaml", kRightInfo), &got, &error))
      << error;
  const StereoCalibration& c = got.calibration;
  cv::Matx33d R_true;
  cv::Rodrigues(cv::Vec3d(0.002, 0.009, -0.003), R_true);
  EXPECT_EQ(c.image_size, cv::Size(640, 480));
  EXPECT_DOUBLE_EQ(c.right.K(1, 1), 704.0);
  EXPECT_DOUBLE_EQ(c.right.dist.at<double>(2), -0.0008);
  EXPECT_LT(cv::norm(cv::Mat(c.R), cv::Mat(R_true), cv::NORM_INF), 1e-8);
  // Baseline = -Tx / fx' = 85.29928274 / 710.7039808 = 0.120020 m, along the rectified x.
  EXPECT_NEAR(c.T[0], -0.12, 1e-8);
  EXPECT_NEAR(c.T[1], 0.001, 1e-8);
  EXPECT_NEAR(c.T[2], 0.002, 1e-8);
}

const std::string kIntrinsicsYml = R"(%YAML:1.0
---
M1: !!opencv-matrix
   rows: 3
   cols: 3
   dt: d
   data: [ 5.3248999999999999e+02, 0., 3.4220000000000002e+02, 0.,
       5.3240999999999997e+02, 2.3344999999999999e+02, 0., 0., 1. ]
D1: !!opencv-matrix
   rows: 1
   cols: 5
   dt: d
   data: [ -2.8100000000000003e-01, 2.5000000000000000e-02,
       1.2000000000000000e-03, -3.0000000000000003e-04, 0. ]
M2: !!opencv-matrix
   rows: 3
   cols: 3
   dt: d
   data: [ 5.3503999999999996e+02, 0., 3.2677999999999997e+02, 0.,
       5.3485000000000002e+02, 2.4998000000000002e+02, 0., 0., 1. ]
D2: !!opencv-matrix
   rows: 1
   cols: 5
   dt: d
   data: [ -2.9099999999999998e-01, 1.4300000000000000e-01,
       -1.1000000000000000e-03, 2.0000000000000001e-04, 0. ]
)";

const std::string kExtrinsicsYml = R"(%YAML:1.0
---
R: !!opencv-matrix
   rows: 3
   cols: 3
   dt: d
   data: [ 1., 0., 0., 0., 1., 0., 0., 0., 1. ]
T: !!opencv-matrix
   rows: 3
   cols: 1
   dt: d
   data: [ -8.2900000000000001e-02, 9.0000000000000008e-04,
       -2.0000000000000001e-04 ]
)";

TEST(CalibImportOpenCv, ReadsStereoCalibFilesAndNeedsAnImageSize) {
  const std::string intrinsics = writeTemp("intrinsics.yml", kIntrinsicsYml);
  const std::string extrinsics = writeTemp("extrinsics.yml", kExtrinsicsYml);
  ImportedCalibration got;
  std::string error;
  EXPECT_FALSE(importOpenCvStereo({intrinsics, extrinsics}, cv::Size(0, 0), &got, &error));
  EXPECT_TRUE(has(error, intrinsics + ": no image size") && has(error, "--image-size")) << error;
  ASSERT_TRUE(importOpenCvStereo({intrinsics, extrinsics}, cv::Size(640, 480), &got, &error)) << error;
  EXPECT_EQ(got.calibration.image_size, cv::Size(640, 480));
  EXPECT_DOUBLE_EQ(got.calibration.left.K(0, 0), 532.49);
  EXPECT_DOUBLE_EQ(got.calibration.right.dist.at<double>(1), 0.143);
  EXPECT_DOUBLE_EQ(got.calibration.T[0], -0.0829);
  // One file with everything and its own image size.
  const std::string all = writeTemp("all.yml", kIntrinsicsYml + kExtrinsicsYml.substr(kExtrinsicsYml.find("R:")) +
                                                   "image_width: 640\nimage_height: 480\n");
  ASSERT_TRUE(importOpenCvStereo({all}, cv::Size(0, 0), &got, &error)) << error;
  EXPECT_EQ(got.calibration.image_size, cv::Size(640, 480));
  EXPECT_FALSE(importOpenCvStereo({all}, cv::Size(752, 480), &got, &error));
  EXPECT_TRUE(has(error, "disagrees with --image-size 752x480")) << error;
  // A key in two files.
  EXPECT_FALSE(importOpenCvStereo({all, extrinsics}, cv::Size(0, 0), &got, &error));
  EXPECT_TRUE(has(error, extrinsics + ": key 'R' is also in " + all)) << error;
}

TEST(CalibImportBadInput, EachBadKalibrFileIsNamedWithItsKey) {
  const struct {
    std::string from, to, message;
  } cases[] = {
      {"  intrinsics: [458.654, 457.296, 367.215, 248.375]\n", "", "key 'cam0.intrinsics' is missing"},
      {"intrinsics: [458.654, 457.296, 367.215, 248.375]", "intrinsics: [458.654, 457.296, 367.215]",
       "key 'cam0.intrinsics' must hold 4 numbers, not 3"},
      {"intrinsics: [457.587, 456.134,", "intrinsics: [-457.587, 456.134,",
       "key 'cam1.intrinsics' focal lengths must be positive"},
      {"resolution: [752, 480]\n  rostopic: /cam1", "resolution: [640, 480]\n  rostopic: /cam1",
       "key 'cam1.resolution' differs between the cameras: 752 x 480 (left) and 640 x 480 (right)"},
      {"- [0.9999972565, 0.002312067192,", "- [1.9999972565, 0.002312067192,",
       "key 'cam1.T_cn_cnm1' is not a rotation"},
      {"0.000399121547]", "0.0]\n  - [0.0, 0.0, 0.0, 1.0]", "key 'cam1.T_cn_cnm1' must hold 16 numbers, not 20"},
      {"camera_model: pinhole\n  distortion_coeffs: [-0.28368365",
       "camera_model: omni\n  distortion_coeffs: [-0.28368365", "key 'cam1.camera_model' is omni; only pinhole"},
      {"distortion_model: radtan\n  intrinsics: [458.654", "distortion_model: fov\n  intrinsics: [458.654",
       "key 'cam0.distortion_model' is fov; radtan, equidistant or none expected"},
      {"cam1:\n", "cam2:\n", "key 'cam1' is missing"},
  };
  for (const auto& c : cases) {
    const std::string path = writeTemp("bad_camchain.yaml", replaced(kEurocCamchain, c.from, c.to));
    ImportedCalibration got;
    std::string error;
    EXPECT_FALSE(importKalibrCamchain(path, &got, &error)) << c.message;
    EXPECT_TRUE(has(error, path + ": " + c.message)) << "expected '" << c.message << "', got: " << error;
  }
  // Both cameras in one place.
  std::string same_place = replaced(kEurocCamchain, "-0.1100738081]", "0.0]");
  same_place = replaced(same_place, "0.000399121547]", "0.0]");
  same_place = replaced(same_place, "-0.0008537025034]", "0.0]");
  const std::string path = writeTemp("zero_baseline.yaml", same_place);
  ImportedCalibration got;
  std::string error;
  EXPECT_FALSE(importKalibrCamchain(path, &got, &error));
  EXPECT_TRUE(has(error, path + ": key 'cam1.T_cn_cnm1' gives a baseline of 0 m")) << error;
}

TEST(CalibImportBadInput, EachBadCameraInfoFileIsNamedWithItsKey) {
  const struct {
    bool right;
    std::string from, to, message;
  } cases[] = {
      {false, "camera_matrix:\n  rows: 3", "camera_matrix:\n  rows: 2", "key 'camera_matrix' is 2 x 3, 3 x 3 expected"},
      {true, "data: [705, 0, 330, 0, 704, 236, 0, 0, 1]", "data: [705, 0, 330, 0, 704, 236, 0, 0]",
       "key 'camera_matrix.data' must hold 9 numbers, not 8"},
      {true, "image_width: 640", "image_width: 752", "differs between the cameras: 640 x 480 (left) and 752 x 480"},
      {false, "distortion_model: plumb_bob", "distortion_model: fisheye62", "key 'distortion_model' is fisheye62"},
      {false, "  cols: 5\n  data: [-0.1, 0.05, 0.001, -0.0005, 0]", "  cols: 4\n  data: [-0.1, 0.05, 0.001, -0.0005]",
       "key 'distortion_coefficients' holds 4 numbers; plumb_bob has 5"},
      {true, "data: [0.9998264341,", "data: [0.8998264341,", "key 'rectification_matrix' is not a rotation"},
      {true, "-85.29928274", "0", "key 'projection_matrix' has Tx = 0.000000"},
      {false, "data: [700, 0, 320, 0, 700, 240, 0, 0, 1]", "data: [0, 0, 320, 0, 700, 240, 0, 0, 1]",
       "key 'camera_matrix' focal lengths must be positive"},
  };
  for (const auto& c : cases) {
    const std::string left = writeTemp("bad_left.yaml", c.right ? kLeftInfo : replaced(kLeftInfo, c.from, c.to));
    const std::string right = writeTemp("bad_right.yaml", c.right ? replaced(kRightInfo, c.from, c.to) : kRightInfo);
    ImportedCalibration got;
    std::string error;
    EXPECT_FALSE(importCameraInfoPair(left, right, &got, &error)) << c.message;
    EXPECT_TRUE(has(error, (c.right ? right : left) + ": ") && has(error, c.message))
        << "expected '" << c.message << "', got: " << error;
  }
  // The two files given the wrong way round.
  ImportedCalibration got;
  std::string error;
  const std::string left = writeTemp("left.yaml", kLeftInfo), right = writeTemp("right.yaml", kRightInfo);
  EXPECT_FALSE(importCameraInfoPair(right, left, &got, &error));
  EXPECT_TRUE(has(error, right + ": key 'projection_matrix' has Tx = -85.299283") &&
              has(error, "give the left camera's file first"))
      << error;
}

TEST(CalibImportBadInput, EachBadOpenCvFileIsNamedWithItsKey) {
  const std::string extrinsics = writeTemp("extrinsics.yml", kExtrinsicsYml);
  const struct {
    bool in_extrinsics;
    std::string from, to, message;
  } cases[] = {
      {false, "M1: !!opencv-matrix\n   rows: 3", "M1: !!opencv-matrix\n   rows: 1",
       "key 'M1' must be an opencv-matrix of 3 x 3 numbers"},
      {false, "D2:", "D3:", "key 'D2' is missing"},
      {true, "data: [ 1., 0., 0., 0., 1., 0., 0., 0., 1. ]", "data: [ 1., 0., 0., 0., 1., 0., 0., 0., -1. ]",
       "key 'R' is a reflection"},
      {true, "data: [ 1., 0., 0., 0., 1., 0., 0., 0., 1. ]", "data: [ 1., 0.1, 0., 0., 1., 0., 0., 0., 1. ]",
       "key 'R' is not a rotation"},
      {true, "data: [ -8.2900000000000001e-02, 9.0000000000000008e-04,\n       -2.0000000000000001e-04 ]",
       "data: [ 0., 0., 0. ]", "key 'T' gives a baseline of 0 m"},
  };
  for (const auto& c : cases) {
    const std::string in =
        writeTemp("bad_intrinsics.yml", c.in_extrinsics ? kIntrinsicsYml : replaced(kIntrinsicsYml, c.from, c.to));
    const std::string ex =
        writeTemp("bad_extrinsics.yml", c.in_extrinsics ? replaced(kExtrinsicsYml, c.from, c.to) : kExtrinsicsYml);
    ImportedCalibration got;
    std::string error;
    EXPECT_FALSE(importOpenCvStereo({in, ex}, cv::Size(640, 480), &got, &error)) << c.message;
    // A missing key names every file it was looked for in.
    EXPECT_TRUE(has(error, c.message) && has(error, c.in_extrinsics ? ex : in))
        << "expected '" << c.message << "', got: " << error;
  }
}

// The round trip without opencv-doc: a rig with the rational model (8 coefficients) through the two formats
// that carry it, and with plumb_bob through all three.
TEST(CalibImportRoundTrip, EachFormatGivesBackARationalAndAPlumbBobRig) {
  StereoCalibration rig;
  rig.image_size = cv::Size(1280, 1024);
  rig.left.K = cv::Matx33d(1402.5, 0, 651.25, 0, 1401.75, 509.5, 0, 0, 1);
  rig.right.K = cv::Matx33d(1398.0, 0, 640.5, 0, 1398.5, 515.0, 0, 0, 1);
  rig.left.dist = (cv::Mat_<double>(1, 8) << 0.41, -0.12, 0.0006, -0.0004, 0.02, 0.78, -0.05, 0.07);
  rig.right.dist = (cv::Mat_<double>(1, 8) << 0.38, -0.10, -0.0003, 0.0005, 0.01, 0.74, -0.04, 0.06);
  cv::Rodrigues(cv::Vec3d(0.004, -0.02, 0.001), rig.R);
  rig.T = cv::Vec3d(-0.30, 0.002, -0.004);
  const std::string dir = deepnav::testing::tempPath("calib_import_rt_");
  for (const bool rational : {true, false}) {
    StereoCalibration c = rig;
    if (!rational) {
      c.left.dist = (cv::Mat_<double>(1, 5) << -0.21, 0.07, 0.0006, -0.0004, 0.0);
      c.right.dist = (cv::Mat_<double>(1, 5) << -0.19, 0.06, -0.0003, 0.0005, 0.0);
    }
    std::vector<std::pair<std::string, ImportedCalibration>> got;
    std::string error;
    ImportedCalibration imported;
    test::writeOpenCvStereo(c, dir + "intrinsics.yml", dir + "extrinsics.yml");
    ASSERT_TRUE(importOpenCvStereo({dir + "intrinsics.yml", dir + "extrinsics.yml"}, c.image_size, &imported, &error))
        << error;
    got.emplace_back("opencv", imported);
    test::writeCameraInfoPair(c, dir + "left.yaml", dir + "right.yaml");
    ASSERT_TRUE(importCameraInfoPair(dir + "left.yaml", dir + "right.yaml", &imported, &error)) << error;
    got.emplace_back("camera-info", imported);
    if (!rational) {
      test::writeKalibrCamchain(c, dir + "camchain.yaml");
      ASSERT_TRUE(importKalibrCamchain(dir + "camchain.yaml", &imported, &error)) << error;
      got.emplace_back("kalibr", imported);
    }
    for (const auto& [format, g] : got) {
      const StereoCalibration& e = g.calibration;
      EXPECT_EQ(e.image_size, c.image_size) << format;
      EXPECT_EQ(cv::norm(cv::Mat(e.left.K), cv::Mat(c.left.K), cv::NORM_INF), 0.0) << format;
      EXPECT_EQ(cv::norm(cv::Mat(e.right.K), cv::Mat(c.right.K), cv::NORM_INF), 0.0) << format;
      EXPECT_EQ(cv::norm(e.left.dist, c.left.dist, cv::NORM_INF), 0.0) << format;
      EXPECT_EQ(cv::norm(e.right.dist, c.right.dist, cv::NORM_INF), 0.0) << format;
      // camera_info's R and T are products of the rectifying rotations: rounding of a few 1e-15.
      EXPECT_LT(cv::norm(cv::Mat(e.R), cv::Mat(c.R), cv::NORM_INF), 1e-12) << format;
      EXPECT_LT(cv::norm(cv::Mat(e.T), cv::Mat(c.T), cv::NORM_INF), 1e-12) << format;
    }
  }
}

TEST(CalibImportCommand, WritesTheCalibrationFileItPrints) {
  ImportCalibrationOptions o;
  o.format = "kalibr";
  o.inputs = {writeTemp("cmd_camchain.yaml", kEurocCamchain)};
  o.out_path = deepnav::testing::tempPath("calib_import_out.yaml");
  ::testing::internal::CaptureStdout();
  const int rc = runImportCalibrationCommand(o);
  std::fflush(stdout);
  const std::string printed = ::testing::internal::GetCapturedStdout();
  std::printf("%s", printed.c_str());
  ASSERT_EQ(rc, 0);
  EXPECT_TRUE(has(printed, "resolution 752 x 480 px")) << printed;
  EXPECT_TRUE(has(printed, "left  fx 458.654 fy 457.296 cx 367.215 cy 248.375 px")) << printed;
  EXPECT_TRUE(has(printed, "baseline 0.1101 m")) << printed;
  StereoCalibration read, imported;
  std::string error;
  ASSERT_TRUE(readStereoCalibrationFile(o.out_path, &read, &error)) << error;
  ImportedCalibration direct;
  ASSERT_TRUE(importKalibrCamchain(o.inputs[0], &direct, &error)) << error;
  EXPECT_EQ(cv::norm(cv::Mat(read.left.K), cv::Mat(direct.calibration.left.K), cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(read.right.dist, direct.calibration.right.dist, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(cv::Mat(read.R), cv::Mat(direct.calibration.R), cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(cv::Mat(read.T), cv::Mat(direct.calibration.T), cv::NORM_INF), 0.0);
  // A wrong number of files is refused with the format's expectation.
  o.format = "camera-info";
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(runImportCalibrationCommand(o), 2);
  EXPECT_TRUE(has(::testing::internal::GetCapturedStderr(), "--format camera-info takes two files"));
}

}  // namespace
}  // namespace deepnav
