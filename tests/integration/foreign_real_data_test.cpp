// Real stereo and IMU data through the foreign readers: the start of EuRoC V1_01 (../shared/data/
// euroc-v101-micro: 752x480 stereo at 20 Hz, ADIS16448 at 200 Hz, the rig still on the floor) imported as
// a deepnav recording, then written as a ROS 2 MCAP and as a ROS 1 bag the way the dataset's own bags
// carry it (/imu0 in the IMU's body frame B: x up, y right, z forward; /cam0, /cam1 image_raw mono8),
// replayed with a topic map whose mounting turns B into the robot frame. The three paths give the same
// trajectory. Skipped when the data is absent.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "board/cli/import_euroc_command.h"
#include "board/replay/bench_replay.h"
#include "drivers/replay/recording_reader.h"
#include "tests/support/foreign_mcap_writer.h"
#include "tests/support/ros1_bag_writer.h"

namespace deepnav {
namespace {

namespace fs = std::filesystem;

fs::path sharedDataDir() {
  if (const char* env = std::getenv("DEEPNAV_SHARED_DATA")) return env;
  return fs::path(DEEPNAV_SOURCE_DIR) / ".." / "shared" / "data";
}

const std::string kBoard = std::string(DEEPNAV_SOURCE_DIR) + "/board/euroc/board.yaml";
constexpr TimeUs kOffsetUs = 1'000'000'000;  // ROS stamps are never 0; a multiple of the 5 ms tick

// R_robot_body of the EuRoC body frame (x up, y right, z forward) in FLU: [0 0 1; 0 -1 0; 1 0 0], i.e.
// [roll, pitch, yaw] = [180, -90, 0] deg (ZYX: Ry(-90) Rx(180)).
const Eigen::Matrix3d& robotFromBody() {
  static const Eigen::Matrix3d R = (Eigen::Matrix3d() << 0, 0, 1, 0, -1, 0, 1, 0, 0).finished();
  return R;
}

const char* kMap =
    "# EuRoC V1_01 as its ROS bags carry it.\n"
    "stereo:\n"
    "  pair_tolerance_ms: 1\n"
    "topics:\n"
    "  /imu0: {sensor: imu, rotation_deg: [180, -90, 0]}   # body x up, y right, z forward\n"
    "  /cam0/image_raw: {sensor: camera_left}\n"
    "  /cam1/image_raw: {sensor: camera_right}\n";

ros::Header headerAt(TimeUs t_us, const char* frame) {
  ros::Header h;
  const TimeUs t = t_us + kOffsetUs;
  h.stamp.sec = static_cast<std::int32_t>(t / 1'000'000);
  h.stamp.nanosec = static_cast<std::uint32_t>((t % 1'000'000) * 1000);
  h.frame_id = frame;
  return h;
}

ros::Image monoImage(TimeUs t_us, const cv::Mat& m, const char* frame) {
  ros::Image img;
  img.header = headerAt(t_us, frame);
  img.width = static_cast<std::uint32_t>(m.cols);
  img.height = static_cast<std::uint32_t>(m.rows);
  img.encoding = "mono8";
  img.step = img.width;
  const cv::Mat c = m.isContinuous() ? m : m.clone();
  img.data.assign(c.data, c.data + c.total());
  return img;
}

template <typename Writer>
void writeDataset(const std::string& recording, Writer& w) {
  RecordingReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(recording, &error)) << error;
  ASSERT_TRUE(reader.forEach(true, [&](const ReplayEvent& e) {
    const std::int64_t log_ns = (e.t_us + kOffsetUs) * 1000;
    if (e.kind == ReplayEvent::Kind::kFrame) {
      w.write("/cam0/image_raw", monoImage(e.frame->t_us, e.frame->left, "cam0"), log_ns);
      w.write("/cam1/image_raw", monoImage(e.frame->t_us, e.frame->right, "cam1"), log_ns);
    } else if (e.kind == ReplayEvent::Kind::kInput) {
      const auto& s = std::get<ImuSample>(e.input);
      ros::Imu m;
      m.header = headerAt(s.t_us, "imu4");
      m.orientation_covariance[0] = -1.0;
      const Eigen::Vector3d w_body = robotFromBody().transpose() * s.w_imu_radps;
      const Eigen::Vector3d f_body = robotFromBody().transpose() * s.f_imu_mps2;
      m.angular_velocity = {w_body.x(), w_body.y(), w_body.z()};
      m.linear_acceleration = {f_body.x(), f_body.y(), f_body.z()};
      w.write("/imu0", m, log_ns);
    }
    return true;
  }, &error)) << error;
}

ReplaySummary replay(const std::string& input, const std::string& out, const std::string& topics) {
  ReplayOptions o;
  o.input_path = input;
  o.out_dir = out;
  o.topics_path = topics;
  o.board_path = kBoard;
  o.progress = false;
  ReplaySummary s;
  std::string error;
  EXPECT_TRUE(runBenchReplay(o, &s, &error)) << error;
  return s;
}

double largestDifference_m(const ReplaySummary& a, const ReplaySummary& b) {
  EXPECT_EQ(a.estimate.size(), b.estimate.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(a.estimate.size(), b.estimate.size()); ++i) {
    EXPECT_NEAR(a.estimate[i].t_s + 1000.0, b.estimate[i].t_s, 1e-6);
    worst = std::max(worst, (a.estimate[i].p_robot_in_odom_m - b.estimate[i].p_robot_in_odom_m).norm());
  }
  return worst;
}

double drift_m(const ReplaySummary& s) {
  double d = 0.0;
  for (const StampedPose& p : s.estimate) d = std::max(d, (p.p_robot_in_odom_m - s.estimate.front().p_robot_in_odom_m).norm());
  return d;
}

TEST(ForeignRealData, EurocAsRos2McapAndRos1BagGivesTheTrajectoryOfItsImport) {
  const fs::path source = sharedDataDir() / "euroc-v101-micro";
  if (!fs::exists(source / "mav0" / "cam0" / "data.csv")) GTEST_SKIP() << "no EuRoC data under " << source;
  const fs::path dir = fs::temp_directory_path() / ("deepnav_foreign_real_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  ImportEurocOptions import;
  import.dir = source.string();
  import.out_path = (dir / "v101.mcap").string();
  import.skip_missing_images = true;  // cam1/data.csv lists images past the extract's end
  import.duration_s = 4.75;           // the images' span
  import.quiet = true;
  ASSERT_EQ(runImportEurocCommand(import), 0);
  const std::string mcap = (dir / "v101_ros2.mcap").string();
  {
    testing::ForeignMcapWriter w(mcap);
    writeDataset(import.out_path, w);
    w.close();
  }
  const std::string bag = (dir / "v101_ros1.bag").string();
  {
    testsupport::Ros1BagWriter w;
    ASSERT_TRUE(w.open(bag, testsupport::Ros1BagWriter::Compression::kBz2));
    writeDataset(import.out_path, w);
    ASSERT_TRUE(w.close());
  }
  const std::string map = (dir / "map.yaml").string();
  std::ofstream(map) << kMap;

  const ReplaySummary own = replay(import.out_path, (dir / "own").string(), "");
  const ReplaySummary ros2 = replay(mcap, (dir / "ros2").string(), map);
  const ReplaySummary ros1 = replay(bag, (dir / "ros1").string(), map);
  ASSERT_GT(own.frames, 80u);
  EXPECT_EQ(ros2.frames, own.frames);
  EXPECT_EQ(ros1.frames, own.frames);
  EXPECT_EQ(ros2.inputs.imu, own.inputs.imu);
  EXPECT_EQ(ros1.inputs.imu, own.inputs.imu);
  EXPECT_EQ(ros2.inputs.vision, own.inputs.vision);
  const double ros2_m = largestDifference_m(own, ros2);
  const double ros1_m = largestDifference_m(own, ros1);
  double bag_vs_mcap_m = 0.0;
  for (std::size_t i = 0; i < std::min(ros1.estimate.size(), ros2.estimate.size()); ++i) {
    bag_vs_mcap_m = std::max(bag_vs_mcap_m, (ros1.estimate[i].p_robot_in_odom_m - ros2.estimate[i].p_robot_in_odom_m).norm());
  }
  std::printf("EuRoC V1_01 start, %zu ticks, %llu pairs, %llu vision results: drift own %.2f mm, ROS 2 %.2f mm, "
              "ROS 1 %.2f mm; largest difference to the import: ROS 2 MCAP %.3g m, ROS 1 bag %.3g m; bag vs MCAP %.3g m\n",
              own.estimate.size(), static_cast<unsigned long long>(own.frames),
              static_cast<unsigned long long>(own.inputs.vision), drift_m(own) * 1e3, drift_m(ros2) * 1e3,
              drift_m(ros1) * 1e3, ros2_m, ros1_m, bag_vs_mcap_m);
  // The same bytes through the same conversion: identical. Against the import the IMU goes through the
  // board's mounting rotation (cos 90 deg is 6e-17, not 0) instead of arriving rotated: rounding only.
  EXPECT_EQ(bag_vs_mcap_m, 0.0);
  EXPECT_LT(ros2_m, 1e-4);
  EXPECT_LT(ros1_m, 1e-4);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace deepnav
