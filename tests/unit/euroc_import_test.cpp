// EuRoC/ASL import (issue 19 item 2): the data.csv and sensor.yaml readers with their errors, the folder
// reader, the body -> FLU robot frame, the stereo calibration and mounting from T_BS, the recording the
// import writes, and the two behaviours a MAV rig needs (IMU-only alignment, marker-less stage 2).
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "board/cli/import_euroc_command.h"
#include "board/config/euroc_mounting.h"
#include "board/config/stereo_calibration_file.h"
#include "board/config/vehicle_setup.h"
#include "drivers/euroc/euroc_csv.h"
#include "drivers/euroc/euroc_dataset.h"
#include "drivers/euroc/euroc_frames.h"
#include "drivers/euroc/euroc_sensor.h"
#include "drivers/euroc/euroc_yaml.h"
#include "drivers/replay/recording_reader.h"
#include "nav/ekf/ekf.h"
#include "nav/ekf/initial_alignment.h"
#include "nav/stage/stage_machine.h"
#include "tests/support/source_paths.h"
#include "tests/support/temp_path.h"

namespace deepnav {
namespace {

namespace fs = std::filesystem;

using deepnav::testing::sharedDataDir;

// Scratch folders under the system's temp directory, removed when the binary ends.
struct ScratchDirs {
  std::vector<fs::path> dirs;
  ~ScratchDirs() {
    std::error_code ec;
    for (const fs::path& d : dirs) fs::remove_all(d, ec);
  }
};

fs::path scratchDir(const std::string& name) {
  static ScratchDirs scratch;
  const fs::path dir = fs::path(deepnav::testing::tempPath("euroc_" + name));
  fs::remove_all(dir);
  fs::create_directories(dir);
  scratch.dirs.push_back(dir);
  return dir;
}

void writeText(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

// A camera sensor.yaml in the EuRoC dialect with the given T_BS rows and cu.
std::string cameraYaml(const std::string& t_bs_data, double cu = 8.0) {
  return "%YAML:1.0\n# General sensor definitions.\nsensor_type: camera\ncomment: test\n\nT_BS:\n  cols: 4\n  rows: 4\n"
         "  data: [" + t_bs_data + "]\n\nrate_hz: 20\nresolution: [64, 48]\ncamera_model: pinhole\n"
         "intrinsics: [20.0, 21.0, " + std::to_string(cu) + ", 6.0] #fu, fv, cu, cv\n"
         "distortion_model: radial-tangential\ndistortion_coefficients: [-0.28, 0.07, 0.0002, 0.00002]\n";
}

// cam0 looking along z_B (its x right = y_B, its y down = -x_B), cam1 0.11 m along +y_B from cam0.
const char* kCam0 = "0, -1, 0, 0.01,\n         1, 0, 0, 0.02,\n         0, 0, 1, 0.03,\n         0, 0, 0, 1";

std::string cam1Yaml() {
  return cameraYaml("0, -1, 0, 0.01,\n 1, 0, 0, 0.13,\n 0, 0, 1, 0.03,\n 0, 0, 0, 1");
}

const char* kImuYaml =
    "%YAML:1.0\nsensor_type: imu\nT_BS:\n  cols: 4\n  rows: 4\n  data: [1.0, 0.0, 0.0, 0.0,\n 0.0, 1.0, 0.0, 0.0,\n"
    " 0.0, 0.0, 1.0, 0.0,\n 0.0, 0.0, 0.0, 1.0]\nrate_hz: 200\ngyroscope_noise_density: 1.6968e-04\n"
    "gyroscope_random_walk: 1.9393e-05\naccelerometer_noise_density: 2.0000e-3\naccelerometer_random_walk: 3.0000e-3\n";

// A small EuRoC folder: 3 stereo pairs 50 ms apart (cam1 has one extra image without a twin), 21 IMU
// samples at 200 Hz from the first pair on, 2 ground-truth rows.
fs::path makeFolder(const std::string& name) {
  const fs::path root = scratchDir(name);
  const fs::path mav = root / "mav0";
  writeText(mav / "cam0" / "sensor.yaml", cameraYaml(kCam0));
  writeText(mav / "cam1" / "sensor.yaml", cam1Yaml());
  writeText(mav / "imu0" / "sensor.yaml", kImuYaml);
  const std::int64_t t0 = 1403715273262142976;
  const auto png = [&](const char* cam, std::int64_t t_ns, int grey) {
    fs::create_directories(mav / cam / "data");
    cv::imwrite((mav / cam / "data" / (std::to_string(t_ns) + ".png")).string(), cv::Mat(48, 64, CV_8UC1, cv::Scalar(grey)));
    return std::to_string(t_ns) + "," + std::to_string(t_ns) + ".png\n";
  };
  std::string cam0 = "#timestamp [ns],filename\n", cam1 = cam0;
  for (int k = 0; k < 3; ++k) {
    cam0 += png("cam0", t0 + k * 50'000'000LL, 10 * k);
    cam1 += png("cam1", t0 + k * 50'000'000LL, 10 * k + 5);
    if (k == 0) cam1 += png("cam1", t0 + 25'000'000LL, 1);  // no twin in cam0
  }
  writeText(mav / "cam0" / "data.csv", cam0);
  writeText(mav / "cam1" / "data.csv", cam1);
  std::string imu = "#timestamp [ns],w_RS_S_x [rad s^-1],w_RS_S_y,w_RS_S_z,a_RS_S_x,a_RS_S_y,a_RS_S_z\n";
  for (int k = 0; k <= 20; ++k) {
    imu += std::to_string(t0 + k * 5'000'000LL) + ",0.01,0.02,0.08,9.08,0.13,-3.69\n";
  }
  writeText(mav / "imu0" / "data.csv", imu);
  writeText(mav / "state_groundtruth_estimate0" / "data.csv",
            "#timestamp,p_x,p_y,p_z,q_w,q_x,q_y,q_z,v_x,v_y,v_z,bw_x,bw_y,bw_z,ba_x,ba_y,ba_z\n" +
                std::to_string(t0) + ",1,2,3,1,0,0,0,0,0,0,-0.002,0.02,0.077,-0.01,0.1,0.05\n" +
                std::to_string(t0 + 50'000'000LL) + ",1,2,3,1,0,0,0,0,0,0,-0.002,0.02,0.077,-0.01,0.1,0.05\n");
  return root;
}

TEST(EurocCsv, UnsortedTimestampsAreRefusedNamingFileAndLine) {
  const fs::path dir = scratchDir("csv");
  writeText(dir / "data.csv", "#timestamp [ns],filename\n200,a.png\n100,b.png\n");
  std::vector<EurocCsvRow> rows;
  std::string error;
  EXPECT_FALSE(readEurocCsv((dir / "data.csv").string(), 2, &rows, &error));
  EXPECT_NE(error.find("data.csv:3:"), std::string::npos) << error;
  EXPECT_NE(error.find("line 2"), std::string::npos) << error;
}

TEST(EurocCsv, WrongColumnsBadTimestampAndBadNumberNameTheLine) {
  const fs::path dir = scratchDir("csv2");
  std::vector<EurocCsvRow> rows;
  std::string error;
  writeText(dir / "a.csv", "#t,f\n100,a.png,extra\n");
  EXPECT_FALSE(readEurocCsv((dir / "a.csv").string(), 2, &rows, &error));
  EXPECT_NE(error.find("a.csv:2: 3 columns, expected 2"), std::string::npos) << error;
  writeText(dir / "b.csv", "#t,f\n\n1e9,a.png\n");
  EXPECT_FALSE(readEurocCsv((dir / "b.csv").string(), 2, &rows, &error));
  EXPECT_NE(error.find("b.csv:3: timestamp '1e9'"), std::string::npos) << error;
  writeText(dir / "c.csv", "#t,wx,wy,wz,ax,ay,az\n100,0,0,0,9.8,x,0\n");
  std::vector<EurocImuRow> imu;
  EXPECT_FALSE(readEurocImu((dir / "c.csv").string(), &imu, &error));
  EXPECT_NE(error.find("c.csv:2: column 6 'x'"), std::string::npos) << error;
  EXPECT_FALSE(readEurocImu((dir / "missing.csv").string(), &imu, &error));
  EXPECT_NE(error.find("missing.csv: cannot open"), std::string::npos) << error;
}

TEST(EurocYaml, MalformedSensorYamlNamesFileLineAndKey) {
  EurocYaml y;
  std::string error;
  // A list never closed: the line where it starts.
  EXPECT_FALSE(y.parse("%YAML:1.0\nsensor_type: camera\nintrinsics: [1, 2,\n  3\n", "s.yaml", &error));
  EXPECT_NE(error.find("s.yaml:3: key 'intrinsics'"), std::string::npos) << error;
  // A line that is no key: value.
  EXPECT_FALSE(y.parse("%YAML:1.0\nsensor_type camera\n", "s.yaml", &error));
  EXPECT_NE(error.find("s.yaml:2:"), std::string::npos) << error;
  // A repeated key.
  EXPECT_FALSE(y.parse("rate_hz: 20\nrate_hz: 30\n", "s.yaml", &error));
  EXPECT_NE(error.find("s.yaml:2: key 'rate_hz' repeated (first on line 1)"), std::string::npos) << error;
  // Typed reads: a list of the wrong length, a missing key.
  ASSERT_TRUE(y.parse("resolution: [752, 480, 1] # w h\nT_BS:\n  rows: 4\n", "s.yaml", &error)) << error;
  std::vector<double> v;
  EXPECT_FALSE(y.numbers("resolution", 2, &v, &error));
  EXPECT_NE(error.find("s.yaml:1: key 'resolution' has 3 numbers, expected 2"), std::string::npos) << error;
  double rows = 0.0;
  EXPECT_TRUE(y.number("T_BS.rows", &rows, &error));
  EXPECT_EQ(rows, 4.0);
  EXPECT_FALSE(y.number("T_BS.cols", &rows, &error));
  EXPECT_NE(error.find("s.yaml: key 'T_BS.cols' missing"), std::string::npos) << error;
}

TEST(EurocSensor, NonRigidTransformAndUnsupportedModelAreRefused) {
  const fs::path dir = scratchDir("sensor");
  EurocCamera cam;
  std::string error;
  writeText(dir / "a.yaml", cameraYaml("2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1"));
  EXPECT_FALSE(readEurocCamera((dir / "a.yaml").string(), &cam, &error));
  EXPECT_NE(error.find("key 'T_BS.data' is not a rigid transform"), std::string::npos) << error;
  std::string text = cameraYaml(kCam0);
  text.replace(text.find("radial-tangential"), 17, "equidistant");
  writeText(dir / "b.yaml", text);
  EXPECT_FALSE(readEurocCamera((dir / "b.yaml").string(), &cam, &error));
  EXPECT_NE(error.find("key 'distortion_model' is 'equidistant'"), std::string::npos) << error;
  writeText(dir / "c.yaml", cameraYaml(kCam0));
  ASSERT_TRUE(readEurocCamera((dir / "c.yaml").string(), &cam, &error)) << error;
  EXPECT_EQ(cam.width_px, 64);
  EXPECT_EQ(cam.height_px, 48);
  EXPECT_DOUBLE_EQ(cam.intrinsics[1], 21.0);
  EXPECT_DOUBLE_EQ(cam.distortion[3], 0.00002);
}

TEST(EurocSensor, ReadsTheRealV101SensorFiles) {
  const fs::path mav = sharedDataDir() / "euroc-v101-micro" / "mav0";
  if (!fs::exists(mav / "cam0" / "sensor.yaml")) GTEST_SKIP() << "no EuRoC data at " << mav;
  EurocCamera cam0, cam1;
  EurocImuInfo imu;
  std::string error;
  ASSERT_TRUE(readEurocCamera((mav / "cam0" / "sensor.yaml").string(), &cam0, &error)) << error;
  ASSERT_TRUE(readEurocCamera((mav / "cam1" / "sensor.yaml").string(), &cam1, &error)) << error;
  ASSERT_TRUE(readEurocImuInfo((mav / "imu0" / "sensor.yaml").string(), &imu, &error)) << error;
  EXPECT_EQ(cam0.width_px, 752);
  EXPECT_EQ(cam0.height_px, 480);
  EXPECT_DOUBLE_EQ(cam0.intrinsics[0], 458.654);
  EXPECT_DOUBLE_EQ(cam1.distortion[0], -0.28368365);
  EXPECT_DOUBLE_EQ(imu.rate_hz, 200.0);
  EXPECT_TRUE(imu.T_body_sensor.isApprox(Eigen::Isometry3d::Identity()));
  // The VI-Sensor's baseline is 11 cm, the right camera along +x of the left.
  const EurocMounting m = eurocMounting(cam0, cam1, imu);
  EXPECT_NEAR(m.baseline_m, 0.110, 0.001);
  EXPECT_LT(m.calibration.T[0], -0.109);
  // cam0 looks forward within 2 degrees in the FLU robot frame.
  EXPECT_LT(m.camera_rotation_deg.cwiseAbs().maxCoeff(), 2.0);
}

TEST(EurocFrames, BodyToRobotIsARotationAndGravityPointsUp) {
  const Eigen::Matrix3d R = eurocRobotFromBody();
  EXPECT_NEAR(R.determinant(), 1.0, 1e-15);
  EXPECT_TRUE((R * R.transpose()).isApprox(Eigen::Matrix3d::Identity()));
  // The first V1_01 sample at rest: 9.09 m/s2 along x_B becomes up (+z of FLU), forward = z_B.
  EurocImuRow row;
  row.t_ns = 2'000'000'600;
  row.f_sensor_mps2 = Eigen::Vector3d(9.0874956666666655, 0.13075533333333333, -3.6938381666666662);
  row.w_sensor_radps = Eigen::Vector3d(-0.002, 0.0175, 0.0775);
  const ImuSample s = eurocImuSample(row, Eigen::Matrix3d::Identity(), 1'000'000'000);
  EXPECT_EQ(s.t_us, 1'000'001);  // rounded to the microsecond
  EXPECT_DOUBLE_EQ(s.f_imu_mps2.z(), row.f_sensor_mps2.x());
  EXPECT_DOUBLE_EQ(s.f_imu_mps2.y(), -row.f_sensor_mps2.y());
  EXPECT_DOUBLE_EQ(s.f_imu_mps2.x(), row.f_sensor_mps2.z());
  EXPECT_DOUBLE_EQ(s.w_imu_radps.z(), -0.002);
  EXPECT_NEAR(s.f_imu_mps2.norm(), 9.81, 0.01);
}

TEST(EurocMounting, CalibrationMapsLeftPointsToRightAndMountingRoundTrips) {
  EurocCamera cam0, cam1;
  EurocImuInfo imu;
  // cam1 rotated 2 degrees about its y and 0.11 m to the right of cam0, cam0 tilted and offset.
  cam0.T_body_sensor.linear() = (Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.2, 0.9, 0.1).normalized())).toRotationMatrix();
  cam0.T_body_sensor.translation() = Eigen::Vector3d(0.01, -0.06, 0.02);
  cam1.T_body_sensor = cam0.T_body_sensor * Eigen::Translation3d(0.11, 0.0, 0.0) * Eigen::AngleAxisd(0.035, Eigen::Vector3d::UnitY());
  cam0.width_px = cam1.width_px = 752;
  cam0.height_px = cam1.height_px = 480;
  cam0.intrinsics = {458.0, 457.0, 367.0, 248.0};
  cam1.intrinsics = {457.0, 456.0, 380.0, 255.0};
  const EurocMounting m = eurocMounting(cam0, cam1, imu);
  // p_in_right = R p_in_left + T for a point seen by both.
  const Eigen::Vector3d p_left(0.3, -0.2, 2.5);
  const Eigen::Vector3d p_right = cam1.T_body_sensor.inverse() * (cam0.T_body_sensor * p_left);
  cv::Vec3d q = m.calibration.R * cv::Vec3d(p_left.x(), p_left.y(), p_left.z()) + m.calibration.T;
  EXPECT_NEAR(q[0], p_right.x(), 1e-12);
  EXPECT_NEAR(q[1], p_right.y(), 1e-12);
  EXPECT_NEAR(q[2], p_right.z(), 1e-12);
  EXPECT_NEAR(m.baseline_m, 0.11, 1e-12);
  EXPECT_EQ(m.calibration.left.K(0, 2), 367.0);
  // The board's camera.rotation_deg and p_cam_in_robot_m give back cam0's pose in the robot frame.
  BoardConfig board = defaultBoardConfig();
  const Eigen::Vector3d rad = m.camera_rotation_deg * (M_PI / 180.0);
  board.camera.q_robot_body = Eigen::AngleAxisd(rad.z(), Eigen::Vector3d::UnitZ()) *
                              Eigen::AngleAxisd(rad.y(), Eigen::Vector3d::UnitY()) *
                              Eigen::AngleAxisd(rad.x(), Eigen::Vector3d::UnitX());
  board.camera.p_cam_in_robot_m = m.p_cam_in_robot_m;
  const Eigen::Isometry3d T_robot_cam = robotFromCamera(board);
  Eigen::Isometry3d expected = Eigen::Isometry3d::Identity();
  expected.linear() = eurocRobotFromBody() * cam0.T_body_sensor.linear();
  expected.translation() = eurocRobotFromBody() * cam0.T_body_sensor.translation();
  EXPECT_TRUE(T_robot_cam.isApprox(expected, 1e-12));
}

TEST(EurocDataset, PairsByTimestampAndReadsImuAndTruth) {
  const fs::path root = makeFolder("folder");
  EurocDataset d;
  std::string error;
  ASSERT_TRUE(readEurocDataset(root.string(), EurocReadOptions{}, &d, &error)) << error;
  EXPECT_EQ(d.pairs.size(), 3u);
  EXPECT_EQ(d.cam0_unpaired, 0);
  EXPECT_EQ(d.cam1_unpaired, 1);
  EXPECT_EQ(d.imu_rows.size(), 21u);
  ASSERT_EQ(d.truth.size(), 2u);
  EXPECT_DOUBLE_EQ(d.truth[0].b_gyro_radps.z(), 0.077);
  // The mav0 folder itself is accepted too; --duration keeps the first 0.05 s.
  EurocReadOptions o;
  o.duration_s = 0.05;
  ASSERT_TRUE(readEurocDataset((root / "mav0").string(), o, &d, &error)) << error;
  EXPECT_EQ(d.pairs.size(), 2u);
  EXPECT_EQ(d.imu_rows.size(), 11u);
}

TEST(EurocDataset, MissingFrameFileAndMissingDataCsvAreNamed) {
  const fs::path root = makeFolder("missing");
  const fs::path mav = root / "mav0";
  fs::remove(mav / "cam0" / "data" / "1403715273312142976.png");
  EurocDataset d;
  std::string error;
  EXPECT_FALSE(readEurocDataset(root.string(), EurocReadOptions{}, &d, &error));
  EXPECT_NE(error.find("cam0/data.csv:3: image file"), std::string::npos) << error;
  EXPECT_NE(error.find("1403715273312142976.png is missing"), std::string::npos) << error;
  // Skipped on request, and counted: the pair is gone.
  EurocReadOptions o;
  o.skip_missing_images = true;
  ASSERT_TRUE(readEurocDataset(root.string(), o, &d, &error)) << error;
  EXPECT_EQ(d.cam0_missing, 1);
  EXPECT_EQ(d.pairs.size(), 2u);
  fs::remove(mav / "imu0" / "data.csv");
  EXPECT_FALSE(readEurocDataset(root.string(), o, &d, &error));
  EXPECT_NE(error.find("imu0/data.csv: cannot open"), std::string::npos) << error;
  EXPECT_FALSE(readEurocDataset(mav.string() + "/cam0", o, &d, &error));
  EXPECT_NE(error.find("not an EuRoC/ASL folder"), std::string::npos) << error;
}

TEST(EurocImport, RecordingHoldsPairsRotatedImuTruthAndCalibration) {
  const fs::path root = makeFolder("import");
  ImportEurocOptions o;
  o.dir = root.string();
  o.out_path = (root / "rec.mcap").string();
  o.calibration_out = (root / "calib.yaml").string();
  o.quiet = true;
  ASSERT_EQ(runImportEurocCommand(o), 0);
  StereoCalibration calib;
  std::string error;
  ASSERT_TRUE(readStereoCalibrationFile(o.calibration_out, &calib, &error)) << error;
  EXPECT_NEAR(calib.T[0], -0.11, 1e-12);
  RecordingReader reader;
  ASSERT_TRUE(reader.open(o.out_path, &error)) << error;
  ASSERT_NE(reader.metadata(kCalibrationMetadata), nullptr);
  EXPECT_EQ(reader.metadata(kCalibrationMetadata)->at("yaml"), stereoCalibrationText(calib, {0.0, 0, "EuRoC sensor.yaml (T_BS, pinhole, radial-tangential)"}));
  ASSERT_NE(reader.metadata("deepnav.euroc"), nullptr);
  EXPECT_EQ(reader.metadata("deepnav.euroc")->at("t0_ns"), "1403715273262142976");
  int imu = 0, frames = 0, truth = 0;
  TimeUs last_us = -1;
  ASSERT_TRUE(reader.forEach(true, [&](const ReplayEvent& e) {
    EXPECT_GE(e.t_us, last_us);
    last_us = e.t_us;
    if (e.kind == ReplayEvent::Kind::kInput) {
      const auto& s = std::get<ImuSample>(e.input);
      EXPECT_EQ(s.t_us, imu * 5000);
      EXPECT_DOUBLE_EQ(s.f_imu_mps2.z(), 9.08);  // up = x_B
      EXPECT_DOUBLE_EQ(s.w_imu_radps.y(), -0.02);
      ++imu;
    } else if (e.kind == ReplayEvent::Kind::kFrame) {
      EXPECT_EQ(e.frame->t_us, frames * 50'000);
      EXPECT_EQ(e.frame->left.at<std::uint8_t>(0, 0), 10 * frames);
      EXPECT_EQ(e.frame->right.at<std::uint8_t>(0, 0), 10 * frames + 5);
      EXPECT_FALSE(e.frame->rectified);
      ++frames;
    } else if (e.kind == ReplayEvent::Kind::kTruth) {
      EXPECT_DOUBLE_EQ(e.truth.p_robot_in_odom_m.y(), 2.0);
      // Robot forward (x_R) = z_B, which is world z with the identity body attitude.
      EXPECT_TRUE((e.truth.q_odom_robot * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitZ()));
      ++truth;
    }
    return true;
  }, &error)) << error;
  EXPECT_EQ(imu, 21);
  EXPECT_EQ(frames, 3);
  EXPECT_EQ(truth, 2);
}

TEST(EurocImport, ABoardGoesIntoTheRecordingAndMustMatchTheImages) {
  const fs::path root = makeFolder("board");
  ImportEurocOptions o;
  o.dir = root.string();
  o.out_path = (root / "rec.mcap").string();
  o.calibration_out = (root / "calib.yaml").string();
  o.quiet = true;
  ASSERT_EQ(runImportEurocCommand(o), 0);  // writes the calibration the board names
  writeText(root / "board.yaml", "camera:\n  width_px: 64\n  height_px: 48\n  calibration_file: calib.yaml\nvision:\n  dense_disparities: 16\n");
  o.board_path = (root / "board.yaml").string();
  o.out_path = (root / "with_board.mcap").string();
  ASSERT_EQ(runImportEurocCommand(o), 0);
  RecordingReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(o.out_path, &error)) << error;
  ASSERT_NE(reader.metadata("deepnav.board"), nullptr);
  VehicleSetup stored;
  bool found = false;
  ASSERT_TRUE(setupFromMetadata(reader.metadata("deepnav.board"), reader.metadata("deepnav.panel"), "stored", &stored,
                                &error, &found, reader.metadata(kCalibrationMetadata)))
      << error;
  EXPECT_TRUE(found);
  EXPECT_TRUE(stored.rectify);
  // A board for other images is refused, naming its keys (with calibration_file the board's own loader
  // refuses it first: the calibration is for 64 x 48).
  writeText(root / "board.yaml", "camera:\n  width_px: 752\n  height_px: 480\n");
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(runImportEurocCommand(o), 1);
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("camera.width_px/height_px/channels are 752x480x1"), std::string::npos) << err;
}

TEST(EurocImport, BadInputFailsWithExitCodeOneAndNoRecording) {
  const fs::path root = makeFolder("bad");
  writeText(root / "mav0" / "cam1" / "sensor.yaml", "%YAML:1.0\nsensor_type: camera\nT_BS:\n  cols: 4\n");
  ImportEurocOptions o;
  o.dir = root.string();
  o.out_path = (root / "rec.mcap").string();
  o.quiet = true;
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(runImportEurocCommand(o), 1);
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("cam1/sensor.yaml"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(o.out_path));
}

TEST(EurocAlignment, ImuOnlyAlignmentIsOffByDefaultAndTakesTheRestingGyroBias) {
  ImuSample s;
  s.f_imu_mps2 = Eigen::Vector3d(-3.69, -0.13, 9.08);
  s.w_imu_radps = Eigen::Vector3d(0.0775, -0.0175, -0.002);
  EkfConfig c;
  c.align_imu_samples = 10;
  Ekf plain;
  ASSERT_TRUE(plain.init(c, nullptr));
  c.align_imu_only = true;
  c.align_gyro_bias_at_rest = true;
  Ekf mav;
  ASSERT_TRUE(mav.init(c, nullptr));
  for (int k = 1; k <= 10; ++k) {
    s.t_us = k * 5000;
    plain.setImu(s);
    mav.setImu(s);
  }
  // The default waits for a compass and a depth sensor; the MAV's aligns, pitched up 22 degrees.
  EXPECT_FALSE(plain.aligned());
  ASSERT_TRUE(mav.aligned());
  EXPECT_TRUE(mav.state().x.b_gyro_radps.isApprox(s.w_imu_radps, 1e-12));
  EXPECT_NEAR(mav.state().x.p_robot_in_odom_m.norm(), 0.0, 1e-12);
  const Eigen::Matrix3d R = mav.state().x.q_odom_robot.toRotationMatrix();
  EXPECT_NEAR(-std::asin(R(2, 0)), std::atan2(3.69, std::hypot(0.13, 9.08)), 1e-9);
}

TEST(EurocStage, StageTwoWithoutPanelIsOffByDefault) {
  StageInputs in;
  in.filter_aligned = true;
  in.has_panel = false;
  StageMachine plain, marker_less;
  StageConfig c;
  ASSERT_TRUE(plain.init(c, nullptr));
  c.stage2_without_panel = true;
  ASSERT_TRUE(marker_less.init(c, nullptr));
  for (TimeUs t = 0; t <= 60'000'000; t += 1'000'000) {
    plain.update(t, in);
    marker_less.update(t, in);
  }
  EXPECT_EQ(plain.stage(), NavStage::kWorkspace);
  EXPECT_EQ(marker_less.stage(), NavStage::kOptimised);
  // With a panel the flag changes nothing: stage 2 still needs the panel fixed and the map.
  in.has_panel = true;
  StageMachine with_panel;
  ASSERT_TRUE(with_panel.init(c, nullptr));
  for (TimeUs t = 0; t <= 60'000'000; t += 1'000'000) with_panel.update(t, in);
  EXPECT_EQ(with_panel.stage(), NavStage::kWorkspace);
  in.filter_aligned = false;
  EXPECT_EQ(marker_less.update(61'000'000, in), NavStage::kInit);
}

}  // namespace
}  // namespace deepnav
