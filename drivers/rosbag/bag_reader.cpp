#include "drivers/rosbag/bag_reader.h"

#include <algorithm>

#include "drivers/rosbag/chunk_merge.h"
#include "drivers/rosbag/ros1_md5.h"

namespace deepnav::rosbag {

bool BagReader::open(const std::string& path, std::string* error) {
  index_ = BagIndex{};
  topics_.clear();
  if (!file_.open(path, error)) return false;
  BagHeaderFields header;
  uint64_t chunks_start = 0;
  if (!readBagHeader(&header, &chunks_start, error) ||
      !readChunks(header, chunks_start, error) || !checkConnections(error)) {
    return false;
  }
  listTopics();
  return true;
}

bool BagReader::readBagHeader(BagHeaderFields* header, uint64_t* chunks_start,
                              std::string* error) {
  char magic[kMagic.size()] = {};
  const size_t n = size_t(std::min<uint64_t>(file_.size(), kMagic.size()));
  file_.readAt(0, n, reinterpret_cast<uint8_t*>(magic));
  const std::string_view head(magic, n);
  if (head.substr(0, kMagicPrefix.size()) != kMagicPrefix) {
    *error = errorAt(file_.path(), 0, "not a ROS bag: it does not start with '#ROSBAG V'");
    return false;
  }
  if (head != kMagic) {
    const std::string version(head.substr(kMagicPrefix.size(), head.find('\n') - kMagicPrefix.size()));
    *error = errorAt(file_.path(), kMagicPrefix.size(),
                     "bag format version '" + version + "', this reader reads 2.0");
    return false;
  }
  RecordFrame frame;
  RecordHeader fields;
  std::string what;
  const uint64_t pos = kMagic.size();
  const ReadStatus status = file_.readRecord(pos, file_.size(), &frame, &fields, &what);
  uint8_t op = 0;
  if (status != ReadStatus::kOk && status != ReadStatus::kBadHeader) {
    what = "cut short (the file has " + std::to_string(file_.size()) + " bytes)";
  } else if (status == ReadStatus::kOk && fields.op(&op, &what)) {
    if (op != uint8_t(Op::kBagHeader)) {
      what = "expected op 3, found op " + std::to_string(op) + " (" + std::string(opName(op)) + ")";
    } else if (fields.has("encryptor")) {
      what = "the bag is encrypted (field 'encryptor'), which this reader does not read";
    } else if (parseBagHeader(fields, header, &what)) {
      *chunks_start = frame.end();
      return true;
    }
  }
  *error = errorAt(file_.path(), pos, "bag header record: " + what);
  return false;
}

bool BagReader::readChunks(const BagHeaderFields& header, uint64_t chunks_start,
                           std::string* error) {
  uint64_t limit = file_.size();
  std::string notice;
  if (header.index_pos == 0) {
    notice = "index_pos is 0 (the recorder did not close the bag): chunks scanned";
  } else if (header.index_pos < chunks_start || header.index_pos > file_.size()) {
    notice = "index_pos " + std::to_string(header.index_pos) + " is outside the file (" +
             std::to_string(file_.size()) + " bytes): chunks scanned";
  } else {
    std::string why;
    if (readIndex(file_, header, chunks_start, &index_, &why, error)) return true;
    if (why.empty()) return false;
    index_ = BagIndex{};
    notice = "index not used (" + why + "): chunks scanned";
    limit = header.index_pos;
  }
  if (!scanChunks(file_, chunks_start, limit, &index_, error)) return false;
  if (header.index_pos > file_.size() && index_.loss.empty() &&
      index_.scan_end < header.index_pos) {
    // Closed, then cut (a copy interrupted): what lay between the end and the index is lost.
    index_.loss = errorAt(file_.path(), file_.size(),
                          "the bag is cut short: its header puts the index at byte " +
                              std::to_string(header.index_pos) +
                              ", past the end of the file; the messages from here on are lost");
  }
  index_.notice = index_.notice.empty() ? notice : notice + "; " + index_.notice;
  return true;
}

bool BagReader::checkConnections(std::string* error) const {
  std::map<std::string_view, const Connection*> by_topic;
  for (const auto& [id, c] : index_.connections) {
    std::string what;
    if (!checkLayout(c.topic, c.type, c.md5sum, &what)) {
      *error = errorAt(file_.path(), c.offset, what);
      return false;
    }
    const auto [it, added] = by_topic.emplace(c.topic, &c);
    if (!added && it->second->type != c.type) {
      *error = errorAt(file_.path(), c.offset,
                       "topic '" + c.topic + "' has connections of two types: " +
                           it->second->type + " and " + c.type);
      return false;
    }
  }
  return true;
}

void BagReader::listTopics() {
  std::map<uint32_t, uint64_t> counts;
  for (const ChunkRef& chunk : index_.chunks) {
    for (const auto& [conn, n] : chunk.messages_per_connection) counts[conn] += n;
  }
  for (const auto& [id, c] : index_.connections) {
    foreign::ForeignTopic* topic = nullptr;
    for (auto& t : topics_) {
      if (t.name == c.topic) topic = &t;
    }
    if (topic == nullptr) {
      topic = &topics_.emplace_back();
      topic->name = c.topic;
      topic->type = c.type;
      topic->serialization = foreign::Serialization::kRos1;
    }
    topic->messages += counts[id];
  }
}

bool BagReader::forEach(const Callback& callback, std::string* error) {
  ChunkMerge merge(file_, index_);
  if (!merge.run(callback, error)) return false;
  if (!merge.stopped() && !index_.loss.empty()) {
    *error = index_.loss;
    return false;
  }
  return true;
}

}  // namespace deepnav::rosbag
