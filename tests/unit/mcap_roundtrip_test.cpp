// Writer -> Reader round trips: every compression, schemas/channels/statistics/metadata, file
// order and log-time order, and the three ways a chunk closes (size, duration, flush()).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "drivers/mcap/crc32.h"
#include "drivers/mcap/reader.h"
#include "drivers/mcap/writer.h"
#include "tests/support/temp_path.h"
#include "tests/support/mcap_test_util.h"

namespace deepnav::mcap {
namespace {

struct Sent {
  uint16_t channel_id;
  uint32_t sequence;
  uint64_t log_time_ns;
  uint64_t publish_time_ns;
  std::vector<uint8_t> data;
};

struct Received {
  uint16_t channel_id;
  uint32_t sequence;
  uint64_t log_time_ns;
  uint64_t publish_time_ns;
  std::vector<uint8_t> data;
};

using deepnav::testing::tempPath;

// Payloads that compress somewhat, like sensor data: a counter pattern with noise.
std::vector<uint8_t> payload(uint32_t i, size_t size) {
  std::vector<uint8_t> p(size);
  uint32_t x = i * 2654435761u + 1;
  for (size_t k = 0; k < size; ++k) {
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    p[k] = (k % 4 == 0) ? uint8_t(x) : uint8_t(k + i);
  }
  return p;
}

std::vector<Received> readAllMessages(Reader& reader, bool log_time_order = false) {
  std::vector<Received> out;
  const auto collect = [&](const MessageView& m) {
    out.push_back(Received{m.channel_id, m.sequence, m.log_time_ns, m.publish_time_ns,
                           std::vector<uint8_t>(m.data, m.data + m.size)});
  };
  const bool ok = log_time_order ? reader.readAllInLogTimeOrder(collect) : reader.readAll(collect);
  EXPECT_TRUE(ok) << reader.error();
  return out;
}

// Four channels over two schemas at different rates; log times interleave and a few arrive late.
std::vector<Sent> makeMessages(size_t count) {
  std::vector<Sent> sent;
  uint32_t sequence[5] = {};
  for (size_t i = 0; i < count; ++i) {
    const uint16_t channel = uint16_t(1 + (i % 7 == 0 ? 3 : i % 3));
    uint64_t t_ns = 1'000'000'000ull + i * 1'000'000ull;
    if (i % 50 == 49) t_ns -= 3'000'000;  // a late sample, out of log-time order
    const size_t size = channel == 4 ? 2000 + i % 500 : 40 + i % 90;
    sent.push_back(Sent{channel, sequence[channel]++, t_ns, t_ns + 17, payload(uint32_t(i), size)});
  }
  return sent;
}

void expectSame(const std::vector<Received>& got, const std::vector<Sent>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (size_t i = 0; i < got.size(); ++i) {
    ASSERT_EQ(got[i].channel_id, want[i].channel_id) << "message " << i;
    ASSERT_EQ(got[i].sequence, want[i].sequence) << "message " << i;
    ASSERT_EQ(got[i].log_time_ns, want[i].log_time_ns) << "message " << i;
    ASSERT_EQ(got[i].publish_time_ns, want[i].publish_time_ns) << "message " << i;
    ASSERT_EQ(got[i].data, want[i].data) << "message " << i;
  }
}

class McapRoundTrip : public ::testing::TestWithParam<Compression> {};

TEST(McapCrc32, MatchesTheStandardCheckValue) {
  const std::string check = "123456789";
  EXPECT_EQ(crc32(reinterpret_cast<const uint8_t*>(check.data()), check.size()), 0xCBF43926u);
  // Incremental use gives the same result as one pass.
  const uint8_t* p = reinterpret_cast<const uint8_t*>(check.data());
  EXPECT_EQ(crc32Update(crc32(p, 4), p + 4, 5), 0xCBF43926u);
}

TEST_P(McapRoundTrip, MessagesSchemasChannelsAndStatisticsSurvive) {
  // GIVEN a file written with several chunks, four channels, two schemas and a metadata record
  const std::string path = tempPath("roundtrip.mcap");
  WriterOptions options;
  options.compression = GetParam();
  options.chunk_size_bytes = 32 * 1024;
  Writer writer;
  std::string error;
  ASSERT_TRUE(writer.open(path, options, &error)) << error;
  const uint16_t imu_schema = writer.addSchema("sensor_msgs/msg/Imu", "ros2msg", "float64 x\n");
  const uint16_t image_schema =
      writer.addSchema("sensor_msgs/msg/Image", "ros2msg", "uint8[] data\n");
  ASSERT_EQ(imu_schema, 1);
  ASSERT_EQ(image_schema, 2);
  const std::map<std::string, std::string> qos = {{"offered_qos_profiles", ""}};
  ASSERT_EQ(writer.addChannel(imu_schema, "/imu", "cdr", qos), 1);
  ASSERT_EQ(writer.addChannel(imu_schema, "/imu2", "cdr"), 2);
  ASSERT_EQ(writer.addChannel(imu_schema, "/depth", "cdr"), 3);
  ASSERT_EQ(writer.addChannel(image_schema, "/camera/left", "cdr", {{"a", "1"}, {"b", "2"}}), 4);
  ASSERT_EQ(writer.addChannel(0, "/unused", "json"), 5);
  ASSERT_TRUE(writer.writeMetadata("vehicle", {{"name", "rov1"}, {"serial", "42"}}));
  const std::vector<Sent> sent = makeMessages(6000);
  for (const Sent& s : sent) {
    ASSERT_TRUE(writer.write(s.channel_id, s.sequence, s.log_time_ns, s.publish_time_ns,
                             s.data.data(), s.data.size()))
        << writer.lastError();
  }
  ASSERT_TRUE(writer.close(&error)) << error;

  // WHEN it is read back
  Reader reader;
  ASSERT_TRUE(reader.open(path, &error)) << error;

  // THEN header, schemas, channels, metadata and statistics are as written
  EXPECT_EQ(reader.header().profile, "ros2");
  EXPECT_EQ(reader.header().library, "deepnav");
  EXPECT_TRUE(reader.hasSummary());
  EXPECT_FALSE(reader.truncated());
  ASSERT_EQ(reader.schemas().size(), 2u);
  EXPECT_EQ(reader.schema(2)->name, "sensor_msgs/msg/Image");
  EXPECT_EQ(reader.schema(2)->encoding, "ros2msg");
  EXPECT_EQ(std::string(reader.schema(2)->data.begin(), reader.schema(2)->data.end()),
            "uint8[] data\n");
  ASSERT_EQ(reader.channels().size(), 5u);
  EXPECT_EQ(reader.channel(1)->topic, "/imu");
  EXPECT_EQ(reader.channel(1)->metadata, qos);
  EXPECT_EQ(reader.channel(4)->schema_id, 2);
  EXPECT_EQ(reader.channel(4)->metadata.at("b"), "2");
  EXPECT_EQ(reader.channel(4)->metadata.count("offered_qos_profiles"), 1u);  // ros2 profile
  EXPECT_EQ(reader.channel(5)->message_encoding, "json");
  ASSERT_EQ(reader.metadata().size(), 1u);
  EXPECT_EQ(reader.metadata()[0].name, "vehicle");
  EXPECT_EQ(reader.metadata()[0].metadata.at("serial"), "42");

  const Statistics& stats = reader.statistics();
  EXPECT_EQ(stats.message_count, sent.size());
  EXPECT_EQ(stats.schema_count, 2);
  EXPECT_EQ(stats.channel_count, 5u);
  EXPECT_EQ(stats.metadata_count, 1u);
  EXPECT_EQ(stats.chunk_count, reader.chunks().size());
  EXPECT_GT(stats.chunk_count, 5u);
  const auto [first, last] = std::minmax_element(
      sent.begin(), sent.end(),
      [](const Sent& a, const Sent& b) { return a.log_time_ns < b.log_time_ns; });
  EXPECT_EQ(stats.message_start_time_ns, first->log_time_ns);
  EXPECT_EQ(stats.message_end_time_ns, last->log_time_ns);
  std::map<uint16_t, uint64_t> counts;
  for (const Sent& s : sent) ++counts[s.channel_id];
  counts[5] = 0;
  EXPECT_EQ(stats.channel_message_counts, counts);
  for (const ChunkInfo& c : reader.chunks()) {
    EXPECT_EQ(c.compression, std::string(compressionName(GetParam())));
    EXPECT_GT(c.message_index_length, 0u);
  }

  // AND every message comes back in file order, bit for bit
  expectSame(readAllMessages(reader), sent);
  EXPECT_TRUE(reader.warnings().empty()) << reader.warnings().front();
  EXPECT_EQ(reader.skippedChunks(), 0u);

  // AND in log-time order they are the same messages, sorted (stable for equal times)
  std::vector<Sent> by_time = sent;
  std::stable_sort(by_time.begin(), by_time.end(),
                   [](const Sent& a, const Sent& b) { return a.log_time_ns < b.log_time_ns; });
  expectSame(readAllMessages(reader, true), by_time);
  std::filesystem::remove(path);
}

INSTANTIATE_TEST_SUITE_P(McapEveryCompression, McapRoundTrip, everyCompression(), compressionTestName);

TEST(McapWriter, ClosesAChunkBeforeItSpansMoreThanTheMaxDuration) {
  // GIVEN a chunk size that is never reached and a 100 ms duration limit
  const std::string path = tempPath("duration.mcap");
  WriterOptions options;
  options.chunk_size_bytes = 64 * 1024 * 1024;
  options.chunk_max_duration_ns = 100'000'000;
  Writer writer;
  std::string error;
  ASSERT_TRUE(writer.open(path, options, &error)) << error;
  const uint16_t channel = writer.addChannel(0, "/depth", "cdr");
  // WHEN 100 messages arrive 10 ms apart
  const uint8_t byte = 7;
  for (uint32_t i = 0; i < 100; ++i) {
    ASSERT_TRUE(writer.write(channel, i, i * 10'000'000ull, i * 10'000'000ull, &byte, 1));
  }
  ASSERT_TRUE(writer.close(&error)) << error;
  // THEN chunks hold 0..100 ms, 110..210 ms, ...: 11 messages each, never over 100 ms
  Reader reader;
  ASSERT_TRUE(reader.open(path, &error)) << error;
  ASSERT_EQ(reader.chunks().size(), 10u);
  for (const ChunkInfo& c : reader.chunks()) {
    EXPECT_LE(c.message_end_time_ns - c.message_start_time_ns, 100'000'000u);
  }
  EXPECT_EQ(reader.chunks()[1].message_start_time_ns, 110'000'000u);
  EXPECT_EQ(readAllMessages(reader).size(), 100u);
  std::filesystem::remove(path);
}

TEST(McapWriter, ClosesAChunkOnceItReachesTheSizeLimit) {
  const std::string path = tempPath("size.mcap");
  WriterOptions options;
  options.chunk_size_bytes = 4096;
  Writer writer;
  std::string error;
  ASSERT_TRUE(writer.open(path, options, &error)) << error;
  const uint16_t channel = writer.addChannel(0, "/blob", "cdr");
  const std::vector<uint8_t> data(1000, 0xAB);
  for (uint32_t i = 0; i < 40; ++i) {
    ASSERT_TRUE(writer.write(channel, i, 1000 + i, 1000 + i, data.data(), data.size()));
  }
  ASSERT_TRUE(writer.close(&error)) << error;
  Reader reader;
  ASSERT_TRUE(reader.open(path, &error)) << error;
  // 1031-byte message records: the 4th one crosses 4096 bytes and closes the chunk.
  ASSERT_EQ(reader.chunks().size(), 10u);
  for (const ChunkInfo& c : reader.chunks()) EXPECT_EQ(c.uncompressed_size, 4u * 1031u);
  std::filesystem::remove(path);
}

TEST(McapWriter, FlushPutsTheOpenChunkOnDiskSoACrashKeepsIt) {
  // GIVEN a writer with three messages, flushed, and two more not yet flushed
  const std::string path = tempPath("flush.mcap");
  Writer writer;
  std::string error;
  ASSERT_TRUE(writer.open(path, WriterOptions{}, &error)) << error;
  const uint16_t channel =
      writer.addChannel(writer.addSchema("s", "ros2msg", "int32 a\n"), "/a", "cdr");
  const uint8_t byte = 1;
  for (uint32_t i = 0; i < 3; ++i) ASSERT_TRUE(writer.write(channel, i, i, i, &byte, 1));
  ASSERT_TRUE(writer.flush());
  EXPECT_EQ(writer.chunkCount(), 1u);
  ASSERT_TRUE(writer.flush());  // nothing open: no empty chunk
  EXPECT_EQ(writer.chunkCount(), 1u);
  for (uint32_t i = 3; i < 5; ++i) ASSERT_TRUE(writer.write(channel, i, i, i, &byte, 1));

  // WHEN the file is read while the writer is still open (as after a kill -9)
  {
    Reader reader;
    ASSERT_TRUE(reader.open(path, &error)) << error;
    // THEN the flushed chunk is there, and the reader says the file was cut off
    EXPECT_TRUE(reader.truncated());
    EXPECT_EQ(readAllMessages(reader).size(), 3u);
    ASSERT_EQ(reader.channels().size(), 1u);
    EXPECT_EQ(reader.channel(channel)->topic, "/a");
  }
  ASSERT_TRUE(writer.close(&error)) << error;
  Reader reader;
  ASSERT_TRUE(reader.open(path, &error)) << error;
  EXPECT_FALSE(reader.truncated());
  EXPECT_EQ(reader.chunks().size(), 2u);
  EXPECT_EQ(readAllMessages(reader).size(), 5u);
  std::filesystem::remove(path);
}

TEST(McapWriter, EmptyRecordingIsValid) {
  const std::string path = tempPath("empty.mcap");
  Writer writer;
  std::string error;
  ASSERT_TRUE(writer.open(path, WriterOptions{}, &error)) << error;
  ASSERT_TRUE(writer.close(&error)) << error;
  Reader reader;
  ASSERT_TRUE(reader.open(path, &error)) << error;
  EXPECT_FALSE(reader.truncated());
  EXPECT_EQ(reader.statistics().message_count, 0u);
  EXPECT_TRUE(reader.chunks().empty());
  EXPECT_TRUE(readAllMessages(reader).empty());
  std::filesystem::remove(path);
}

TEST(McapWriter, WithoutCrcsStillRoundTrips) {
  const std::string path = tempPath("nocrc.mcap");
  WriterOptions options;
  options.enable_crcs = false;
  options.chunk_size_bytes = 2048;
  Writer writer;
  std::string error;
  ASSERT_TRUE(writer.open(path, options, &error)) << error;
  const uint16_t channel = writer.addChannel(0, "/x", "cdr");
  const std::vector<Sent> sent = [&] {
    std::vector<Sent> v;
    for (uint32_t i = 0; i < 300; ++i)
      v.push_back(Sent{channel, i, i * 5u, i * 5u, payload(i, 33)});
    return v;
  }();
  for (const Sent& s : sent) {
    ASSERT_TRUE(writer.write(s.channel_id, s.sequence, s.log_time_ns, s.publish_time_ns,
                             s.data.data(), s.data.size()));
  }
  ASSERT_TRUE(writer.close(&error)) << error;
  Reader reader;
  ASSERT_TRUE(reader.open(path, &error)) << error;
  expectSame(readAllMessages(reader), sent);
  EXPECT_TRUE(reader.warnings().empty());
  std::filesystem::remove(path);
}

TEST(McapWriter, ReportsErrorsInsteadOfThrowing) {
  Writer writer;
  std::string error;
  EXPECT_FALSE(writer.open("/nonexistent-dir/x.mcap", WriterOptions{}, &error));
  EXPECT_NE(error.find("/nonexistent-dir/x.mcap"), std::string::npos) << error;
  EXPECT_EQ(writer.addSchema("a", "b", "c"), 0);  // not open
  const uint8_t byte = 0;
  EXPECT_FALSE(writer.write(1, 0, 0, 0, &byte, 1));

  const std::string path = tempPath("errors.mcap");
  ASSERT_TRUE(writer.open(path, WriterOptions{}, &error)) << error;
  EXPECT_EQ(writer.addChannel(9, "/bad", "cdr"), 0);  // unknown schema
  EXPECT_FALSE(writer.write(3, 0, 0, 0, &byte, 1));   // unknown channel
  EXPECT_NE(writer.lastError().find("unknown channel"), std::string::npos);
  EXPECT_TRUE(writer.close(&error)) << error;
  std::filesystem::remove(path);
}

TEST(McapReader, RejectsFilesThatAreNotMcap) {
  const std::string path = tempPath("garbage.mcap");
  std::string error;
  {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    std::fputs("this is not an mcap file at all, just text", f);
    std::fclose(f);
  }
  Reader reader;
  EXPECT_FALSE(reader.open(path, &error));
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_NE(error.find("byte 0"), std::string::npos) << error;
  EXPECT_FALSE(reader.open(tempPath("missing.mcap"), &error));
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace deepnav::mcap
