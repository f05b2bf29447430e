// The reader against damaged files: cut off at many byte positions (as by a crash or power loss
// while recording) and with bytes flipped. It must never crash, return exactly the messages of
// complete, intact chunks, and say what happened with the file name and byte offset.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

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
  std::vector<uint8_t> data;
  size_t chunk;  // index of the chunk the writer put it in
};

using deepnav::testing::tempPath;

std::vector<uint8_t> readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

void writeFile(const std::string& path, const uint8_t* data, size_t size) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  if (size > 0) {
    ASSERT_EQ(std::fwrite(data, 1, size, f), size);
  }
  std::fclose(f);
}

// A recording of three channels in small chunks. Chunks close on size only, so a message's
// chunk is the number of chunks closed before it was written.
std::vector<Sent> writeRecording(const std::string& path, Compression compression) {
  WriterOptions options;
  options.compression = compression;
  options.chunk_size_bytes = 6 * 1024;
  options.chunk_max_duration_ns = ~uint64_t(0);
  Writer writer;
  std::string error;
  EXPECT_TRUE(writer.open(path, options, &error)) << error;
  const uint16_t schema = writer.addSchema("sensor_msgs/msg/Imu", "ros2msg", "float64 x\n");
  const uint16_t channels[3] = {writer.addChannel(schema, "/imu", "cdr"),
                                writer.addChannel(schema, "/dvl", "cdr"),
                                writer.addChannel(0, "/log", "json")};
  std::vector<Sent> sent;
  uint32_t x = 12345;
  for (uint32_t i = 0; i < 1500; ++i) {
    Sent s{channels[i % 3], i / 3, 5'000'000'000ull + i * 2'000'000ull, {}, writer.chunkCount()};
    s.data.resize(20 + i % 60);
    for (uint8_t& b : s.data) {
      x = x * 1103515245u + 12345u;
      b = uint8_t(x >> 24);
    }
    EXPECT_TRUE(writer.write(s.channel_id, s.sequence, s.log_time_ns, s.log_time_ns, s.data.data(),
                             s.data.size()));
    sent.push_back(std::move(s));
  }
  EXPECT_TRUE(writer.close(&error)) << error;
  return sent;
}

struct ReadResult {
  bool opened = false;
  bool read_ok = false;
  std::string error;
  std::vector<Sent> messages;
};

ReadResult readBack(const std::string& path, Reader& reader, bool log_time_order = false) {
  ReadResult r;
  r.opened = reader.open(path, &r.error);
  if (!r.opened) return r;
  const auto collect = [&](const MessageView& m) {
    r.messages.push_back(Sent{m.channel_id, m.sequence, m.log_time_ns,
                              std::vector<uint8_t>(m.data, m.data + m.size), 0});
  };
  r.read_ok = log_time_order ? reader.readAllInLogTimeOrder(collect) : reader.readAll(collect);
  if (!r.read_ok) r.error = reader.error();
  return r;
}

bool sameMessage(const Sent& a, const Sent& b) {
  return a.channel_id == b.channel_id && a.sequence == b.sequence &&
         a.log_time_ns == b.log_time_ns && a.data == b.data;
}

class McapTruncated : public ::testing::TestWithParam<Compression> {};

TEST_P(McapTruncated, ReturnsExactlyTheMessagesOfCompleteChunksAtEveryCut) {
  // GIVEN a complete recording and where each of its chunks ends
  const std::string path = tempPath("full.mcap");
  const std::string cut_path = tempPath("cut.mcap");
  const std::vector<Sent> sent = writeRecording(path, GetParam());
  const std::vector<uint8_t> bytes = readFile(path);
  std::vector<uint64_t> chunk_end;
  {
    Reader full;
    std::string error;
    ASSERT_TRUE(full.open(path, &error)) << error;
    for (const ChunkInfo& c : full.chunks())
      chunk_end.push_back(c.chunk_start_offset + c.chunk_length);
    ASSERT_GT(chunk_end.size(), 5u);
    ASSERT_TRUE(std::is_sorted(chunk_end.begin(), chunk_end.end()));
  }

  // WHEN the file is cut every 997 bytes (and just before the end)
  std::vector<size_t> cuts;
  for (size_t cut = 0; cut < bytes.size(); cut += 997) cuts.push_back(cut);
  cuts.push_back(bytes.size() - 1);
  for (const size_t cut : cuts) {
    SCOPED_TRACE("cut at byte " + std::to_string(cut) + " of " + std::to_string(bytes.size()));
    writeFile(cut_path, bytes.data(), cut);
    const size_t complete_chunks =
        size_t(std::upper_bound(chunk_end.begin(), chunk_end.end(), cut) - chunk_end.begin());
    std::vector<const Sent*> expected;
    for (const Sent& s : sent) {
      if (s.chunk < complete_chunks) expected.push_back(&s);
    }

    Reader reader;
    const ReadResult got = readBack(cut_path, reader);
    // THEN a file cut inside its first bytes is refused with a message naming it...
    if (!got.opened) {
      EXPECT_TRUE(expected.empty());
      EXPECT_NE(got.error.find(cut_path), std::string::npos) << got.error;
      EXPECT_NE(got.error.find("byte"), std::string::npos) << got.error;
      continue;
    }
    // ...and any other cut gives every message of every complete chunk, in order, and no other
    ASSERT_TRUE(got.read_ok) << got.error;
    EXPECT_TRUE(reader.truncated());
    ASSERT_EQ(got.messages.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
      ASSERT_TRUE(sameMessage(got.messages[i], *expected[i])) << "message " << i;
    }
    EXPECT_EQ(reader.chunks().size(), complete_chunks);
    EXPECT_EQ(reader.skippedChunks(), 0u);
    ASSERT_FALSE(reader.warnings().empty());
    const std::string& warning = reader.warnings().back();
    EXPECT_NE(warning.find("recording " + cut_path + " cut off after " +
                           std::to_string(complete_chunks) + " complete chunks"),
              std::string::npos)
        << warning;
    if (!expected.empty()) {
      EXPECT_NE(warning.find("last message at t="), std::string::npos) << warning;
    }

    // AND log-time order over the same file gives the same messages
    Reader sorted_reader;
    EXPECT_EQ(readBack(cut_path, sorted_reader, true).messages.size(), expected.size());
  }
  std::filesystem::remove(path);
  std::filesystem::remove(cut_path);
}

TEST_P(McapTruncated, CorruptBytesGiveAnErrorOrWarningNeverACrashOrWrongData) {
  // GIVEN a complete recording with CRCs
  const std::string path = tempPath("full.mcap");
  const std::string bad_path = tempPath("bad.mcap");
  const std::vector<Sent> sent = writeRecording(path, GetParam());
  const std::vector<uint8_t> bytes = readFile(path);

  // WHEN one byte at a time is flipped, all over the file
  std::vector<size_t> positions;
  for (size_t at = 0; at < bytes.size(); at += 241) positions.push_back(at);
  for (size_t at = bytes.size() - 64; at < bytes.size(); ++at) positions.push_back(at);
  for (const size_t at : positions) {
    SCOPED_TRACE("byte " + std::to_string(at) + " flipped");
    std::vector<uint8_t> bad = bytes;
    bad[at] ^= 0x5A;
    writeFile(bad_path, bad.data(), bad.size());
    Reader reader;
    const ReadResult got = readBack(bad_path, reader);
    // THEN the reader reports it: an error naming the file and a byte offset, or a warning
    const std::string problem = !got.opened || !got.read_ok ? got.error
                                : reader.warnings().empty() ? std::string()
                                                            : reader.warnings().front();
    EXPECT_NE(problem.find(bad_path), std::string::npos) << "undetected: " << problem;
    EXPECT_NE(problem.find("byte"), std::string::npos) << problem;
    // AND whatever messages it returns are ones that were written, unchanged
    size_t next = 0;
    for (const Sent& m : got.messages) {
      while (next < sent.size() && !sameMessage(sent[next], m)) ++next;
      ASSERT_LT(next, sent.size()) << "a message that was never written came back";
    }
  }
  std::filesystem::remove(path);
  std::filesystem::remove(bad_path);
}

INSTANTIATE_TEST_SUITE_P(McapEveryCompression, McapTruncated, everyCompression(), compressionTestName);

TEST(McapCorruptChunk, ABadCrcSkipsOnlyThatChunkAndCountsIt) {
  // GIVEN an uncompressed recording whose second chunk has one payload byte changed
  const std::string path = tempPath("crc.mcap");
  const std::vector<Sent> sent = writeRecording(path, Compression::kNone);
  std::vector<uint8_t> bytes = readFile(path);
  ChunkInfo second;
  {
    Reader reader;
    std::string error;
    ASSERT_TRUE(reader.open(path, &error)) << error;
    second = reader.chunks().at(1);
  }
  bytes[second.chunk_start_offset + second.chunk_length - 10] ^= 0xFF;
  writeFile(path, bytes.data(), bytes.size());

  // WHEN it is read
  Reader reader;
  const ReadResult got = readBack(path, reader);

  // THEN every other chunk's messages come back and the bad chunk is counted and reported
  ASSERT_TRUE(got.opened && got.read_ok) << got.error;
  EXPECT_EQ(reader.skippedChunks(), 1u);
  size_t expected = 0;
  for (const Sent& s : sent) expected += s.chunk != 1 ? 1 : 0;
  EXPECT_EQ(got.messages.size(), expected);
  bool crc_warning = false;
  for (const std::string& w : reader.warnings()) {
    crc_warning |= w.find("CRC mismatch") != std::string::npos &&
                   w.find("byte " + std::to_string(second.chunk_start_offset)) != std::string::npos;
  }
  EXPECT_TRUE(crc_warning);
  std::filesystem::remove(path);
}

TEST(McapCorruptChunk, ALengthPastTheDataSectionIsAnErrorWithItsOffset) {
  const std::string path = tempPath("length.mcap");
  writeRecording(path, Compression::kZstd);
  std::vector<uint8_t> bytes = readFile(path);
  uint64_t chunk_at = 0;
  {
    Reader reader;
    std::string error;
    ASSERT_TRUE(reader.open(path, &error)) << error;
    chunk_at = reader.chunks().at(2).chunk_start_offset;
  }
  bytes[chunk_at + 1 + 6] = 0x7F;  // record length becomes enormous
  writeFile(path, bytes.data(), bytes.size());
  Reader reader;
  const ReadResult got = readBack(path, reader);
  ASSERT_TRUE(got.opened);
  EXPECT_FALSE(got.read_ok);
  EXPECT_NE(got.error.find(path), std::string::npos) << got.error;
  EXPECT_NE(got.error.find("at byte " + std::to_string(chunk_at)), std::string::npos) << got.error;
  std::filesystem::remove(path);
}

TEST(McapTruncatedSummary, ACutAfterTheDataSectionKeepsEveryChunk) {
  const std::string path = tempPath("summarycut.mcap");
  const std::vector<Sent> sent = writeRecording(path, Compression::kLz4);
  const std::vector<uint8_t> bytes = readFile(path);
  writeFile(path, bytes.data(), bytes.size() - 20);  // footer gone, summary partly there
  Reader reader;
  const ReadResult got = readBack(path, reader);
  ASSERT_TRUE(got.opened && got.read_ok) << got.error;
  EXPECT_TRUE(reader.truncated());
  EXPECT_EQ(got.messages.size(), sent.size());
  EXPECT_EQ(reader.statistics().message_count, sent.size());  // rebuilt from message indexes
  EXPECT_EQ(reader.channels().size(), 3u);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace deepnav::mcap
