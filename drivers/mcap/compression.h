#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

// Chunk compression: zstd (single frame) or LZ4 (frame format, as MCAP's registry requires),
// from Debian's libzstd and liblz4. Contexts are created once and reused for every chunk, so
// compressing a chunk does not allocate in steady state.
struct ZSTD_CCtx_s;
struct ZSTD_DCtx_s;
struct LZ4F_cctx_s;
struct LZ4F_dctx_s;

namespace deepnav::mcap {

enum class Compression { kNone, kZstd, kLz4 };

// The name written in the Chunk record's compression field: "", "zstd", "lz4".
std::string_view compressionName(Compression c);

class ChunkCompressor {
 public:
  ChunkCompressor() = default;
  ~ChunkCompressor();
  ChunkCompressor(const ChunkCompressor&) = delete;
  ChunkCompressor& operator=(const ChunkCompressor&) = delete;

  // level: zstd 1..19 (0: library default) or LZ4 acceleration-free levels 0..12 (0: fast).
  bool init(Compression c, int level, std::string* error);
  // Largest output compress() can produce for `input_size` bytes.
  size_t bound(size_t input_size) const;
  // Compresses into out[0..), which must hold bound(size) bytes. Returns the compressed size,
  // 0 on failure (with *error set).
  size_t compress(const uint8_t* data, size_t size, uint8_t* out, size_t out_capacity,
                  std::string* error);

 private:
  size_t compressZstd(const uint8_t* data, size_t size, uint8_t* out, size_t cap,
                      std::string* error);
  size_t compressLz4(const uint8_t* data, size_t size, uint8_t* out, size_t cap,
                     std::string* error);
  void release();

  Compression compression_ = Compression::kNone;
  int level_ = 0;
  ZSTD_CCtx_s* zstd_ = nullptr;
  LZ4F_cctx_s* lz4_ = nullptr;
};

class ChunkDecompressor {
 public:
  ChunkDecompressor() = default;
  ~ChunkDecompressor();
  ChunkDecompressor(const ChunkDecompressor&) = delete;
  ChunkDecompressor& operator=(const ChunkDecompressor&) = delete;

  // Decompresses `size` bytes compressed with `compression` ("", "zstd", "lz4") into exactly
  // out_size bytes. False (with *error) on an unknown algorithm, corrupt input, or a size that
  // differs from out_size; never reads or writes outside the given ranges.
  bool decompress(std::string_view compression, const uint8_t* data, size_t size, uint8_t* out,
                  size_t out_size, std::string* error);

 private:
  bool decompressZstd(const uint8_t* data, size_t size, uint8_t* out, size_t out_size,
                      std::string* error);
  bool decompressLz4(const uint8_t* data, size_t size, uint8_t* out, size_t out_size,
                     std::string* error);

  ZSTD_DCtx_s* zstd_ = nullptr;
  LZ4F_dctx_s* lz4_ = nullptr;
};

}  // namespace deepnav::mcap
