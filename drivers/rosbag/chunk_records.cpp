#include "drivers/rosbag/chunk_records.h"

#include "drivers/rosbag/bag_records.h"
#include "drivers/rosbag/record_header.h"

namespace deepnav::rosbag {
namespace {

bool parseOne(const uint8_t* data, const RecordFrame& frame, ChunkContent* content,
              std::string* what) {
  RecordHeader header;
  uint8_t op = 0;
  if (!header.parse(data + frame.header_offset, frame.header_len, what) ||
      !header.op(&op, what)) {
    return false;
  }
  if (op == uint8_t(Op::kConnection)) {
    Connection c;
    if (!parseConnection(header, data + frame.data_offset, frame.data_len, &c, what)) {
      *what = "connection record: " + *what;
      return false;
    }
    c.offset = frame.offset;
    content->connections.push_back(std::move(c));
  } else if (op == uint8_t(Op::kMessageData)) {
    MessageEntry m;
    if (!parseMessageData(header, &m.conn, &m.time_ns, what)) {
      *what = "message data record: " + *what;
      return false;
    }
    m.order = uint32_t(content->messages.size());
    m.data_offset = frame.data_offset;
    m.data_size = frame.data_len;
    content->messages.push_back(m);
  }
  return true;
}

}  // namespace

bool parseChunkRecords(const uint8_t* data, size_t size, bool complete, ChunkContent* content,
                       std::string* what, uint64_t* what_offset) {
  content->connections.clear();
  content->messages.clear();
  content->complete_bytes = 0;
  uint64_t pos = 0;
  for (;;) {
    RecordFrame frame;
    const FrameStatus status = frameRecord(data, size, pos, &frame);
    if (status == FrameStatus::kEnd) return true;
    if (status == FrameStatus::kTruncated) {
      if (!complete) return true;
      *what_offset = pos;
      *what = "record lengths run past the chunk's end (" + std::to_string(size) + " bytes)";
      return false;
    }
    if (!parseOne(data, frame, content, what)) {
      *what_offset = pos;
      return false;
    }
    pos = frame.end();
    content->complete_bytes = pos;
  }
}

}  // namespace deepnav::rosbag
