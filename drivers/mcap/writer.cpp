#include "drivers/mcap/writer.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <limits>

#include "drivers/mcap/crc32.h"
#include "drivers/mcap/format.h"
#include "drivers/mcap/record_builder.h"

namespace deepnav::mcap {
namespace {

constexpr size_t kScratchReserveBytes = 64 * 1024;
constexpr size_t kOffsetsPerChunkGuess = 8;

bool byLogTime(const MessageIndexEntry& a, const MessageIndexEntry& b) {
  return a.log_time_ns != b.log_time_ns ? a.log_time_ns < b.log_time_ns : a.offset < b.offset;
}

}  // namespace

Writer::~Writer() {
  std::string ignored;
  close(&ignored);
}

bool Writer::fail(std::string message) {
  if (!failed_) error_ = std::move(message);
  failed_ = true;
  return false;
}

bool Writer::open(const std::string& path, const WriterOptions& options, std::string* error) {
  if (file_ != nullptr) {
    *error = "mcap writer already has " + path_ + " open";
    return false;
  }
  resetState();
  options_ = options;
  path_ = path;
  if (!compressor_.init(options.compression, options.compression_level, error)) return false;
  file_ = std::fopen(path.c_str(), "wb");
  if (file_ == nullptr) {
    *error = "cannot create " + path + ": " + std::strerror(errno);
    return false;
  }
  // The chunk buffer holds a full chunk plus the message that makes it overflow.
  const size_t chunk_capacity =
      options.chunk_size_bytes + options.max_message_bytes + kRecordPrefixSize + kMessageFixedSize;
  chunk_buffer_.reserve(chunk_capacity);
  compressed_buffer_.resize(compressor_.bound(chunk_capacity));
  scratch_.reserve(kScratchReserveBytes);
  chunks_.reserve(options.expected_chunks);
  message_index_offsets_.reserve(options.expected_chunks * kOffsetsPerChunkGuess);

  in_data_section_ = true;
  scratch_.clear();
  putBytes(scratch_, kMagic, kMagicSize);
  appendHeader(scratch_, Header{options.profile, options.library});
  if (!writeOut(scratch_) || !pushToOs()) {
    *error = error_;
    std::fclose(file_);
    file_ = nullptr;
    return false;
  }
  return true;
}

void Writer::resetState() {
  error_.clear();
  failed_ = false;
  file_offset_ = 0;
  data_crc_ = 0;
  in_data_section_ = false;
  chunk_buffer_.clear();
  resetChunk();
  schemas_.clear();
  channels_.clear();
  chunks_.clear();
  message_index_offsets_.clear();
  metadata_index_.clear();
  message_count_ = 0;
  message_start_ns_ = 0;
  message_end_ns_ = 0;
}

uint16_t Writer::addSchema(std::string_view name, std::string_view encoding,
                           std::string_view data) {
  if (file_ == nullptr || failed_) return 0;
  if (schemas_.size() >= std::numeric_limits<uint16_t>::max()) {
    fail("too many schemas in " + path_);
    return 0;
  }
  SchemaState s;
  s.schema.id = uint16_t(schemas_.size() + 1);
  s.schema.name = name;
  s.schema.encoding = encoding;
  s.schema.data.assign(data.begin(), data.end());
  schemas_.push_back(std::move(s));
  return schemas_.back().schema.id;
}

uint16_t Writer::addChannel(uint16_t schema_id, std::string_view topic,
                            std::string_view message_encoding,
                            const std::map<std::string, std::string>& metadata) {
  if (file_ == nullptr || failed_) return 0;
  if (schema_id > schemas_.size()) {
    error_ = "channel " + std::string(topic) + ": unknown schema id " + std::to_string(schema_id);
    return 0;
  }
  if (channels_.size() >= std::numeric_limits<uint16_t>::max()) {
    fail("too many channels in " + path_);
    return 0;
  }
  ChannelState c;
  c.channel.id = uint16_t(channels_.size() + 1);
  c.channel.schema_id = schema_id;
  c.channel.topic = topic;
  c.channel.message_encoding = message_encoding;
  c.channel.metadata = metadata;
  // The ros2 profile requires this key; rosbag2 reads "" as "default QoS".
  if (options_.profile == "ros2") c.channel.metadata.try_emplace("offered_qos_profiles", "");
  c.index.reserve(options_.index_entries_per_channel);
  channels_.push_back(std::move(c));
  return channels_.back().channel.id;
}

bool Writer::write(uint16_t channel_id, uint32_t sequence, uint64_t log_time_ns,
                   uint64_t publish_time_ns, const uint8_t* data, size_t size) {
  if (file_ == nullptr || failed_) return false;
  if (channel_id == 0 || channel_id > channels_.size()) {
    error_ = "write to unknown channel id " + std::to_string(channel_id);
    return false;
  }
  if (chunkWouldSpanTooLong(log_time_ns) && !closeChunk()) return false;
  ChannelState& channel = channels_[channel_id - 1];
  channel.index.push_back(MessageIndexEntry{log_time_ns, chunk_buffer_.size()});
  appendMessage(chunk_buffer_,
                MessageView{channel_id, sequence, log_time_ns, publish_time_ns, data, size});
  noteMessage(channel, log_time_ns);
  if (chunk_buffer_.size() >= options_.chunk_size_bytes) return closeChunk();
  return true;
}

bool Writer::chunkWouldSpanTooLong(uint64_t log_time_ns) const {
  if (chunk_message_count_ == 0) return false;
  const uint64_t start = std::min(chunk_start_ns_, log_time_ns);
  const uint64_t end = std::max(chunk_end_ns_, log_time_ns);
  return end - start > options_.chunk_max_duration_ns;
}

void Writer::noteMessage(ChannelState& channel, uint64_t log_time_ns) {
  if (chunk_message_count_ == 0) {
    chunk_start_ns_ = chunk_end_ns_ = log_time_ns;
  } else {
    chunk_start_ns_ = std::min(chunk_start_ns_, log_time_ns);
    chunk_end_ns_ = std::max(chunk_end_ns_, log_time_ns);
  }
  if (message_count_ == 0) {
    message_start_ns_ = message_end_ns_ = log_time_ns;
  } else {
    message_start_ns_ = std::min(message_start_ns_, log_time_ns);
    message_end_ns_ = std::max(message_end_ns_, log_time_ns);
  }
  ++chunk_message_count_;
  ++channel.message_count;
  ++message_count_;
}

bool Writer::writeMetadata(std::string_view name,
                           const std::map<std::string, std::string>& metadata) {
  if (file_ == nullptr || failed_) return false;
  scratch_.clear();
  appendMetadata(scratch_, Metadata{std::string(name), metadata});
  metadata_index_.push_back(MetadataIndexEntry{file_offset_, scratch_.size(), std::string(name)});
  return writeOut(scratch_);
}

bool Writer::flush() {
  if (file_ == nullptr || failed_) return false;
  return closeChunk();
}

bool Writer::writeOut(const uint8_t* data, size_t size) {
  if (failed_) return false;
  if (size > 0 && std::fwrite(data, 1, size, file_) != size) {
    return fail("write to " + path_ + " failed at byte " + std::to_string(file_offset_) + ": " +
                std::strerror(errno));
  }
  if (in_data_section_ && options_.enable_crcs) data_crc_ = crc32Update(data_crc_, data, size);
  file_offset_ += size;
  return true;
}

bool Writer::pushToOs() {
  if (failed_) return false;
  if (std::fflush(file_) != 0)
    return fail("flush of " + path_ + " failed: " + std::strerror(errno));
  if (options_.sync_each_chunk && ::fdatasync(::fileno(file_)) != 0) {
    return fail("fdatasync of " + path_ + " failed: " + std::strerror(errno));
  }
  return true;
}

bool Writer::closeChunk() {
  if (chunk_message_count_ == 0) return true;
  if (!writeDefinitions(true)) return false;
  const uint8_t* payload = nullptr;
  size_t payload_size = 0;
  if (!compressChunk(&payload, &payload_size)) return false;

  ChunkInfo info;
  info.message_start_time_ns = chunk_start_ns_;
  info.message_end_time_ns = chunk_end_ns_;
  info.chunk_start_offset = file_offset_;
  info.compression = compressionName(options_.compression);
  info.compressed_size = payload_size;
  info.uncompressed_size = chunk_buffer_.size();
  const uint32_t crc = options_.enable_crcs ? crc32(chunk_buffer_.data(), chunk_buffer_.size()) : 0;
  scratch_.clear();
  appendChunkPrefix(scratch_, info, crc);
  if (!writeOut(scratch_) || !writeOut(payload, payload_size)) return false;
  info.chunk_length = file_offset_ - info.chunk_start_offset;
  if (!writeMessageIndexes(&info)) return false;
  resetChunk();
  return pushToOs();
}

bool Writer::compressChunk(const uint8_t** payload, size_t* payload_size) {
  if (options_.compression == Compression::kNone) {
    *payload = chunk_buffer_.data();
    *payload_size = chunk_buffer_.size();
    return true;
  }
  const size_t bound = compressor_.bound(chunk_buffer_.size());
  // Only a message larger than max_message_bytes gets here with a too-small buffer.
  if (compressed_buffer_.size() < bound) compressed_buffer_.resize(bound);
  std::string error;
  const size_t n =
      compressor_.compress(chunk_buffer_.data(), chunk_buffer_.size(), compressed_buffer_.data(),
                           compressed_buffer_.size(), &error);
  if (n == 0) return fail(path_ + ": " + error);
  *payload = compressed_buffer_.data();
  *payload_size = n;
  return true;
}

// Schema and Channel records of channels that are not in the file yet: those with messages in
// the open chunk, or (at close) all of them.
bool Writer::writeDefinitions(bool only_channels_in_chunk) {
  scratch_.clear();
  for (ChannelState& c : channels_) {
    if (c.in_file || (only_channels_in_chunk && c.index.empty())) continue;
    const uint16_t schema_id = c.channel.schema_id;
    if (schema_id != 0 && !schemas_[schema_id - 1].in_file) {
      appendSchema(scratch_, schemas_[schema_id - 1].schema);
      schemas_[schema_id - 1].in_file = true;
    }
    appendChannel(scratch_, c.channel);
    c.in_file = true;
  }
  if (!only_channels_in_chunk) {
    for (SchemaState& s : schemas_) {
      if (!s.in_file) appendSchema(scratch_, s.schema);
      s.in_file = true;
    }
  }
  return writeOut(scratch_);
}

bool Writer::writeMessageIndexes(ChunkInfo* info) {
  scratch_.clear();
  const uint64_t start = file_offset_;
  const size_t offsets_begin = message_index_offsets_.size();
  for (ChannelState& c : channels_) {
    if (c.index.empty()) continue;
    // Sensors on one channel are time-ordered almost always; sorting is the rare path.
    if (!std::is_sorted(c.index.begin(), c.index.end(), byLogTime)) {
      std::sort(c.index.begin(), c.index.end(), byLogTime);
    }
    message_index_offsets_.emplace_back(c.channel.id, start + scratch_.size());
    appendMessageIndex(scratch_, c.channel.id, c.index.data(), c.index.size());
  }
  info->message_index_length = scratch_.size();
  chunks_.push_back(
      ChunkRecord{*info, offsets_begin, message_index_offsets_.size() - offsets_begin});
  return writeOut(scratch_);
}

void Writer::resetChunk() {
  chunk_buffer_.clear();
  for (ChannelState& c : channels_) c.index.clear();
  chunk_start_ns_ = chunk_end_ns_ = 0;
  chunk_message_count_ = 0;
}

bool Writer::writeDataEnd() {
  scratch_.clear();
  appendDataEnd(scratch_, options_.enable_crcs ? data_crc_ : 0);
  in_data_section_ = false;
  return writeOut(scratch_);
}

Statistics Writer::statistics() const {
  Statistics s;
  s.message_count = message_count_;
  s.schema_count = uint16_t(schemas_.size());
  s.channel_count = uint32_t(channels_.size());
  s.metadata_count = uint32_t(metadata_index_.size());
  s.chunk_count = uint32_t(chunks_.size());
  s.message_start_time_ns = message_start_ns_;
  s.message_end_time_ns = message_end_ns_;
  for (const ChannelState& c : channels_) s.channel_message_counts[c.channel.id] = c.message_count;
  return s;
}

// Summary records grouped by opcode, then one Summary Offset per group. Returns where in `out`
// the Summary Offset records begin.
size_t Writer::appendSummary(std::vector<uint8_t>& out) const {
  struct Group {
    Opcode op;
    size_t begin;
    size_t end;
  };
  std::vector<Group> groups;
  const uint64_t base = file_offset_;
  auto group = [&](Opcode op, auto&& append_records) {
    const size_t begin = out.size();
    append_records();
    if (out.size() > begin) groups.push_back(Group{op, begin, out.size()});
  };
  group(Opcode::kSchema, [&] {
    for (const SchemaState& s : schemas_) appendSchema(out, s.schema);
  });
  group(Opcode::kChannel, [&] {
    for (const ChannelState& c : channels_) appendChannel(out, c.channel);
  });
  group(Opcode::kStatistics, [&] { appendStatistics(out, statistics()); });
  group(Opcode::kChunkIndex, [&] {
    for (const ChunkRecord& c : chunks_) {
      appendChunkIndex(out, c.info, message_index_offsets_.data() + c.offsets_begin,
                       c.offsets_count);
    }
  });
  group(Opcode::kMetadataIndex, [&] {
    for (const MetadataIndexEntry& m : metadata_index_) {
      appendMetadataIndex(out, m.offset, m.length, m.name);
    }
  });
  const size_t offsets_at = out.size();
  for (const Group& g : groups) appendSummaryOffset(out, g.op, base + g.begin, g.end - g.begin);
  return offsets_at;
}

bool Writer::writeSummaryAndFooter() {
  const uint64_t summary_start = file_offset_;
  std::vector<uint8_t> out;
  const size_t offsets_at = appendSummary(out);
  const bool has_offsets = out.size() > offsets_at;
  putU8(out, uint8_t(Opcode::kFooter));
  putU64(out, kFooterContentSize);
  putU64(out, summary_start);
  putU64(out, has_offsets ? summary_start + offsets_at : 0);
  putU32(out, options_.enable_crcs ? crc32(out.data(), out.size()) : 0);
  putBytes(out, kMagic, kMagicSize);
  return writeOut(out);
}

bool Writer::close(std::string* error) {
  if (file_ == nullptr) return true;
  bool ok = !failed_ && closeChunk() && writeDefinitions(false) && writeDataEnd() &&
            writeSummaryAndFooter() && pushToOs();
  if (std::fclose(file_) != 0 && ok)
    ok = fail("close of " + path_ + " failed: " + std::strerror(errno));
  file_ = nullptr;
  if (!ok) *error = error_;
  return ok;
}

}  // namespace deepnav::mcap
