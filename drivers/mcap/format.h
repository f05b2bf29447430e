#pragma once
#include <cstddef>
#include <cstdint>

// Constants of the MCAP container format, major version 0 (https://mcap.dev/spec).
namespace deepnav::mcap {

// 0x89 "MCAP" '0' "\r\n": the first and last 8 bytes of every file.
inline constexpr uint8_t kMagic[8] = {0x89, 'M', 'C', 'A', 'P', 0x30, '\r', '\n'};
inline constexpr size_t kMagicSize = sizeof(kMagic);

enum class Opcode : uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kAttachment = 0x09,
  kAttachmentIndex = 0x0A,
  kStatistics = 0x0B,
  kMetadata = 0x0C,
  kMetadataIndex = 0x0D,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F,
};

// Every record starts with a 1-byte opcode and a uint64 content length.
inline constexpr size_t kRecordPrefixSize = 1 + 8;

// The little-endian uint64 at p (a record prefix's length field: p = prefix + 1).
inline uint64_t le64(const uint8_t* p) {
  uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}
// Footer content: summary_start (8) + summary_offset_start (8) + summary_crc (4).
inline constexpr size_t kFooterContentSize = 8 + 8 + 4;
inline constexpr size_t kFooterRecordSize = kRecordPrefixSize + kFooterContentSize;
// Message content before the payload: channel_id, sequence, log_time, publish_time.
inline constexpr size_t kMessageFixedSize = 2 + 4 + 8 + 8;
// Chunk content before the compression string: start, end, uncompressed_size, uncompressed_crc.
inline constexpr size_t kChunkFixedSize = 8 + 8 + 8 + 4;

}  // namespace deepnav::mcap
