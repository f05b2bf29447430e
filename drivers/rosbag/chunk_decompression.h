#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "drivers/mcap/compression.h"

// A bag chunk's data back to its records. rosbag writes "none", "bz2" (one bzip2 stream, libbz2)
// or "lz4" (roslz4, which writes the standard LZ4 frame format: magic 0x184D2204, FLG version 1
// with independent blocks and a content checksum, BD, the XXH32 header checksum, blocks whose
// high size bit marks a stored block, EndMark, content checksum; see ros_comm
// utilities/roslz4/src/lz4s.c, writeHeader/bufferToOutput/writeEOS), so liblz4's frame API reads it.
namespace deepnav::rosbag {

bool isKnownCompression(std::string_view compression);

// The largest decompressed chunk accepted (rosbag's default chunk is 768 KiB): a corrupt 'size'
// field must not make the reader allocate gigabytes.
inline constexpr uint32_t kMaxChunkBytes = 512u << 20;

class ChunkDecompressor {
 public:
  // Decompresses into exactly out_size bytes (*out is resized). False with *what on an unknown
  // compression, corrupt data, or a decompressed size other than out_size.
  bool decompress(std::string_view compression, const uint8_t* in, size_t in_size, size_t out_size,
                  std::vector<uint8_t>* out, std::string* what);
  // For a chunk cut short: as many leading bytes of its content as the bytes present yield (at
  // most out_size). Never fails; *out holds what was recovered.
  void decompressPrefix(std::string_view compression, const uint8_t* in, size_t in_size,
                        size_t out_size, std::vector<uint8_t>* out);

 private:
  bool bz2(const uint8_t* in, size_t in_size, size_t out_size, std::vector<uint8_t>* out,
           std::string* what);

  mcap::ChunkDecompressor lz4_;  // the LZ4 frame decoder MCAP chunks use
};

}  // namespace deepnav::rosbag
