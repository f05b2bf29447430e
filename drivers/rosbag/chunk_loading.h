#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "drivers/rosbag/bag_file.h"
#include "drivers/rosbag/bag_format.h"
#include "drivers/rosbag/chunk_decompression.h"
#include "drivers/rosbag/chunk_records.h"

// One chunk from the file to its records: read its data, decompress it (for a chunk cut short,
// as much as the bytes present give) and walk its records.
namespace deepnav::rosbag {

// Reads the chunk record header at `pos` (records end at `limit`) into *chunk: compression, size
// and where its data lies. A chunk whose data runs past `limit` is marked partial. False with
// *error (file, byte, field) on a record that is not a chunk, a missing field, an unknown
// compression or an implausible size.
bool locateChunk(BagFile& file, uint64_t pos, uint64_t limit, ChunkRef* chunk, std::string* error);

// *bytes receives the decompressed chunk, *content its records (data offsets into *bytes).
bool loadChunk(const BagFile& file, const ChunkRef& chunk, ChunkDecompressor* decompressor,
               std::vector<uint8_t>* compressed, std::vector<uint8_t>* bytes,
               ChunkContent* content, std::string* error);

}  // namespace deepnav::rosbag
