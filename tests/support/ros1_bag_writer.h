#pragma once
// Test scaffolding: a ROS 1 bag (format 2.0) writer laid out as rosbag writes one
// (http://wiki.ros.org/Bags/Format/2.0): magic, a bag header record padded to 4096 bytes, chunks
// (none, bz2 or lz4) each followed by one index data record per connection, then the index
// section (every connection record, then one chunk info record per chunk) at index_pos. A
// connection record is written into the chunk where the connection is first used.
// Usage: open(path, compression, chunk_size); write(topic, msg, log_time_ns)...; close().
// closeAsCrashed() leaves the file as a recorder killed mid-recording does. Chunks are written to
// the file as they fill; close() rewrites the bag header with index_pos, as rosbag does.
#include <bzlib.h>
#include <lz4frame.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "tests/support/ros1_msg_encoder.h"

namespace deepnav::testsupport {

class Ros1BagWriter {
 public:
  enum class Compression { kNone, kBz2, kLz4 };

  // The bag header's name of a compression ("none", "bz2", "lz4").
  static std::string compressionName(Compression c) {
    return c == Compression::kBz2 ? "bz2" : c == Compression::kLz4 ? "lz4" : "none";
  }

  bool open(const std::string& path, Compression compression = Compression::kNone,
            size_t chunk_size = 768 * 1024) {
    path_ = path;
    compression_ = compression;
    chunk_size_ = chunk_size;
    out_.open(path_, std::ios::binary | std::ios::trunc);
    pos_ = 0;
    append(std::vector<uint8_t>(kMagic.begin(), kMagic.end()));
    append(bagHeaderRecord(0, 0, 0));
    return out_.good();
  }

  template <class Msg>
  bool write(const std::string& topic, const Msg& msg, int64_t log_time_ns) {
    const uint32_t seq = seq_[topic]++;
    return writeRaw(topic, Ros1Type<Msg>::kName, Ros1Type<Msg>::kMd5,
                    Ros1Type<Msg>::definition(), encodeRos1(msg, seq), log_time_ns);
  }

  // Any serialized message under any type and md5sum (a non-standard layout, a short message...).
  bool writeRaw(const std::string& topic, std::string_view type, std::string_view md5,
                const std::string& definition, const std::vector<uint8_t>& data,
                int64_t log_time_ns) {
    auto it = connection_ids_.find(topic);
    if (it == connection_ids_.end()) {
      it = connection_ids_.emplace(topic, uint32_t(connections_.size())).first;
      connections_.push_back(connectionRecord(it->second, topic, type, md5, definition));
      chunk_.insert(chunk_.end(), connections_.back().begin(), connections_.back().end());
    }
    const uint32_t conn = it->second;
    if (chunk_times_.empty()) chunk_start_ = chunk_end_ = log_time_ns;
    chunk_start_ = std::min(chunk_start_, log_time_ns);
    chunk_end_ = std::max(chunk_end_, log_time_ns);
    chunk_times_[conn].push_back({log_time_ns, uint32_t(chunk_.size())});
    std::vector<uint8_t> header;
    field(&header, "op", {uint8_t(0x02)});
    field(&header, "conn", le(conn, 4));
    field(&header, "time", rosTime(log_time_ns));
    appendRecord(&chunk_, header, data);
    if (chunk_.size() >= chunk_size_) flushChunk();
    return true;
  }

  bool close() {
    flushChunk();
    const uint64_t index_pos = pos_;
    for (const auto& c : connections_) append(c);
    for (const auto& info : chunk_infos_) appendChunkInfo(info);
    rewriteBagHeader(index_pos, uint32_t(connections_.size()), uint32_t(chunk_infos_.size()));
    index_pos_ = index_pos;
    return finish();
  }

  // As a recorder killed mid-recording leaves the bag: no index section, index_pos 0 in the bag
  // header. With `unfinished_chunk`, the open chunk is left as rosbag leaves it while writing:
  // its header's sizes still the placeholders 0 and its (compressed) records after it, no index
  // data records; without, the open chunk is closed first.
  bool closeAsCrashed(bool unfinished_chunk) {
    if (unfinished_chunk && !chunk_.empty()) {
      chunk_positions_.push_back(pos_);
      std::vector<uint8_t> record;
      appendRecord(&record, chunkHeader(0), {});
      append(record);
      append(compress(chunk_));
      chunk_.clear();
    } else {
      flushChunk();
    }
    return finish();
  }

  const std::vector<uint64_t>& chunkPositions() const { return chunk_positions_; }
  const std::vector<size_t>& chunkMessageCounts() const { return chunk_message_counts_; }
  uint64_t indexPos() const { return index_pos_; }
  uint64_t fileSize() const { return pos_; }

 private:
  static constexpr std::string_view kMagic = "#ROSBAG V2.0\n";
  static constexpr size_t kBagHeaderBytes = 4096;  // rosbag pads the bag header record to 4 KiB

  struct ChunkInfo {
    uint64_t pos;
    int64_t start_ns, end_ns;
    std::map<uint32_t, uint32_t> counts;
  };

  static std::vector<uint8_t> le(uint64_t v, int n) {
    std::vector<uint8_t> b;
    for (int i = 0; i < n; ++i) b.push_back(uint8_t(v >> (8 * i)));
    return b;
  }
  static std::vector<uint8_t> rosTime(int64_t ns) {
    std::vector<uint8_t> b = le(uint64_t(ns / 1000000000), 4);
    const std::vector<uint8_t> nsec = le(uint64_t(ns % 1000000000), 4);
    b.insert(b.end(), nsec.begin(), nsec.end());
    return b;
  }
  static std::vector<uint8_t> text(std::string_view s) {
    std::vector<uint8_t> b(s.size());
    if (!s.empty()) std::memcpy(b.data(), s.data(), s.size());
    return b;
  }
  static void field(std::vector<uint8_t>* out, std::string_view name,
                    const std::vector<uint8_t>& value) {
    const std::vector<uint8_t> n = le(name.size() + 1 + value.size(), 4);
    out->insert(out->end(), n.begin(), n.end());
    out->insert(out->end(), name.begin(), name.end());
    out->push_back('=');
    out->insert(out->end(), value.begin(), value.end());
  }
  static void appendRecord(std::vector<uint8_t>* out, const std::vector<uint8_t>& header,
                           const std::vector<uint8_t>& data) {
    const std::vector<uint8_t> hl = le(header.size(), 4);
    const std::vector<uint8_t> dl = le(data.size(), 4);
    out->insert(out->end(), hl.begin(), hl.end());
    out->insert(out->end(), header.begin(), header.end());
    out->insert(out->end(), dl.begin(), dl.end());
    out->insert(out->end(), data.begin(), data.end());
  }

  static std::vector<uint8_t> connectionRecord(uint32_t id, std::string_view topic,
                                               std::string_view type, std::string_view md5,
                                               const std::string& definition) {
    std::vector<uint8_t> header;
    field(&header, "op", {uint8_t(0x07)});
    field(&header, "conn", le(id, 4));
    field(&header, "topic", text(topic));
    std::vector<uint8_t> data;
    field(&data, "topic", text(topic));
    field(&data, "type", text(type));
    field(&data, "md5sum", text(md5));
    field(&data, "message_definition", text(definition));
    field(&data, "callerid", text("/deepnav_test"));
    std::vector<uint8_t> record;
    appendRecord(&record, header, data);
    return record;
  }

  std::vector<uint8_t> bagHeaderRecord(uint64_t index_pos, uint32_t conns, uint32_t chunks) const {
    std::vector<uint8_t> header;
    field(&header, "op", {uint8_t(0x03)});
    field(&header, "index_pos", le(index_pos, 8));
    field(&header, "conn_count", le(conns, 4));
    field(&header, "chunk_count", le(chunks, 4));
    std::vector<uint8_t> record;
    appendRecord(&record, header, std::vector<uint8_t>(kBagHeaderBytes - 8 - header.size(), ' '));
    return record;
  }
  void rewriteBagHeader(uint64_t index_pos, uint32_t conns, uint32_t chunks) {
    const std::vector<uint8_t> r = bagHeaderRecord(index_pos, conns, chunks);
    out_.seekp(std::streamoff(kMagic.size()));
    out_.write(reinterpret_cast<const char*>(r.data()), std::streamsize(r.size()));
    out_.seekp(std::streamoff(pos_));
  }

  std::vector<uint8_t> chunkHeader(uint32_t size) const {
    std::vector<uint8_t> header;
    field(&header, "op", {uint8_t(0x05)});
    field(&header, "compression", text(compressionName(compression_)));
    field(&header, "size", le(size, 4));
    return header;
  }

  std::vector<uint8_t> compress(const std::vector<uint8_t>& in) const {
    if (compression_ == Compression::kBz2) {
      unsigned n = unsigned(in.size() + in.size() / 100 + 600);
      std::vector<uint8_t> out(n);
      BZ2_bzBuffToBuffCompress(reinterpret_cast<char*>(out.data()), &n,
                               const_cast<char*>(reinterpret_cast<const char*>(in.data())),
                               unsigned(in.size()), 9, 0, 0);
      out.resize(n);
      return out;
    }
    if (compression_ == Compression::kLz4) {
      // As roslz4 writes it: independent blocks, 1 MiB blocks, a content checksum, no size.
      LZ4F_preferences_t prefs;
      std::memset(&prefs, 0, sizeof(prefs));
      prefs.frameInfo.blockSizeID = LZ4F_max1MB;
      prefs.frameInfo.blockMode = LZ4F_blockIndependent;
      prefs.frameInfo.contentChecksumFlag = LZ4F_contentChecksumEnabled;
      std::vector<uint8_t> out(LZ4F_compressFrameBound(in.size(), &prefs));
      out.resize(LZ4F_compressFrame(out.data(), out.size(), in.data(), in.size(), &prefs));
      return out;
    }
    return in;
  }

  void flushChunk() {
    if (chunk_.empty()) return;
    ChunkInfo info{pos_, chunk_start_, chunk_end_, {}};
    chunk_positions_.push_back(info.pos);
    std::vector<uint8_t> record;
    appendRecord(&record, chunkHeader(uint32_t(chunk_.size())), compress(chunk_));
    for (const auto& [conn, entries] : chunk_times_) {
      std::vector<uint8_t> header;
      field(&header, "op", {uint8_t(0x04)});
      field(&header, "ver", le(1, 4));
      field(&header, "conn", le(conn, 4));
      field(&header, "count", le(entries.size(), 4));
      std::vector<uint8_t> data;
      for (const auto& [t, offset] : entries) {
        const std::vector<uint8_t> tb = rosTime(t);
        const std::vector<uint8_t> ob = le(offset, 4);
        data.insert(data.end(), tb.begin(), tb.end());
        data.insert(data.end(), ob.begin(), ob.end());
      }
      appendRecord(&record, header, data);
      info.counts[conn] = uint32_t(entries.size());
    }
    size_t messages = 0;
    for (const auto& [conn, n] : info.counts) messages += n;
    chunk_message_counts_.push_back(messages);
    append(record);
    chunk_infos_.push_back(info);
    chunk_.clear();
    chunk_times_.clear();
  }

  void appendChunkInfo(const ChunkInfo& info) {
    std::vector<uint8_t> header;
    field(&header, "op", {uint8_t(0x06)});
    field(&header, "ver", le(1, 4));
    field(&header, "chunk_pos", le(info.pos, 8));
    field(&header, "start_time", rosTime(info.start_ns));
    field(&header, "end_time", rosTime(info.end_ns));
    field(&header, "count", le(info.counts.size(), 4));
    std::vector<uint8_t> data;
    for (const auto& [conn, n] : info.counts) {
      const std::vector<uint8_t> c = le(conn, 4);
      const std::vector<uint8_t> k = le(n, 4);
      data.insert(data.end(), c.begin(), c.end());
      data.insert(data.end(), k.begin(), k.end());
    }
    std::vector<uint8_t> record;
    appendRecord(&record, header, data);
    append(record);
  }

  void append(const std::vector<uint8_t>& bytes) {
    out_.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    pos_ += bytes.size();
  }
  bool finish() {
    out_.close();
    return !out_.fail();
  }

  std::string path_;
  Compression compression_ = Compression::kNone;
  size_t chunk_size_ = 0;
  std::ofstream out_;
  uint64_t pos_ = 0;
  std::vector<uint8_t> chunk_;
  int64_t chunk_start_ = 0;
  int64_t chunk_end_ = 0;
  std::map<uint32_t, std::vector<std::pair<int64_t, uint32_t>>> chunk_times_;
  std::map<std::string, uint32_t> connection_ids_;
  std::map<std::string, uint32_t> seq_;
  std::vector<std::vector<uint8_t>> connections_;
  std::vector<ChunkInfo> chunk_infos_;
  std::vector<uint64_t> chunk_positions_;
  std::vector<size_t> chunk_message_counts_;
  uint64_t index_pos_ = 0;
};

}  // namespace deepnav::testsupport
