// ROS 1 bags the reader must survive: a recorder killed before closing the bag (no index, last
// chunk unfinished), files cut at many byte offsets, and malformed files (wrong magic or version,
// unknown compression, a missing header field, a wrong decompressed size, lengths past the end of
// the file, a type with another layout). Never a crash; one error naming the file, the byte and
// the field; the messages before a cut are delivered.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string_view>

#include "drivers/rosbag/bag_reader.h"
#include "tests/support/ros1_bag_writer.h"
#include "tests/unit/rosbag_test_util.h"

namespace deepnav::rosbag {
namespace {

using testsupport::encodeRos1;
using testsupport::Ros1BagWriter;
using Compression = Ros1BagWriter::Compression;
constexpr auto compressionName = &Ros1BagWriter::compressionName;
using namespace testing_util;

constexpr uint64_t kChunksStart = 13 + 4096;  // magic + the padded bag header record

struct Sent {
  std::string topic;
  int64_t t;
  std::vector<uint8_t> data;
};

// Two topics over several chunks; returns what was written, in log-time (= write) order.
std::vector<Sent> writeBag(Ros1BagWriter* writer, int n = 24) {
  std::vector<Sent> sent;
  for (int i = 0; i < n; ++i) {
    const ros::Imu imu = sampleImu(i);
    writer->write("/imu", imu, 1000 * i);
    sent.push_back({"/imu", 1000 * i, encodeRos1(imu, uint32_t(i))});
    const ros::FluidPressure p = sampleFluidPressure(i);
    writer->write("/depth", p, 1000 * i + 1);
    sent.push_back({"/depth", 1000 * i + 1, encodeRos1(p, uint32_t(i))});
  }
  return sent;
}

void replaceOnce(std::vector<uint8_t>* bytes, uint64_t from, std::string_view what,
                 std::string_view with) {
  ASSERT_EQ(what.size(), with.size());
  const auto it = std::search(bytes->begin() + std::ptrdiff_t(from), bytes->end(), what.begin(),
                              what.end());
  ASSERT_NE(it, bytes->end()) << what;
  std::copy(with.begin(), with.end(), it);
}

void expectOpenFails(const std::string& path, const std::vector<std::string>& parts) {
  BagReader reader;
  std::string error;
  EXPECT_FALSE(reader.open(path, &error));
  EXPECT_NE(error.find(path), std::string::npos) << error;
  for (const auto& p : parts) EXPECT_NE(error.find(p), std::string::npos) << error << " / " << p;
}

class RosbagDamaged : public ::testing::TestWithParam<Compression> {};

TEST_P(RosbagDamaged, BagNotClosedIsReadByScanningItsChunks) {
  const std::string path = deepnav::testing::tempPath(compressionName(GetParam()) + ".bag");
  Ros1BagWriter writer;
  ASSERT_TRUE(writer.open(path, GetParam(), 700));
  const std::vector<Sent> sent = writeBag(&writer);
  ASSERT_TRUE(writer.closeAsCrashed(false));
  BagReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(path, &error)) << error;
  EXPECT_NE(reader.notice().find("index_pos is 0"), std::string::npos) << reader.notice();
  ASSERT_EQ(reader.topics().size(), 2u);
  EXPECT_EQ(reader.topics()[0].messages, sent.size() / 2);
  bool ok = false;
  const std::vector<Delivered> got = readAll(reader, &ok, &error);
  EXPECT_TRUE(ok) << error;
  ASSERT_EQ(got.size(), sent.size());
  for (size_t i = 0; i < sent.size(); ++i) EXPECT_EQ(got[i].data, sent[i].data);
}

TEST_P(RosbagDamaged, UnfinishedLastChunk) {
  const std::string path = deepnav::testing::tempPath(compressionName(GetParam()) + ".bag");
  Ros1BagWriter writer;
  ASSERT_TRUE(writer.open(path, GetParam(), 700));
  const std::vector<Sent> sent = writeBag(&writer, 25);
  ASSERT_TRUE(writer.closeAsCrashed(true));
  const uint64_t last = writer.chunkPositions().back();
  BagReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(path, &error)) << error;
  bool ok = false;
  const std::vector<Delivered> got = readAll(reader, &ok, &error);
  if (GetParam() == Compression::kNone) {
    // Its records follow the placeholder header whole: all read, the notice says so.
    EXPECT_TRUE(ok) << error;
    EXPECT_EQ(got.size(), sent.size());
    EXPECT_NE(reader.notice().find("never finished"), std::string::npos) << reader.notice();
  } else {
    // A compressed stream without its sizes cannot be read: the earlier chunks are delivered.
    EXPECT_FALSE(ok);
    EXPECT_NE(error.find(path + ": byte " + std::to_string(last)), std::string::npos) << error;
    EXPECT_NE(error.find("never finished"), std::string::npos) << error;
    EXPECT_GT(got.size(), 0u);
    EXPECT_LT(got.size(), sent.size());
  }
  for (size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i].data, sent[i].data);
}

// Cut at ~300 offsets spread over the file and at every chunk boundary (and one byte on either
// side). Before the end of the bag header: open fails. After: the messages of every chunk before
// the cut come out, in order, intact; if any message is missing forEach says so with the file and
// byte; a cut in the index section loses nothing.
TEST_P(RosbagDamaged, CutAtManyOffsets) {
  const std::string full = deepnav::testing::tempPath(compressionName(GetParam()) + "_full.bag");
  Ros1BagWriter writer;
  ASSERT_TRUE(writer.open(full, GetParam(), 700));
  const std::vector<Sent> sent = writeBag(&writer);
  ASSERT_TRUE(writer.close());
  const std::vector<uint8_t> bytes = readBytes(full);
  const std::vector<uint64_t>& chunks = writer.chunkPositions();
  ASSERT_GE(chunks.size(), 4u);

  std::vector<uint64_t> cuts;
  for (uint64_t c = 0; c < bytes.size(); c += 1 + bytes.size() / 300) cuts.push_back(c);
  for (uint64_t p : chunks) cuts.insert(cuts.end(), {p - 1, p, p + 1, p + 30});
  cuts.insert(cuts.end(), {kChunksStart - 1, kChunksStart, writer.indexPos(),
                           writer.indexPos() + 1, bytes.size() - 1});
  const std::string path = deepnav::testing::tempPath(compressionName(GetParam()) + "_cut.bag");
  for (uint64_t cut : cuts) {
    SCOPED_TRACE("cut at byte " + std::to_string(cut));
    writeBytes(path, bytes.data(), size_t(cut));
    BagReader reader;
    std::string error;
    if (cut < kChunksStart) {
      EXPECT_FALSE(reader.open(path, &error));
      EXPECT_NE(error.find(path + ": byte "), std::string::npos) << error;
      continue;
    }
    ASSERT_TRUE(reader.open(path, &error)) << error;
    bool ok = false;
    const std::vector<Delivered> got = readAll(reader, &ok, &error);
    ASSERT_LE(got.size(), sent.size());
    // Whole chunks before the cut: chunk k is whole once chunk k+1 (or the index) starts.
    size_t whole = 0;
    size_t in_whole_chunks = 0;
    for (size_t k = 0; k < chunks.size(); ++k) {
      const uint64_t next = k + 1 < chunks.size() ? chunks[k + 1] : writer.indexPos();
      if (next <= cut) {
        whole = k + 1;
        in_whole_chunks += writer.chunkMessageCounts()[k];
      }
    }
    if (cut >= writer.indexPos()) {
      EXPECT_TRUE(ok) << error;
      EXPECT_EQ(got.size(), sent.size());
    }
    if (got.size() < sent.size()) {
      EXPECT_FALSE(ok);
      EXPECT_NE(error.find(path + ": byte "), std::string::npos) << error;
    }
    // Delivered: a prefix of what was written (each chunk holds consecutive messages).
    for (size_t i = 0; i < got.size(); ++i) {
      ASSERT_EQ(got[i].topic, sent[i].topic) << i;
      ASSERT_EQ(got[i].log_time_ns, sent[i].t) << i;
      ASSERT_EQ(got[i].data, sent[i].data) << i;
    }
    EXPECT_GE(got.size(), in_whole_chunks) << whole << " whole chunks";
  }
}

INSTANTIATE_TEST_SUITE_P(RosbagCompressions, RosbagDamaged,
                         ::testing::Values(Compression::kNone, Compression::kBz2,
                                           Compression::kLz4),
                         [](const auto& info) { return compressionName(info.param); });

class RosbagMalformed : public ::testing::Test {
 protected:
  // A closed, valid bag (bz2) and its bytes, to be damaged.
  void SetUp() override {
    path_ = deepnav::testing::tempPath("bag.bag");
    ASSERT_TRUE(writer_.open(path_, Compression::kBz2, 700));
    writeBag(&writer_);
    ASSERT_TRUE(writer_.close());
    bytes_ = readBytes(path_);
  }
  void save() { writeBytes(path_, bytes_.data(), bytes_.size()); }

  std::string path_;
  Ros1BagWriter writer_;
  std::vector<uint8_t> bytes_;
};

TEST_F(RosbagMalformed, NotABag) {
  const std::string text = "hello, this is not a bag\n";
  writeBytes(path_, reinterpret_cast<const uint8_t*>(text.data()), text.size());
  expectOpenFails(path_, {": byte 0: ", "not a ROS bag"});
  writeBytes(path_, nullptr, 0);
  expectOpenFails(path_, {": byte 0: ", "not a ROS bag"});
}

TEST_F(RosbagMalformed, OtherFormatVersion) {
  replaceOnce(&bytes_, 0, "#ROSBAG V2.0", "#ROSBAG V1.2");
  save();
  expectOpenFails(path_, {"version '1.2'", "reads 2.0"});
}

TEST_F(RosbagMalformed, BagHeaderFieldMissing) {
  replaceOnce(&bytes_, 0, "index_pos=", "index_pod=");
  save();
  expectOpenFails(path_, {": byte 13: ", "bag header record", "'index_pos' is missing"});
}

// The n-th occurrence of `what` at or after `from`.
std::vector<uint8_t>::iterator findNth(std::vector<uint8_t>* bytes, uint64_t from,
                                       std::string_view what, int n) {
  auto it = bytes->begin() + std::ptrdiff_t(from);
  for (int i = 0; i <= n; ++i) {
    if (i > 0) ++it;
    it = std::search(it, bytes->end(), what.begin(), what.end());
    if (it == bytes->end()) break;
  }
  return it;
}

TEST_F(RosbagMalformed, DamagedIndexFallsBackToScanning) {
  const auto it = findNth(&bytes_, writer_.indexPos(), "chunk_pos=", 0);
  ASSERT_NE(it, bytes_.end());
  *(it + 8) = 'z';  // "chunk_poz=": the chunk info lacks its chunk_pos
  save();
  BagReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(path_, &error)) << error;
  EXPECT_NE(reader.notice().find("index not used"), std::string::npos) << reader.notice();
  EXPECT_NE(reader.notice().find("'chunk_pos' is missing"), std::string::npos) << reader.notice();
  bool ok = false;
  const std::vector<Delivered> got = readAll(reader, &ok, &error);
  EXPECT_TRUE(ok) << error;
  EXPECT_EQ(got.size(), 48u);
}

TEST_F(RosbagMalformed, ChunkInfoTimesThatLieAreAnError) {
  // Chunk 1's start_time moved to 1 s, after all its messages (which are in the first 24 us).
  const auto it = findNth(&bytes_, writer_.indexPos(), "start_time=", 1);
  ASSERT_NE(it, bytes_.end());
  *(it + 11) = 1;
  save();
  BagReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(path_, &error)) << error;
  bool ok = true;
  readAll(reader, &ok, &error);
  EXPECT_FALSE(ok);
  EXPECT_NE(error.find(path_ + ": byte " + std::to_string(writer_.chunkPositions()[1]) + ": "),
            std::string::npos)
      << error;
  EXPECT_NE(error.find("the index is inconsistent"), std::string::npos) << error;
}

TEST_F(RosbagMalformed, EncryptedBagIsRefused) {
  // rosbag's encrypted bags carry an 'encryptor' field in the bag header: put one in place of
  // chunk_count (same field length, 16 bytes).
  const auto it = std::search(bytes_.begin(), bytes_.end(), std::begin("chunk_count="),
                              std::end("chunk_count=") - 1);
  ASSERT_NE(it, bytes_.end());
  const std::string_view field = "encryptor=AesCbc";
  std::copy(field.begin(), field.end(), it);
  save();
  expectOpenFails(path_, {": byte 13: ", "encrypted", "'encryptor'"});
}

TEST_F(RosbagMalformed, UnknownCompression) {
  const uint64_t chunk = writer_.chunkPositions()[1];
  replaceOnce(&bytes_, chunk, "compression=bz2", "compression=zst");
  save();
  expectOpenFails(path_, {": byte " + std::to_string(chunk) + ": ", "'compression' is 'zst'"});
}

TEST_F(RosbagMalformed, UnknownCompressionInABagNotClosed) {
  Ros1BagWriter writer;
  ASSERT_TRUE(writer.open(path_, Compression::kNone, 700));
  writeBag(&writer);
  ASSERT_TRUE(writer.closeAsCrashed(false));
  bytes_ = readBytes(path_);
  const uint64_t chunk = writer.chunkPositions()[2];
  replaceOnce(&bytes_, chunk, "compression=none", "compression=zstd");
  save();
  expectOpenFails(path_, {": byte " + std::to_string(chunk) + ": ", "'compression' is 'zstd'"});
}

TEST_F(RosbagMalformed, DecompressedSizeDiffers) {
  // The chunk header's 'size' field: "size=" then 4 bytes; make it one larger.
  const uint64_t chunk = writer_.chunkPositions()[1];
  const std::string_view key = "size=";
  auto it = std::search(bytes_.begin() + std::ptrdiff_t(chunk), bytes_.end(), key.begin(), key.end());
  ASSERT_NE(it, bytes_.end());
  ++*(it + std::ptrdiff_t(key.size()));
  save();
  BagReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(path_, &error)) << error;
  bool ok = true;
  const std::vector<Delivered> got = readAll(reader, &ok, &error);
  EXPECT_FALSE(ok);
  EXPECT_NE(error.find(path_ + ": byte " + std::to_string(chunk) + ": "), std::string::npos) << error;
  EXPECT_NE(error.find("'size'"), std::string::npos) << error;
  EXPECT_FALSE(got.empty());  // the first chunk's messages came before
}

TEST_F(RosbagMalformed, ChunkLengthPastTheEnd) {
  // data_len of chunk 0 (after its header) set to 0x7fffffff.
  const uint64_t chunk = writer_.chunkPositions()[0];
  const uint32_t header_len = uint32_t(bytes_[chunk]) | uint32_t(bytes_[chunk + 1]) << 8;
  const uint64_t data_len_at = chunk + 4 + header_len;
  bytes_[data_len_at] = 0xff;
  bytes_[data_len_at + 1] = 0xff;
  bytes_[data_len_at + 2] = 0xff;
  bytes_[data_len_at + 3] = 0x7f;
  save();
  expectOpenFails(path_, {": byte " + std::to_string(chunk) + ": ", "chunk record"});
}

TEST_F(RosbagMalformed, BagHeaderLengthPastTheEnd) {
  bytes_[13 + 3] = 0x40;  // header_len of the bag header: > 1 GiB
  save();
  expectOpenFails(path_, {": byte 13: ", "bag header record"});
}

TEST_F(RosbagMalformed, TypeWithAnotherLayoutIsRefusedNamingTheTopic) {
  Ros1BagWriter writer;
  ASSERT_TRUE(writer.open(path_, Compression::kLz4, 700));
  writeBag(&writer, 3);
  writer.writeRaw("/vendor/imu", "sensor_msgs/Imu", "0123456789abcdef0123456789abcdef",
                  "float32 ax\n", {0, 0, 0, 0}, 5000);
  ASSERT_TRUE(writer.close());
  expectOpenFails(path_, {"topic '/vendor/imu'", "sensor_msgs/Imu", "md5sum"});
}

TEST_F(RosbagMalformed, UnknownTypesAreListedNotRefused) {
  Ros1BagWriter writer;
  ASSERT_TRUE(writer.open(path_, Compression::kNone, 700));
  writeBag(&writer, 3);
  writer.writeRaw("/tf", "tf2_msgs/TFMessage", "94810edda583a504dfda3829e70d7eec", "", {0, 0, 0, 0},
                  5000);
  ASSERT_TRUE(writer.close());
  BagReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(path_, &error)) << error;
  ASSERT_EQ(reader.topics().size(), 3u);
  EXPECT_EQ(reader.topics()[2].type, "tf2_msgs/TFMessage");
}

}  // namespace
}  // namespace deepnav::rosbag

namespace deepnav::rosbag {
namespace {

using testsupport::Ros1BagWriter;
using namespace testing_util;

// Bytes overwritten at ~200 places (lengths, field names, compressed data, the index): open and
// forEach must not crash or read out of bounds (also run under ASan and UBSan while writing the
// reader), and every error names the file.
class RosbagFlipped : public ::testing::TestWithParam<Ros1BagWriter::Compression> {};

TEST_P(RosbagFlipped, NoCrashAndErrorsNameTheFile) {
  const std::string path = deepnav::testing::tempPath("flipped.bag");
  Ros1BagWriter writer;
  ASSERT_TRUE(writer.open(path, GetParam(), 700));
  for (int i = 0; i < 20; ++i) writer.write("/imu", sampleImu(i), 1000 * i);
  ASSERT_TRUE(writer.close());
  const std::vector<uint8_t> bytes = readBytes(path);
  for (size_t at = 13; at < bytes.size(); at += 1 + bytes.size() / 200) {
    for (uint8_t value : {uint8_t(0x00), uint8_t(0xff), uint8_t(bytes[at] ^ 0x10)}) {
      std::vector<uint8_t> damaged = bytes;
      damaged[at] = value;
      writeBytes(path, damaged.data(), damaged.size());
      BagReader reader;
      std::string error;
      bool ok = reader.open(path, &error);
      if (ok) readAll(reader, &ok, &error);
      if (!ok) {
        EXPECT_EQ(error.rfind(path + ": ", 0), 0u) << "byte " << at << ": " << error;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(RosbagCompressions, RosbagFlipped,
                         ::testing::Values(Ros1BagWriter::Compression::kNone,
                                           Ros1BagWriter::Compression::kBz2,
                                           Ros1BagWriter::Compression::kLz4),
                         [](const auto& info) { return compressionName(info.param); });

}  // namespace
}  // namespace deepnav::rosbag
