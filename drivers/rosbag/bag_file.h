#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "drivers/mcap/random_access_file.h"
#include "drivers/rosbag/record_header.h"

// The bag file read record by record at explicit offsets (pread), so a bag of many GiB is never
// held in memory: the reader jumps from the bag header to the index and to each chunk.
namespace deepnav::rosbag {

enum class ReadStatus {
  kOk,
  kEnd,        // `pos` is the limit: no record there
  kHeaderCut,  // header_len, the header or data_len runs past the limit
  kDataCut,    // header read and parsed, the data runs past the limit
  kBadHeader,  // the header's fields are malformed (*what says how)
};

class BagFile {
 public:
  bool open(const std::string& path, std::string* error);
  const std::string& path() const { return path_; }
  uint64_t size() const { return file_.size(); }
  bool readAt(uint64_t offset, size_t n, uint8_t* out) const {
    return file_.readAt(offset, n, out);
  }

  // Frames the record at `pos` (records end at `limit`) and parses its header into *header, which
  // stays valid until the next call.
  ReadStatus readRecord(uint64_t pos, uint64_t limit, RecordFrame* frame, RecordHeader* header,
                        std::string* what);
  // The record's data, or its first `n` bytes.
  bool readData(const RecordFrame& frame, uint64_t n, std::vector<uint8_t>* out) const;

 private:
  std::string path_;
  mcap::RandomAccessFile file_;
  std::vector<uint8_t> header_bytes_;
};

}  // namespace deepnav::rosbag
