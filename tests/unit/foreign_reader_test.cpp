// A ROS 2 MCAP written like `ros2 bag record` (our writer, ros2msg schemas, CDR) read through a topic map:
// the container, the factory, every message type in NED/FRD and ENU/FLU converted to the loop's samples,
// and every bad input named by topic.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "board/config/topic_map_file.h"
#include "board/config/vehicle_setup.h"
#include "board/replay/bench_replay.h"
#include "drivers/replay/recording_reader.h"
#include "drivers/foreign/foreign_replay_reader.h"
#include "drivers/foreign/mcap_container.h"
#include "drivers/foreign/open_foreign_container.h"
#include "tests/support/foreign_mcap_writer.h"
#include "tests/support/ros1_bag_writer.h"

namespace deepnav::foreign {
namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr std::int64_t kT0Ns = 1'700'000'000'000'000'000;  // 2023-11-14, as a ROS clock stamps
constexpr std::int64_t kT0Us = kT0Ns / 1000;

std::string tempPath(const std::string& name) { return ::testing::TempDir() + "foreign_" + name; }

ros::Header headerAt(std::int64_t t_ns, const char* frame) {
  ros::Header h;
  h.stamp.sec = static_cast<std::int32_t>(t_ns / 1'000'000'000);
  h.stamp.nanosec = static_cast<std::uint32_t>(t_ns % 1'000'000'000);
  h.frame_id = frame;
  return h;
}

Eigen::Quaterniond zyx(double yaw_deg, double pitch_deg, double roll_deg) {
  return Eigen::AngleAxisd(yaw_deg * kDeg, Eigen::Vector3d::UnitZ()) *
         Eigen::AngleAxisd(pitch_deg * kDeg, Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(roll_deg * kDeg, Eigen::Vector3d::UnitX());
}

ros::Imu imuAt(std::int64_t t_ns, const Eigen::Quaterniond& q) {
  ros::Imu m;
  m.header = headerAt(t_ns, "imu");
  m.orientation = {q.x(), q.y(), q.z(), q.w()};
  m.angular_velocity = {0.01, 0.02, 0.03};
  m.linear_acceleration = {0.0, 0.0, -9.81};
  return m;
}

cv::Mat pattern(int value) {
  cv::Mat m(64, 80, CV_8UC1);
  for (int r = 0; r < m.rows; ++r) {
    for (int c = 0; c < m.cols; ++c) m.at<std::uint8_t>(r, c) = static_cast<std::uint8_t>((r * 7 + c * 3 + value) & 0xFF);
  }
  return m;
}

ros::Image rawImage(std::int64_t t_ns, const cv::Mat& grey) {
  ros::Image m;
  m.header = headerAt(t_ns, "left");
  m.width = static_cast<std::uint32_t>(grey.cols);
  m.height = static_cast<std::uint32_t>(grey.rows);
  m.encoding = "mono8";
  m.step = m.width;
  m.data.assign(grey.data, grey.data + grey.total());
  return m;
}

ros::CompressedImage pngImage(std::int64_t t_ns, const cv::Mat& grey) {
  ros::CompressedImage m;
  m.header = headerAt(t_ns, "right");
  m.format = "png";
  EXPECT_TRUE(cv::imencode(".png", grey, m.data));
  return m;
}

// Half a second of an FRD AHRS (10 Hz) heading 30 deg, an ENU DVL (TwistWithCovarianceStamped), an FRD DVL
// (TwistStamped), a pressure sensor, an FRD magnetometer and a stereo pair (raw left, PNG right, 2 ms apart),
// each message logged 1 ms after its stamp.
template <typename Writer>
void writeSensorsTo(Writer& w) {
  for (int i = 0; i < 5; ++i) {
    const std::int64_t t = kT0Ns + i * 100'000'000LL;
    w.write("/ahrs", imuAt(t, zyx(30, 10, 5)), t + 1'000'000);  // NED heading 30, pitch up 10, roll 5
    ros::TwistWithCovarianceStamped dvl;
    dvl.header = headerAt(t + 10'000'000, "dvl");
    dvl.twist.twist.linear = {0.5, 0.1, -0.05};
    dvl.twist.covariance[0] = dvl.twist.covariance[7] = dvl.twist.covariance[14] = 1e-4;
    w.write("/dvl", dvl, t + 11'000'000);
    ros::TwistStamped dvl2;
    dvl2.header = headerAt(t + 20'000'000, "dvl2");
    dvl2.twist.linear = {0.5, 0.1, -0.05};
    w.write("/dvl_frd", dvl2, t + 21'000'000);
    ros::FluidPressure p;
    p.header = headerAt(t + 30'000'000, "pressure");
    p.fluid_pressure = 101325.0 + 1025.0 * 9.80665 * (100.0 + i);  // 100 m + i
    w.write("/pressure", p, t + 31'000'000);
    ros::MagneticField mag;
    mag.header = headerAt(t + 40'000'000, "mag");
    // Level (its attitude is the AHRS's: pitched and rolled, so this reading is levelled by it), FRD.
    const Eigen::Vector3d field_enu(0.0, 20e-6, -40e-6);
    const Eigen::Quaterniond q_odom_robot = Eigen::AngleAxisd(60 * kDeg, Eigen::Vector3d::UnitZ()) *
                                            Eigen::AngleAxisd(-10 * kDeg, Eigen::Vector3d::UnitY()) *
                                            Eigen::AngleAxisd(5 * kDeg, Eigen::Vector3d::UnitX());
    const Eigen::Vector3d m_flu = q_odom_robot.conjugate() * field_enu;  // ENU yaw 60 = heading 30
    mag.magnetic_field = {m_flu.x(), -m_flu.y(), -m_flu.z()};            // as an FRD sensor reads it
    w.write("/mag", mag, t + 41'000'000);
    w.write("/left", rawImage(t + 50'000'000, pattern(i)), t + 51'000'000);
    w.write("/right", pngImage(t + 52'000'000, pattern(100 + i)), t + 53'000'000);
  }
}

std::string writeSensors(const std::string& name) {
  const std::string path = tempPath(name);
  testing::ForeignMcapWriter w(path);
  writeSensorsTo(w);
  w.close();
  return path;
}

// The same messages in a ROS 1 bag (lz4 chunks small enough that they overlap in time).
std::string writeSensorsBag(const std::string& name) {
  const std::string path = tempPath(name);
  testsupport::Ros1BagWriter w;
  EXPECT_TRUE(w.open(path, testsupport::Ros1BagWriter::Compression::kLz4, 16 * 1024));
  writeSensorsTo(w);
  EXPECT_TRUE(w.close());
  return path;
}

const char* kMapText =
    "topics:\n"
    "  /ahrs: {sensor: [imu, attitude, heading], convention: ned_frd}\n"
    "  /dvl: {sensor: dvl}\n"
    "  /dvl_frd: {sensor: dvl, convention: ned_frd}\n"
    "  /pressure: {sensor: depth}\n"
    "  /mag: {sensor: compass, convention: ned_frd}\n"
    "  /left: {sensor: camera_left}\n"
    "  /right: {sensor: camera_right}\n";

TopicMap parseMap(const std::string& text) {
  TopicMapFile f;
  std::string error;
  EXPECT_TRUE(parseTopicMapText(text, "map.yaml", &f, &error)) << error;
  return f.map;
}

ForeignVehicle smallCamera() {
  ForeignVehicle v;
  v.width_px = 80;
  v.height_px = 64;
  v.channels = 1;
  v.pair_tolerance_us = 5000;
  return v;
}

struct Collected {
  std::vector<ImuSample> imu;
  std::vector<AttitudeSample> attitude;
  std::vector<HeadingSample> heading;
  std::vector<DvlSample> dvl;
  std::vector<DepthSample> depth;
  std::vector<StereoFrame> frames;
  std::vector<TimeUs> times;
};

bool collect(ForeignReplayReader& reader, Collected* c, std::string* error) {
  return reader.forEach(true, [&](const ReplayEvent& e) {
    c->times.push_back(e.t_us);
    if (e.kind == ReplayEvent::Kind::kFrame) {
      StereoFrame copy = *e.frame;
      copy.left = e.frame->left.clone();
      copy.right = e.frame->right.clone();
      c->frames.push_back(copy);
      return true;
    }
    if (const auto* s = std::get_if<ImuSample>(&e.input)) c->imu.push_back(*s);
    if (const auto* s = std::get_if<AttitudeSample>(&e.input)) c->attitude.push_back(*s);
    if (const auto* s = std::get_if<HeadingSample>(&e.input)) c->heading.push_back(*s);
    if (const auto* s = std::get_if<DvlSample>(&e.input)) c->dvl.push_back(*s);
    if (const auto* s = std::get_if<DepthSample>(&e.input)) c->depth.push_back(*s);
    return true;
  }, error);
}

TEST(ForeignReader, TheMcapContainerListsTopicsTypesAndCounts) {
  const std::string path = writeSensors("topics.mcap");
  std::string error;
  auto container = openForeignContainer(path, &error);
  ASSERT_NE(container, nullptr) << error;
  ASSERT_EQ(container->topics().size(), 7u);
  EXPECT_EQ(container->topics()[0].name, "/ahrs");
  EXPECT_EQ(container->topics()[0].type, "sensor_msgs/msg/Imu");
  EXPECT_EQ(container->topics()[0].messages, 5u);
  EXPECT_EQ(container->topics()[0].serialization, Serialization::kCdr);
  EXPECT_TRUE(container->topics()[0].unsupported.empty());
  std::int64_t last = 0;
  int n = 0;
  ASSERT_TRUE(container->forEach([&](const ForeignMessage& m) {
    EXPECT_GE(m.log_time_ns, last);
    last = m.log_time_ns;
    ++n;
    return true;
  }, &error)) << error;
  EXPECT_EQ(n, 35);
}

TEST(ForeignReader, EveryTypeConvertsToTheHandComputedSamples) {
  const std::string path = writeSensors("all.mcap");
  ForeignReplayReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(path, parseMap(kMapText), &error)) << error;
  reader.setVehicle(smallCamera());
  Collected c;
  ASSERT_TRUE(collect(reader, &c, &error)) << error;
  ASSERT_EQ(c.imu.size(), 5u);
  EXPECT_EQ(c.imu[0].t_us, kT0Us);  // the header stamp, not the log time 1 ms later
  EXPECT_EQ(c.imu[1].t_us, kT0Us + 100'000);
  EXPECT_EQ(c.imu[0].w_imu_radps, Eigen::Vector3d(0.01, -0.02, -0.03));
  EXPECT_EQ(c.imu[0].f_imu_mps2, Eigen::Vector3d(0.0, 0.0, 9.81));
  ASSERT_EQ(c.attitude.size(), 5u);
  EXPECT_NEAR(c.attitude[0].roll_rad, 5 * kDeg, 1e-12);
  EXPECT_NEAR(c.attitude[0].pitch_rad, -10 * kDeg, 1e-12);
  ASSERT_EQ(c.heading.size(), 10u);  // 5 from the AHRS, 5 from the magnetometer
  for (const HeadingSample& h : c.heading) EXPECT_NEAR(h.heading_rad, 30 * kDeg, 1e-9) << h.t_us;
  ASSERT_EQ(c.dvl.size(), 10u);
  EXPECT_EQ(c.dvl[0].t_us, kT0Us + 10'000);
  EXPECT_EQ(c.dvl[0].v_dvl_mps, Eigen::Vector3d(0.5, 0.1, -0.05));  // ENU/FLU as is
  EXPECT_EQ(c.dvl[0].cov_v_dvl_mps2, Eigen::Matrix3d::Identity() * 1e-4);
  EXPECT_EQ(c.dvl[1].v_dvl_mps, Eigen::Vector3d(0.5, -0.1, 0.05));  // FRD: y and z flip
  EXPECT_TRUE(c.dvl[1].cov_v_dvl_mps2.isZero());
  ASSERT_EQ(c.depth.size(), 5u);
  EXPECT_NEAR(c.depth[0].depth_m, 100.0, 1e-9);
  EXPECT_NEAR(c.depth[4].depth_m, 104.0, 1e-9);
  ASSERT_EQ(c.frames.size(), 5u);
  EXPECT_EQ(c.frames[2].t_us, kT0Us + 200'000 + 50'000);  // the left stamp
  EXPECT_EQ(cv::norm(c.frames[2].left, pattern(2), cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(c.frames[2].right, pattern(102), cv::NORM_INF), 0.0);
  EXPECT_EQ(reader.stats().messages, 35u);
  EXPECT_EQ(reader.stats().bad_messages, 0u);
  EXPECT_EQ(reader.stats().incomplete_frames, 0u);
  EXPECT_TRUE(reader.warnings().empty()) << reader.warnings().front();
}

TEST(ForeignReader, TheSameMessagesInARos1BagGiveTheSameSamples) {
  const TopicMap map = parseMap(kMapText);
  ForeignReplayReader from_mcap, from_bag;
  std::string error;
  ASSERT_TRUE(from_mcap.open(writeSensors("same.mcap"), map, &error)) << error;
  ASSERT_TRUE(from_bag.open(writeSensorsBag("same.bag"), map, &error)) << error;
  from_mcap.setVehicle(smallCamera());
  from_bag.setVehicle(smallCamera());
  Collected a, b;
  ASSERT_TRUE(collect(from_mcap, &a, &error)) << error;
  ASSERT_TRUE(collect(from_bag, &b, &error)) << error;
  EXPECT_EQ(b.times, a.times);
  ASSERT_EQ(b.imu.size(), a.imu.size());
  for (std::size_t i = 0; i < a.imu.size(); ++i) EXPECT_EQ(b.imu[i].f_imu_mps2, a.imu[i].f_imu_mps2);
  ASSERT_EQ(b.heading.size(), a.heading.size());
  for (std::size_t i = 0; i < a.heading.size(); ++i) EXPECT_EQ(b.heading[i].heading_rad, a.heading[i].heading_rad);
  ASSERT_EQ(b.dvl.size(), a.dvl.size());
  for (std::size_t i = 0; i < a.dvl.size(); ++i) EXPECT_EQ(b.dvl[i].v_dvl_mps, a.dvl[i].v_dvl_mps);
  ASSERT_EQ(b.depth.size(), 5u);
  EXPECT_EQ(b.depth[3].depth_m, a.depth[3].depth_m);
  ASSERT_EQ(b.frames.size(), 5u);
  EXPECT_EQ(cv::norm(b.frames[4].right, a.frames[4].right, cv::NORM_INF), 0.0);
  EXPECT_EQ(from_bag.stats().bad_messages, 0u);
}

TEST(ForeignReader, AnEnuAhrsIsTakenAsIsAndLogTimeCanStampIt) {
  const std::string path = writeSensors("enu.mcap");
  ForeignReplayReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(path, parseMap("topics:\n  /ahrs: {sensor: [attitude, heading], stamp: log_time}\n"),
                          &error))
      << error;
  reader.setVehicle(smallCamera());
  Collected c;
  ASSERT_TRUE(collect(reader, &c, &error)) << error;
  ASSERT_EQ(c.attitude.size(), 5u);
  // The NED quaternion read as ENU: ENU yaw 30 deg, i.e. heading 60; pitch and roll as written.
  EXPECT_NEAR(c.attitude[0].pitch_rad, 10 * kDeg, 1e-12);
  EXPECT_NEAR(c.heading[0].heading_rad, 60 * kDeg, 1e-12);
  EXPECT_EQ(c.attitude[0].t_us, kT0Us + 1000);  // log time
  EXPECT_EQ(reader.stats().unknown_topic, 30u);  // the other topics, not in this map
}

TEST(ForeignReader, AMapTopicMissingFromTheFileIsNamedWithWhatTheFileHolds) {
  const std::string path = writeSensors("missing.mcap");
  ForeignReplayReader reader;
  std::string error;
  EXPECT_FALSE(reader.open(path, parseMap("topics:\n  /imu/data: {sensor: imu}\n"), &error));
  EXPECT_NE(error.find("topic '/imu/data' (in map.yaml) is not in the recording; it holds: /ahrs (sensor_msgs/msg/Imu)"),
            std::string::npos)
      << error;
}

TEST(ForeignReader, ATopicOfAnotherTypeIsNamedWithTheTypeItsSensorReads) {
  const std::string path = writeSensors("mismatch.mcap");
  ForeignReplayReader reader;
  std::string error;
  EXPECT_FALSE(reader.open(path, parseMap("topics:\n  /pressure: {sensor: imu}\n"), &error));
  EXPECT_NE(error.find("topic '/pressure' (in map.yaml) is sensor_msgs/msg/FluidPressure; sensor 'imu' reads "
                       "sensor_msgs/msg/Imu"),
            std::string::npos)
      << error;
  EXPECT_FALSE(reader.open(path, parseMap("topics:\n  /mag: {sensor: dvl}\n"), &error));
  EXPECT_NE(error.find("sensor 'dvl' reads geometry_msgs/msg/TwistWithCovarianceStamped or"), std::string::npos)
      << error;
}

TEST(ForeignReader, AnotherEncodingIsRefusedNamingTheTopic) {
  const std::string path = tempPath("json.mcap");
  {
    testing::ForeignMcapWriter w(path);
    w.writeRaw("/imu_json", "sensor_msgs/msg/Imu", "{}", "jsonschema", "json", {'{', '}'}, kT0Ns);
    w.writeRaw("/imu_ros1", "sensor_msgs/Imu", "Header header", "ros1msg", "ros1", {0}, kT0Ns);
    w.close();
  }
  ForeignReplayReader reader;
  std::string error;
  EXPECT_FALSE(reader.open(path, parseMap("topics:\n  /imu_json: {sensor: imu}\n"), &error));
  EXPECT_NE(error.find("topic '/imu_json' (in map.yaml) cannot be read: message encoding 'json' (only cdr is read)"),
            std::string::npos)
      << error;
  EXPECT_FALSE(reader.open(path, parseMap("topics:\n  /imu_ros1: {sensor: imu}\n"), &error));
  EXPECT_NE(error.find("'/imu_ros1'"), std::string::npos) << error;
  EXPECT_NE(error.find("'ros1'"), std::string::npos) << error;
}

TEST(ForeignReader, StampsGoingBackBeyondTheToleranceStopTheReplayNamingTheTopic) {
  const std::string path = tempPath("unsorted.mcap");
  {
    testing::ForeignMcapWriter w(path);
    w.write("/imu", imuAt(kT0Ns, Eigen::Quaterniond::Identity()), kT0Ns);
    w.write("/imu", imuAt(kT0Ns + 10'000'000, Eigen::Quaterniond::Identity()), kT0Ns + 10'000'000);
    w.write("/imu", imuAt(kT0Ns + 7'000'000, Eigen::Quaterniond::Identity()), kT0Ns + 20'000'000);  // 3 ms back
    w.close();
  }
  ForeignReplayReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(path, parseMap("topics:\n  /imu: {sensor: imu}\n"), &error)) << error;
  Collected c;
  EXPECT_FALSE(collect(reader, &c, &error));
  EXPECT_NE(error.find("topic '/imu': stamps are not sorted: message 3 goes back 3.000 ms (stamp_tolerance_ms allows "
                       "0.000 ms)"),
            std::string::npos)
      << error;
  EXPECT_EQ(c.imu.size(), 2u);
  // Within a stated tolerance the sample goes through.
  ASSERT_TRUE(reader.open(path, parseMap("topics:\n  /imu: {sensor: imu, stamp_tolerance_ms: 5}\n"), &error)) << error;
  Collected d;
  ASSERT_TRUE(collect(reader, &d, &error)) << error;
  EXPECT_EQ(d.imu.size(), 3u);
}

TEST(ForeignReader, AnAttitudeAskedOfAnImuWithoutOrientationIsCountedAndNamed) {
  const std::string path = tempPath("no_orientation.mcap");
  {
    testing::ForeignMcapWriter w(path);
    for (int i = 0; i < 3; ++i) {
      ros::Imu m = imuAt(kT0Ns + i * 5'000'000LL, Eigen::Quaterniond::Identity());
      m.orientation_covariance[0] = -1.0;  // a plain IMU
      w.write("/imu", m, kT0Ns + i * 5'000'000LL);
    }
    w.close();
  }
  ForeignReplayReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(path, parseMap("topics:\n  /imu: {sensor: [imu, attitude]}\n"), &error)) << error;
  Collected c;
  ASSERT_TRUE(collect(reader, &c, &error)) << error;
  EXPECT_EQ(c.imu.size(), 3u);
  EXPECT_TRUE(c.attitude.empty());
  ASSERT_EQ(reader.warnings().size(), 1u);
  EXPECT_NE(reader.warnings()[0].find("topic '/imu': no attitude sample from 3 of 3 messages (no orientation: "
                                      "orientation_covariance[0] = -1"),
            std::string::npos)
      << reader.warnings()[0];
  EXPECT_EQ(reader.counts("/imu")->without_value[static_cast<std::size_t>(ForeignSensor::kAttitude)], 3u);
}

TEST(ForeignReader, AnEmptyStampIsRefusedWithTheWayOut) {
  const std::string path = tempPath("nostamp.mcap");
  {
    testing::ForeignMcapWriter w(path);
    w.write("/imu", imuAt(0, Eigen::Quaterniond::Identity()), kT0Ns);
    w.close();
  }
  ForeignReplayReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(path, parseMap("topics:\n  /imu: {sensor: imu}\n"), &error)) << error;
  Collected c;
  EXPECT_FALSE(collect(reader, &c, &error));
  EXPECT_NE(error.find("topic '/imu': header.stamp is 0"), std::string::npos) << error;
  EXPECT_NE(error.find("stamp: log_time"), std::string::npos) << error;
}

TEST(ForeignReader, ImagesOfAnUnreadEncodingOrAnotherSizeStopTheReplayNamingTheTopic) {
  const std::string path = tempPath("bayer.mcap");
  {
    testing::ForeignMcapWriter w(path);
    ros::Image bayer = rawImage(kT0Ns, pattern(0));
    bayer.encoding = "bayer_rggb8";
    w.write("/left", bayer, kT0Ns);
    w.write("/right", rawImage(kT0Ns, pattern(0)), kT0Ns);
    w.close();
  }
  ForeignReplayReader reader;
  std::string error;
  const TopicMap map = parseMap("topics:\n  /left: {sensor: camera_left}\n  /right: {sensor: camera_right}\n");
  ASSERT_TRUE(reader.open(path, map, &error)) << error;
  reader.setVehicle(smallCamera());
  Collected c;
  EXPECT_FALSE(collect(reader, &c, &error));
  EXPECT_NE(error.find("topic '/left': message 1: image encoding 'bayer_rggb8' is not read"), std::string::npos)
      << error;
  const std::string sized = writeSensors("sized.mcap");
  ASSERT_TRUE(reader.open(sized, map, &error)) << error;
  ForeignVehicle big = smallCamera();
  big.width_px = 688;
  big.height_px = 516;
  reader.setVehicle(big);
  EXPECT_FALSE(collect(reader, &c, &error));
  EXPECT_NE(error.find("topic '/left': images are 80x64; the board's camera is 688x516"), std::string::npos) << error;
}

TEST(ForeignReader, UndecodableMessagesAreCountedSkippedAndNamedOnce) {
  const std::string path = tempPath("damaged.mcap");
  {
    testing::ForeignMcapWriter w(path);
    w.write("/imu", imuAt(kT0Ns, Eigen::Quaterniond::Identity()), kT0Ns);
    w.writeRaw("/imu", "sensor_msgs/msg/Imu", ros::ros2MsgDefinition("sensor_msgs/msg/Imu"), "ros2msg", "cdr",
               {0, 1, 0, 0, 1, 2}, kT0Ns + 1000);
    w.close();
  }
  ForeignReplayReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(path, parseMap("topics:\n  /imu: {sensor: imu}\n"), &error)) << error;
  Collected c;
  ASSERT_TRUE(collect(reader, &c, &error)) << error;
  EXPECT_EQ(c.imu.size(), 1u);
  EXPECT_EQ(reader.stats().bad_messages, 1u);
  ASSERT_EQ(reader.warnings().size(), 1u);
  EXPECT_NE(reader.warnings()[0].find("topic '/imu': message 2 does not decode as sensor_msgs/msg/Imu"),
            std::string::npos)
      << reader.warnings()[0];
}

TEST(ForeignReader, TheFactoryRefusesWhatIsNeitherMcapNorABag) {
  const std::string path = tempPath("garbage.bin");
  std::ofstream(path) << "not a recording at all";
  std::string error;
  EXPECT_EQ(openForeignContainer(path, &error), nullptr);
  EXPECT_NE(error.find("neither a ROS 2 MCAP recording"), std::string::npos) << error;
  EXPECT_EQ(openForeignContainer(tempPath("absent.mcap"), &error), nullptr);
  EXPECT_NE(error.find("absent.mcap: cannot open"), std::string::npos) << error;
  // A truncated MCAP: the MCAP reader's own message, naming the file.
  const std::string whole = writeSensors("whole.mcap");
  const std::string cut = tempPath("cut.mcap");
  std::filesystem::copy_file(whole, cut, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::resize_file(cut, 12);
  EXPECT_EQ(openForeignContainer(cut, &error), nullptr);
  EXPECT_NE(error.find("cut.mcap"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav::foreign

namespace deepnav {
namespace {

// An 80x64 camera (ORB VO takes 64x64 at least) for the half-second test recording.
const char* kSmallBoard =
    "camera:\n  width_px: 80\n  height_px: 64\n  fx_px: 60\n  fy_px: 60\n  cx_px: 39.5\n  cy_px: 31.5\n"
    "vision:\n  dense_disparities: 16\n";

TEST(ForeignBenchReplay, TheMapsMountingsReplaceTheBoardsAndTheRunIsRecordedWithThem) {
  const std::string dir = ::testing::TempDir() + "foreign_bench/";
  std::filesystem::create_directories(dir);
  const std::string recording = foreign::writeSensors("bench.mcap");
  std::ofstream(dir + "board.yaml") << kSmallBoard;
  std::ofstream(dir + "map.yaml") << foreign::kMapText << "  /unused: {sensor: dvl}\n";
  ReplayOptions o;
  o.input_path = recording;
  o.topics_path = dir + "map.yaml";
  o.board_path = dir + "board.yaml";
  o.out_dir = dir + "out";
  o.progress = false;
  ReplaySummary s;
  std::string error;
  // A topic of the map that the recording does not hold: named, nothing run.
  EXPECT_FALSE(runBenchReplay(o, &s, &error));
  EXPECT_NE(error.find("topic '/unused' (in " + dir + "map.yaml) is not in the recording"), std::string::npos) << error;
  std::string map_text = foreign::kMapText;
  map_text.replace(map_text.find("/dvl: {sensor: dvl}"), 19, "/dvl: {sensor: dvl, rotation_deg: [0, 0, 45]}");
  std::ofstream(dir + "map.yaml") << map_text;
  o.overrides = {"ekf.dvl_sigma_mps=0.02"};
  ASSERT_TRUE(runBenchReplay(o, &s, &error)) << error;
  EXPECT_EQ(s.frames, 5u);
  EXPECT_EQ(s.inputs.imu, 5u);
  EXPECT_EQ(s.inputs.dvl, 10u);
  EXPECT_EQ(s.inputs.depth, 5u);
  EXPECT_EQ(s.inputs.heading, 10u);
  RecordingReader out;
  ASSERT_TRUE(out.open(o.out_dir + "/replay.mcap", &error)) << error;
  VehicleSetup stored;
  ASSERT_TRUE(loadReplaySetup("", out, "replay.mcap", &stored, &error)) << error;
  const Eigen::Quaterniond q45(Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()));
  EXPECT_LT(stored.config.ekf.q_robot_dvl.angularDistance(q45), 1e-12);
  EXPECT_EQ(stored.config.ekf.dvl_sigma_mps, 0.02);  // the command line's --set still applies
  ASSERT_NE(out.metadata("deepnav.foreign"), nullptr);
  EXPECT_EQ(out.metadata("deepnav.foreign")->at("recording"), recording);
  // --realtime does not take a foreign recording.
  o.realtime = true;
  EXPECT_FALSE(runBenchReplay(o, &s, &error));
  EXPECT_NE(error.find("--topics replays on the bench only"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav
