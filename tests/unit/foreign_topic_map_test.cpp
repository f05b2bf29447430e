// The topic map file: the worked example parses to what its comments say, every key is documented, and
// each bad file gets one message naming the file, the topic and the key.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "board/config/topic_map_file.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

using foreign::ForeignSensor;

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string parseError(const std::string& text) {
  TopicMapFile f;
  std::string error;
  EXPECT_FALSE(parseTopicMapText(text, "map.yaml", &f, &error)) << text;
  return error;
}

TEST(ForeignTopicMap, TheWorkedExampleParsesAsItsCommentsSay) {
  TopicMapFile f;
  std::string error;
  ASSERT_TRUE(loadTopicMapFile(deepnav::testing::sourceDir() + "/board/examples/topic_map.yaml", &f, &error))
      << error;
  ASSERT_EQ(f.map.topics.size(), 5u);
  const foreign::TopicMapping* ahrs = f.map.find("/ahrs/imu");
  ASSERT_NE(ahrs, nullptr);
  EXPECT_TRUE(ahrs->has(ForeignSensor::kImu) && ahrs->has(ForeignSensor::kAttitude) &&
              ahrs->has(ForeignSensor::kHeading));
  EXPECT_EQ(ahrs->convention, foreign::FrameConvention::kNedFrd);
  EXPECT_FALSE(ahrs->heading_is_true);
  // An imu topic's mounting is the board's ekf.imu_rotation_deg (replaced), which the reader reads back.
  EXPECT_FALSE(ahrs->q_robot_sensor.has_value());
  const foreign::TopicMapping* depth = f.map.find("/pressure");
  ASSERT_NE(depth, nullptr);
  EXPECT_EQ(depth->water_density_kgpm3, 1027.0);
  EXPECT_EQ(depth->atmospheric_pa, 101325.0);
  ASSERT_TRUE(f.map.pair_tolerance_us.has_value());
  EXPECT_EQ(*f.map.pair_tolerance_us, 5000);
  EXPECT_TRUE(f.map.find("/stereo/left/image_raw/compressed")->has(ForeignSensor::kCameraLeft));
  const std::vector<std::string> overrides = {
      "ekf.imu_rotation_deg=[0, 0, 180]", "ekf.p_imu_in_robot_m=[0.10, 0.0, -0.05]",
      "ekf.dvl_rotation_deg=[0, 0, 45]",  "ekf.p_dvl_in_robot_m=[-0.3, 0.0, -0.4]",
      "ekf.p_depth_in_robot_m=[0.0, 0.0, -0.2]"};
  EXPECT_EQ(f.board_overrides, overrides);
}

TEST(ForeignTopicMap, DefaultsWhenOnlyTheSensorIsGiven) {
  TopicMapFile f;
  std::string error;
  ASSERT_TRUE(parseTopicMapText("topics:\n  /imu: {sensor: imu}\n", "map.yaml", &f, &error)) << error;
  const foreign::TopicMapping& m = f.map.topics.at(0);
  EXPECT_EQ(m.convention, foreign::FrameConvention::kEnuFlu);
  EXPECT_EQ(m.stamp, foreign::StampSource::kHeader);
  EXPECT_EQ(m.stamp_tolerance_us, 0);
  EXPECT_FALSE(f.map.pair_tolerance_us.has_value());  // the board's camera.pair_tolerance_ms
  EXPECT_TRUE(f.board_overrides.empty());
}

TEST(ForeignTopicMap, AnAttitudeOnlyTopicConvertsWithItsOwnMounting) {
  TopicMapFile f;
  std::string error;
  ASSERT_TRUE(parseTopicMapText("topics:\n  /ahrs: {sensor: attitude, rotation_deg: [0, 0, 90]}\n", "map.yaml", &f,
                                &error))
      << error;
  ASSERT_TRUE(f.map.topics.at(0).q_robot_sensor.has_value());
  EXPECT_TRUE(f.map.topics.at(0).q_robot_sensor->isApprox(
      Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ())), 1e-12));
  EXPECT_TRUE(f.board_overrides.empty());
}

TEST(ForeignTopicMap, EveryKeyIsDocumented) {
  const std::string doc = readFile(deepnav::testing::sourceDir() + "/docs/foreign-recordings.md");
  ASSERT_FALSE(doc.empty());
  EXPECT_NE(doc.find(describeTopicMapParams()), std::string::npos)
      << "docs/foreign-recordings.md must hold the table of describeTopicMapParams():\n"
      << describeTopicMapParams();
  EXPECT_NE(doc.find("pair_tolerance_ms"), std::string::npos);
}

TEST(ForeignTopicMap, BadFilesAreRefusedNamingFileTopicAndKey) {
  struct Case {
    const char* text;
    const char* expected;  // a part of the message
  } cases[] = {
      {"topics:\n  /imu: {sensor: imu, convention: nwu}\n", "map.yaml: topics./imu: key 'convention' is 'nwu'"},
      {"topics:\n  /imu: {sensor: imu, stamp_tolerance_ms: -1}\n", "key 'stamp_tolerance_ms' is -1, out of range"},
      {"topics:\n  /imu: {sensor: imu, frame: ned}\n", "map.yaml: topics./imu: unknown key 'frame'; allowed: sensor,"},
      {"topics:\n  /imu: {convention: ned_frd}\n", "map.yaml: topics./imu: key 'sensor' is missing"},
      {"topics:\n  /imu: {sensor: gyro}\n", "key 'sensor': 'gyro' is not a sensor"},
      {"topics:\n  /imu: {sensor: [imu, imu]}\n", "'imu' is repeated"},
      {"topics:\n  /x: {sensor: [imu, dvl]}\n", "imu, dvl cannot share a topic"},
      {"topics:\n  /p: {sensor: depth, convention: ned_frd}\n", "topics./p: key 'convention' applies to imu,"},
      {"topics:\n  /p: {sensor: depth, rotation_deg: [0, 0, 1]}\n", "key 'rotation_deg' applies to"},
      {"topics:\n  /imu: {sensor: imu, water_density_kgpm3: 1000}\n", "applies to depth topics only"},
      {"topics:\n  /p: {sensor: depth, water_density_kgpm3: 100}\n", "key 'water_density_kgpm3' is 100, out of range"},
      {"topics:\n  /c: {sensor: camera_left, mono16_bits: 17}\n", "key 'mono16_bits' is 17"},
      {"topics:\n  /c: {sensor: camera_left}\n", "one camera_left and one camera_right topic (the map has 1 and 0)"},
      {"topics:\n  /c: {sensor: camera_right, rotation_deg: [0, 0, 1]}\n  /d: {sensor: camera_left}\n",
       "topics./c: key 'rotation_deg' applies to"},
      {"topics:\n  /m: {sensor: compass}\n", "needs the vehicle's roll and pitch"},
      {"topics:\n  /a: {sensor: imu, rotation_deg: [0, 0, 1]}\n  /b: {sensor: imu, rotation_deg: [0, 0, 2]}\n",
       "two topics give the mounting ekf.imu_rotation_deg"},
      {"topics:\n  /imu: {sensor: imu, rotation_deg: [0, 0, 270]}\n", "key 'rotation_deg' is [0, 0, 270]"},
      {"stereo:\n  pair_tolerance_ms: 0\ntopics:\n  /imu: {sensor: imu}\n", "map.yaml: stereo: key 'pair_tolerance_ms'"},
      {"topic:\n  /imu: {sensor: imu}\n", "map.yaml: unknown key 'topic'; allowed: topics, stereo"},
      {"topics: {}\n", "key 'topics' must map each foreign topic"},
      {"topics:\n  /imu: imu\n", "topics./imu: expected a map"},
      {"topics:\n  /imu: {sensor: imu}\n  /imu: {sensor: dvl}\n", "/imu"},  // repeated key: the strict loader
  };
  for (const Case& c : cases) {
    const std::string error = parseError(c.text);
    EXPECT_NE(error.find(c.expected), std::string::npos) << "file:\n" << c.text << "message: " << error;
  }
}

TEST(ForeignTopicMap, AMissingFileIsNamed) {
  TopicMapFile f;
  std::string error;
  EXPECT_FALSE(loadTopicMapFile("/nonexistent/map.yaml", &f, &error));
  EXPECT_NE(error.find("/nonexistent/map.yaml"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav
