#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace deepnav::mcap {

// A read-only file read at explicit offsets (pread), so a recording of many GiB is never held in
// memory and a reader can jump from the footer to the summary to a chunk.
class RandomAccessFile {
 public:
  RandomAccessFile() = default;
  ~RandomAccessFile();
  RandomAccessFile(const RandomAccessFile&) = delete;
  RandomAccessFile& operator=(const RandomAccessFile&) = delete;

  bool open(const std::string& path, std::string* error);
  void close();
  uint64_t size() const { return size_; }
  // Reads exactly `n` bytes at `offset`; false if they are not all in the file or on an I/O error.
  bool readAt(uint64_t offset, size_t n, uint8_t* out) const;

 private:
  int fd_ = -1;
  uint64_t size_ = 0;
};

}  // namespace deepnav::mcap
