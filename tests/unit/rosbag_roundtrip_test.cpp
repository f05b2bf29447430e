// ROS 1 bags written by the test writer (tests/support/ros1_bag_writer.h, laid out as rosbag
// writes them) read back by drivers/rosbag: every message type and every compression, topics and
// counts from the index, log-time order across chunks and connections.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <tuple>

#include "drivers/rosbag/bag_reader.h"
#include "drivers/rosbag/ros1_md5.h"
#include "drivers/rosbag/ros1_msg_codec.h"
#include "tests/support/ros1_bag_writer.h"
#include "tests/unit/rosbag_test_util.h"

namespace deepnav::rosbag {
namespace {

using testsupport::encodeRos1;
using testsupport::Ros1BagWriter;
using testsupport::Ros1Type;
using Compression = Ros1BagWriter::Compression;
constexpr auto compressionName = &Ros1BagWriter::compressionName;
using namespace testing_util;

// Decodes `d` as Msg and checks it against `sent`: equal structs serialize to equal bytes, so the
// sent message re-encoded must equal the decoded one re-encoded (seq is not kept by the structs).
template <class Msg>
void expectDecodesTo(const Delivered& d, const Msg& sent) {
  Msg got;
  ASSERT_TRUE(decodeRos1(d.data.data(), d.data.size(), &got)) << d.topic;
  EXPECT_EQ(encodeRos1(got), encodeRos1(sent)) << d.topic;
  EXPECT_EQ(got.header.stamp.sec, sent.header.stamp.sec);
  EXPECT_EQ(got.header.stamp.nanosec, sent.header.stamp.nanosec);
  EXPECT_EQ(got.header.frame_id, sent.header.frame_id);
  EXPECT_EQ(d.type, Ros1Type<Msg>::kName);
}

class RosbagRoundTrip : public ::testing::TestWithParam<Compression> {};

TEST_P(RosbagRoundTrip, EveryMessageTypeDecodesToWhatWasWritten) {
  const std::string path = deepnav::testing::tempPath(compressionName(GetParam()) + ".bag");
  Ros1BagWriter writer;
  ASSERT_TRUE(writer.open(path, GetParam(), 600));  // small chunks: several per bag
  const int64_t t0 = 1700000000000000000LL;
  constexpr int kEach = 4;
  for (int i = 0; i < kEach; ++i) {
    const int64_t t = t0 + i * 1000000LL;
    writer.write("/imu", sampleImu(i), t + 1);
    writer.write("/cam0/image_raw", sampleImage(i), t + 2);
    writer.write("/cam1/compressed", sampleCompressedImage(i), t + 3);
    writer.write("/depth", sampleFluidPressure(i), t + 4);
    writer.write("/dvl/twist", sampleTwistStamped(i), t + 5);
    writer.write("/dvl/twist_cov", sampleTwistWithCovariance(i), t + 6);
    writer.write("/mag", sampleMagneticField(i), t + 7);
  }
  ASSERT_TRUE(writer.close());
  ASSERT_GT(writer.chunkPositions().size(), 3u);

  BagReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(path, &error)) << error;
  EXPECT_EQ(reader.notice(), "");  // the index was used
  ASSERT_EQ(reader.topics().size(), 7u);
  for (const auto& topic : reader.topics()) {
    EXPECT_EQ(topic.messages, uint64_t(kEach)) << topic.name;
    EXPECT_EQ(topic.serialization, foreign::Serialization::kRos1);
  }
  EXPECT_EQ(reader.topics()[0].name, "/imu");
  EXPECT_EQ(reader.topics()[0].type, "sensor_msgs/Imu");

  bool ok = false;
  const std::vector<Delivered> got = readAll(reader, &ok, &error);
  ASSERT_TRUE(ok) << error;
  ASSERT_EQ(got.size(), size_t(7 * kEach));
  std::map<std::string, int> seen;
  for (const Delivered& d : got) {
    const int i = seen[d.topic]++;
    if (d.topic == "/imu") expectDecodesTo(d, sampleImu(i));
    if (d.topic == "/cam0/image_raw") expectDecodesTo(d, sampleImage(i));
    if (d.topic == "/cam1/compressed") expectDecodesTo(d, sampleCompressedImage(i));
    if (d.topic == "/depth") expectDecodesTo(d, sampleFluidPressure(i));
    if (d.topic == "/dvl/twist") expectDecodesTo(d, sampleTwistStamped(i));
    if (d.topic == "/dvl/twist_cov") expectDecodesTo(d, sampleTwistWithCovariance(i));
    if (d.topic == "/mag") expectDecodesTo(d, sampleMagneticField(i));
  }
  EXPECT_EQ(got.front().log_time_ns, t0 + 1);
  EXPECT_EQ(got.back().log_time_ns, t0 + (kEach - 1) * 1000000LL + 7);
}

// Two IMUs written in bursts (chunks of one overlap in time those of the other), a third topic
// with the same log times as the first (ties), some messages written late: the reader must give
// the stable sort by log time of the write order, i.e. ties in file order.
TEST_P(RosbagRoundTrip, MessagesComeInLogTimeOrderAcrossChunksAndConnections) {
  const std::string path = deepnav::testing::tempPath(compressionName(GetParam()) + ".bag");
  Ros1BagWriter writer;
  ASSERT_TRUE(writer.open(path, GetParam(), 1500));
  struct Sent {
    std::string topic;
    int64_t t;
    std::vector<uint8_t> data;
  };
  std::vector<Sent> sent;
  uint32_t seq_a = 0, seq_b = 0, seq_c = 0;
  auto put = [&](const std::string& topic, int i, int64_t t, uint32_t* seq) {
    const ros::Imu m = sampleImu(i);
    writer.write(topic, m, t);
    sent.push_back({topic, t, encodeRos1(m, (*seq)++)});
  };
  for (int burst = 0; burst < 4; ++burst) {
    for (int i = 0; i < 20; ++i) put("/imu_a", i, 1000 * (burst * 20 + i), &seq_a);
    for (int i = 0; i < 20; ++i) put("/imu_b", i, 1000 * (burst * 20 + i) + 500, &seq_b);
    for (int i = 0; i < 20; ++i) put("/imu_c", i, 1000 * (burst * 20 + i), &seq_c);
  }
  put("/imu_b", 99, 1, &seq_b);  // late: belongs at the very start
  ASSERT_TRUE(writer.close());
  ASSERT_GT(writer.chunkPositions().size(), 8u);

  BagReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(path, &error)) << error;
  bool ok = false;
  const std::vector<Delivered> got = readAll(reader, &ok, &error);
  ASSERT_TRUE(ok) << error;
  std::stable_sort(sent.begin(), sent.end(), [](const Sent& a, const Sent& b) { return a.t < b.t; });
  ASSERT_EQ(got.size(), sent.size());
  for (size_t i = 0; i < sent.size(); ++i) {
    ASSERT_EQ(got[i].topic, sent[i].topic) << "message " << i;
    ASSERT_EQ(got[i].log_time_ns, sent[i].t) << "message " << i;
    ASSERT_EQ(got[i].data, sent[i].data) << "message " << i;
  }
}

TEST_P(RosbagRoundTrip, CallbackReturningFalseStops) {
  const std::string path = deepnav::testing::tempPath(compressionName(GetParam()) + ".bag");
  Ros1BagWriter writer;
  ASSERT_TRUE(writer.open(path, GetParam(), 500));
  for (int i = 0; i < 30; ++i) writer.write("/depth", sampleFluidPressure(i), 1000 + i);
  ASSERT_TRUE(writer.close());
  BagReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(path, &error)) << error;
  int n = 0;
  EXPECT_TRUE(reader.forEach([&](const foreign::ForeignMessage&) { return ++n < 5; }, &error));
  EXPECT_EQ(n, 5);
}

INSTANTIATE_TEST_SUITE_P(RosbagCompressions, RosbagRoundTrip,
                         ::testing::Values(Compression::kNone, Compression::kBz2,
                                           Compression::kLz4),
                         [](const auto& info) { return compressionName(info.param); });

TEST(RosbagRoundTripEmpty, ClosedBagWithoutMessagesHasNoTopics) {
  const std::string path = deepnav::testing::tempPath("empty.bag");
  Ros1BagWriter writer;
  ASSERT_TRUE(writer.open(path));
  ASSERT_TRUE(writer.close());
  BagReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(path, &error)) << error;
  EXPECT_TRUE(reader.topics().empty());
  bool ok = false;
  EXPECT_TRUE(readAll(reader, &ok, &error).empty());
  EXPECT_TRUE(ok) << error;
}

// A message of a standard type (md5sum right) but too short for it: the container delivers its
// bytes, the decoder refuses them.
TEST(RosbagRoundTripShort, MessageTooShortForItsTypeIsDeliveredButDoesNotDecode) {
  const std::string path = deepnav::testing::tempPath("short.bag");
  Ros1BagWriter writer;
  ASSERT_TRUE(writer.open(path, Compression::kLz4));
  std::vector<uint8_t> imu = encodeRos1(sampleImu(0));
  imu.resize(imu.size() - 8);  // the last covariance element missing
  writer.writeRaw("/imu", Ros1Type<ros::Imu>::kName, Ros1Type<ros::Imu>::kMd5,
                  Ros1Type<ros::Imu>::definition(), imu, 1000);
  ASSERT_TRUE(writer.close());
  BagReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(path, &error)) << error;
  bool ok = false;
  const std::vector<Delivered> got = readAll(reader, &ok, &error);
  ASSERT_TRUE(ok) << error;
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].data, imu);
  ros::Imu decoded;
  EXPECT_FALSE(decodeRos1(got[0].data.data(), got[0].data.size(), &decoded));
}

// The md5sums the reader checks against are those of the standard definitions (the writer's,
// computed separately by the ROS md5 rule).
TEST(RosbagMd5, StandardTableMatchesTheDefinitions) {
  EXPECT_EQ(standardMd5("sensor_msgs/Image"), Ros1Type<ros::Image>::kMd5);
  EXPECT_EQ(standardMd5("sensor_msgs/CompressedImage"), Ros1Type<ros::CompressedImage>::kMd5);
  EXPECT_EQ(standardMd5("sensor_msgs/Imu"), Ros1Type<ros::Imu>::kMd5);
  EXPECT_EQ(standardMd5("sensor_msgs/FluidPressure"), Ros1Type<ros::FluidPressure>::kMd5);
  EXPECT_EQ(standardMd5("sensor_msgs/MagneticField"), Ros1Type<ros::MagneticField>::kMd5);
  EXPECT_EQ(standardMd5("geometry_msgs/TwistStamped"), Ros1Type<ros::TwistStamped>::kMd5);
  EXPECT_EQ(standardMd5("geometry_msgs/TwistWithCovarianceStamped"),
            Ros1Type<ros::TwistWithCovarianceStamped>::kMd5);
  EXPECT_EQ(standardMd5("nav_msgs/Odometry"), "");
}

}  // namespace
}  // namespace deepnav::rosbag
