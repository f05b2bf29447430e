// `deepnav replay --topics` end to end: a simulated dive (IMU, AHRS, compass, DVL, depth, rendered stereo)
// rewritten as a ROS 2 MCAP the way other drivers publish it (NED/FRD IMU and DVL, AHRS orientation as
// sensor_msgs/Imu, pressure in Pa, raw left images and PNG right images), replayed through a topic map:
// the loop and vision give the trajectory of the original recording, and the output recording replays
// bit for bit with a plain `deepnav replay`.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <opencv2/imgcodecs.hpp>

#include "board/config/vehicle_setup.h"
#include "board/replay/bench_replay.h"
#include "drivers/foreign/frame_conventions.h"
#include "drivers/replay/recording_reader.h"
#include "tests/support/foreign_mcap_writer.h"
#include "tests/support/ros1_bag_writer.h"
#include "tests/support/temp_path.h"
#include "tests/support/test_dive.h"
#include "tests/support/source_paths.h"
#include "tests/support/test_replay.h"

namespace deepnav {
namespace {

constexpr TimeUs kOffsetUs = 1'000'000'000;  // 1000 s: ROS stamps are never 0; a multiple of the tick period
constexpr double kRhoG = 1025.0 * 9.80665;   // the map's depth model (its defaults)
const std::string kBoard = deepnav::testing::sourceDir() + "/board/sim/board.yaml";

ros::Header headerAt(TimeUs t_us) {
  ros::Header h;
  const TimeUs t = t_us + kOffsetUs;
  h.stamp.sec = static_cast<std::int32_t>(t / 1'000'000);
  h.stamp.nanosec = static_cast<std::uint32_t>((t % 1'000'000) * 1000);
  return h;
}

ros::Quaternion rosQuaternion(const Eigen::Quaterniond& q) { return {q.x(), q.y(), q.z(), q.w()}; }
ros::Vector3 rosVector(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

const Eigen::Matrix3d& frd() { return foreign::rotationFluFromFrd(); }  // its own inverse

// The inverse of the input boundary's conversion: q_ned_frd = R_ned_enu q_enu_flu R_flu_frd.
Eigen::Quaterniond toNedFrd(const Eigen::Quaterniond& q_enu_flu) {
  return Eigen::Quaterniond(foreign::rotationEnuFromNed().transpose()) * q_enu_flu * Eigen::Quaterniond(frd());
}

struct Written {
  int imu = 0, attitude = 0, heading = 0, dvl = 0, dvl_invalid = 0, depth = 0, frames = 0;
};

// The dive as foreign drivers would have published it, through a writer with write(topic, msg, log_time_ns):
// a ROS 2 MCAP (testing::ForeignMcapWriter) or a ROS 1 bag (testsupport::Ros1BagWriter).
template <typename Writer>
Written writeForeign(const std::string& dive, Writer& w, const Eigen::Quaterniond& q_robot_imu) {
  RecordingReader reader;
  std::string error;
  EXPECT_TRUE(reader.open(dive, &error)) << error;
  Written n;
  reader.forEach(true, [&](const ReplayEvent& e) {
    const std::int64_t log_ns = (e.t_us + kOffsetUs) * 1000;
    if (e.kind == ReplayEvent::Kind::kFrame) {
      ros::Image left;
      left.header = headerAt(e.frame->t_us);
      left.width = static_cast<std::uint32_t>(e.frame->left.cols);
      left.height = static_cast<std::uint32_t>(e.frame->left.rows);
      left.encoding = "mono8";
      left.step = left.width;
      const cv::Mat l = e.frame->left.isContinuous() ? e.frame->left : e.frame->left.clone();
      left.data.assign(l.data, l.data + l.total());
      w.write("/stereo/left/image_raw", left, log_ns);
      ros::CompressedImage right;
      right.header = headerAt(e.frame->t_us);
      right.format = "mono8; png compressed mono8";
      EXPECT_TRUE(cv::imencode(".png", e.frame->right, right.data));
      w.write("/stereo/right/image_raw/compressed", right, log_ns);
      ++n.frames;
      return true;
    }
    if (e.kind != ReplayEvent::Kind::kInput) return true;
    if (const auto* s = std::get_if<ImuSample>(&e.input)) {
      ros::Imu m;
      m.header = headerAt(s->t_us);
      m.orientation_covariance[0] = -1.0;  // a plain IMU: no orientation
      m.angular_velocity = rosVector(frd() * s->w_imu_radps);
      m.linear_acceleration = rosVector(frd() * s->f_imu_mps2);
      w.write("/imu/data_raw", m, log_ns);
      ++n.imu;
    } else if (const auto* s = std::get_if<AttitudeSample>(&e.input)) {
      // An AHRS in NED/FRD, mounted as the IMU: it reports q_odom_robot * q_robot_imu.
      const Eigen::Quaterniond q_odom_robot = Eigen::AngleAxisd(s->pitch_rad, Eigen::Vector3d::UnitY()) *
                                              Eigen::AngleAxisd(s->roll_rad, Eigen::Vector3d::UnitX());
      ros::Imu m;
      m.header = headerAt(s->t_us);
      m.orientation = rosQuaternion(toNedFrd(q_odom_robot * q_robot_imu));
      m.orientation_covariance[0] = m.orientation_covariance[4] = s->sigma_rad * s->sigma_rad;
      w.write("/ahrs/attitude", m, log_ns);
      ++n.attitude;
    } else if (const auto* s = std::get_if<HeadingSample>(&e.input)) {
      const double yaw = M_PI / 2.0 - s->heading_rad;
      ros::Imu m;
      m.header = headerAt(s->t_us);
      m.orientation = rosQuaternion(Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ())) * q_robot_imu);
      m.orientation_covariance[8] = s->sigma_rad * s->sigma_rad;
      w.write("/ahrs/heading", m, log_ns);
      ++n.heading;
    } else if (const auto* s = std::get_if<DvlSample>(&e.input)) {
      if (!s->valid) {  // a DVL driver publishes no velocity without bottom lock
        ++n.dvl_invalid;
        return true;
      }
      ros::TwistWithCovarianceStamped m;
      m.header = headerAt(s->t_us);
      m.twist.twist.linear = rosVector(frd() * s->v_dvl_mps);
      Eigen::Matrix3d C = s->cov_v_dvl_mps2;
      const double sigma = s->fom_mps;
      if (!(C.diagonal().array() > 0.0).all()) C = Eigen::Matrix3d::Identity() * (sigma * sigma);
      const Eigen::Matrix3d C_frd = frd() * C * frd().transpose();
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) m.twist.covariance[static_cast<std::size_t>(r * 6 + c)] = C_frd(r, c);
      }
      w.write("/dvl/twist", m, log_ns);
      ++n.dvl;
    } else if (const auto* s = std::get_if<DepthSample>(&e.input)) {
      ros::FluidPressure m;
      m.header = headerAt(s->t_us);
      m.fluid_pressure = 101325.0 + s->depth_m * kRhoG;
      m.variance = std::pow(s->sigma_m * kRhoG, 2);
      w.write("/pressure", m, log_ns);
      ++n.depth;
    }
    return true;
  }, &error);
  return n;
}

const char* kMap =
    "# The dive's sensors as foreign drivers publish them.\n"
    "topics:\n"
    "  /imu/data_raw: {sensor: imu, convention: ned_frd}\n"
    "  /ahrs/attitude: {sensor: attitude, convention: ned_frd}\n"
    "  /ahrs/heading: {sensor: heading, north: magnetic}\n"
    "  /dvl/twist: {sensor: dvl, convention: ned_frd}\n"
    "  /pressure: {sensor: depth}\n"
    "  /stereo/left/image_raw: {sensor: camera_left}\n"
    "  /stereo/right/image_raw/compressed: {sensor: camera_right}\n";

ReplaySummary replay(const std::string& input, const std::string& out, const std::string& topics,
                     const std::string& board) {
  ReplayOptions o;
  o.input_path = input;
  o.out_dir = out;
  o.topics_path = topics;
  o.board_path = board;
  return testing::replayOrFail(o);
}

// The converted run's estimate against the original's, tick by tick (its clock is 1000 s later).
void expectSameTrajectory(const ReplaySummary& original, const ReplaySummary& converted, const char* what) {
  ASSERT_EQ(converted.estimate.size(), original.estimate.size());
  ASSERT_FALSE(original.estimate.empty());
  double worst_m = 0.0, worst_dt_s = 0.0;
  for (std::size_t i = 0; i < original.estimate.size(); ++i) {
    worst_dt_s = std::max(worst_dt_s, std::abs(converted.estimate[i].t_s - 1000.0 - original.estimate[i].t_s));
    worst_m = std::max(worst_m, (converted.estimate[i].p_robot_in_odom_m - original.estimate[i].p_robot_in_odom_m).norm());
  }
  std::printf("%s: ticks %zu, frames %llu, vision %llu; against the original: largest position difference %.3g m, "
              "time %.3g s\n",
              what, original.estimate.size(), static_cast<unsigned long long>(converted.frames),
              static_cast<unsigned long long>(converted.inputs.vision), worst_m, worst_dt_s);
  EXPECT_LT(worst_dt_s, 1e-6);
  EXPECT_LT(worst_m, 1e-3);
}

class ForeignReplay : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dive_ = testing::makeTestDive("foreign_dive", 8.0);
    VehicleSetup setup;
    std::string error;
    ASSERT_TRUE(loadVehicleSetup(kBoard, &setup, &error)) << error;
    foreign_ = testing::tempPath("foreign_dive_ros2.mcap");
    testing::ForeignMcapWriter mcap(foreign_);
    written_ = writeForeign(dive_, mcap, setup.config.ekf.q_robot_imu);
    mcap.close();
    bag_ = testing::tempPath("foreign_dive_ros1.bag");
    testsupport::Ros1BagWriter bag;
    ASSERT_TRUE(bag.open(bag_, testsupport::Ros1BagWriter::Compression::kLz4));
    const Written in_bag = writeForeign(dive_, bag, setup.config.ekf.q_robot_imu);
    ASSERT_TRUE(bag.close());
    ASSERT_EQ(in_bag.frames, written_.frames);
    map_ = testing::tempPath("foreign_map.yaml");
    std::ofstream(map_) << kMap;
  }
  // Each replay once for the suite (the tests compare them).
  static const ReplaySummary& original() {
    static const ReplaySummary s = replay(dive_, testing::tempPath("foreign_original"), "", kBoard);
    return s;
  }
  static const ReplaySummary& converted() {
    static const ReplaySummary s = replay(foreign_, convertedDir(), map_, kBoard);
    return s;
  }
  static std::string convertedDir() { return testing::tempPath("foreign_converted"); }

  static std::string dive_, foreign_, bag_, map_;
  static Written written_;
};
std::string ForeignReplay::dive_, ForeignReplay::foreign_, ForeignReplay::bag_, ForeignReplay::map_;
Written ForeignReplay::written_;

TEST_F(ForeignReplay, ARos2RecordingOfTheDiveGivesTheTrajectoryOfTheOriginal) {
  ASSERT_GT(written_.frames, 70);
  ASSERT_GT(written_.attitude, 0);
  ASSERT_GT(written_.heading, 0);
  EXPECT_FALSE(converted().reproduce);
  EXPECT_EQ(converted().frames, original().frames);
  EXPECT_EQ(converted().inputs.imu, original().inputs.imu);
  EXPECT_EQ(converted().inputs.attitude, original().inputs.attitude);
  EXPECT_EQ(converted().inputs.heading, original().inputs.heading);
  EXPECT_EQ(converted().inputs.depth, original().inputs.depth);
  EXPECT_EQ(converted().inputs.dvl + static_cast<std::uint64_t>(written_.dvl_invalid), original().inputs.dvl);
  EXPECT_EQ(converted().read.incomplete_frames, 0u);
  expectSameTrajectory(original(), converted(), "ROS 2 MCAP");
}

TEST_F(ForeignReplay, ARos1BagOfTheDiveGivesTheTrajectoryOfTheOriginal) {
  const ReplaySummary from_bag = replay(bag_, testing::tempPath("foreign_converted_bag"), map_, kBoard);
  EXPECT_EQ(from_bag.frames, original().frames);
  EXPECT_EQ(from_bag.inputs.imu, original().inputs.imu);
  EXPECT_EQ(from_bag.read.bad_messages, 0u);
  expectSameTrajectory(original(), from_bag, "ROS 1 bag (lz4 chunks)");
}

TEST_F(ForeignReplay, ItsOutputRecordingReplaysBitForBitWithAPlainReplay) {
  const ReplaySummary& run = converted();
  const ReplaySummary again = replay(convertedDir() + "/replay.mcap", testing::tempPath("foreign_again"), "", "");
  EXPECT_TRUE(again.reproduce);
  EXPECT_EQ(again.solutions_compared, run.ticks);
  EXPECT_EQ(again.mismatches, 0u);
  EXPECT_EQ(again.inputs.imu, run.inputs.imu);
  EXPECT_EQ(again.inputs.vision, run.inputs.vision);
  RecordingReader out;
  std::string error;
  ASSERT_TRUE(out.open(convertedDir() + "/replay.mcap", &error)) << error;
  const auto* foreign = out.metadata("deepnav.foreign");
  ASSERT_NE(foreign, nullptr);
  EXPECT_EQ(foreign->at("topic_map"), kMap);
}

TEST_F(ForeignReplay, TheCommandLineRunsItAndNamesAMissingTopic) {
  const std::string bin = deepnav::testing::binDir() + "/deepnav";
  const std::string out = testing::tempPath("foreign_cli");
  const std::string log = testing::tempPath("foreign_cli.log");
  // Dead reckoning (no vision) keeps it short: the command line's wiring is what is tested here.
  const std::string cmd = bin + " replay --topics " + map_ + " --board " + kBoard + " " + foreign_ + " --out " + out +
                          " --set vision.vo_mode=none --set markers.enabled=false > " + log + " 2>&1";
  const int rc = std::system(cmd.c_str());
  std::ifstream first_log(log);
  ASSERT_EQ(rc, 0) << cmd << "\n" << std::string(std::istreambuf_iterator<char>(first_log), {});
  EXPECT_TRUE(std::filesystem::exists(out + "/replay.mcap"));
  const std::string bad_map = testing::tempPath("foreign_bad_map.yaml");
  std::ofstream(bad_map) << "topics:\n  /imu/data: {sensor: imu}\n";
  const std::string bad = bin + " replay --topics " + bad_map + " " + foreign_ + " --out " + out + "_bad > " + log +
                          " 2>&1";
  EXPECT_NE(std::system(bad.c_str()), 0);
  std::ifstream in(log);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("topic '/imu/data' (in " + bad_map + ") is not in the recording"), std::string::npos) << text;
}

}  // namespace
}  // namespace deepnav
