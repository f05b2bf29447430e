#include "drivers/rosbag/bag_format.h"

namespace deepnav::rosbag {

std::string_view opName(uint8_t op) {
  switch (Op(op)) {
    case Op::kMessageData:
      return "message data record";
    case Op::kBagHeader:
      return "bag header record";
    case Op::kIndexData:
      return "index data record";
    case Op::kChunk:
      return "chunk record";
    case Op::kChunkInfo:
      return "chunk info record";
    case Op::kConnection:
      return "connection record";
  }
  return "record";
}

std::string errorAt(const std::string& path, uint64_t offset, std::string_view what) {
  return path + ": byte " + std::to_string(offset) + ": " + std::string(what);
}

}  // namespace deepnav::rosbag
