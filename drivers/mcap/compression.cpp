#include "drivers/mcap/compression.h"

#include <lz4frame.h>
#include <zstd.h>

#include <cstring>

namespace deepnav::mcap {
namespace {

LZ4F_preferences_t lz4Preferences(int level, size_t content_size) {
  LZ4F_preferences_t prefs;
  std::memset(&prefs, 0, sizeof(prefs));
  prefs.compressionLevel = level;
  // The content size in the frame header lets any reader size its output without guessing.
  prefs.frameInfo.contentSize = content_size;
  prefs.autoFlush = 1;  // no internal staging copy of the input
  return prefs;
}

}  // namespace

std::string_view compressionName(Compression c) {
  switch (c) {
    case Compression::kZstd:
      return "zstd";
    case Compression::kLz4:
      return "lz4";
    case Compression::kNone:
      break;
  }
  return "";
}

ChunkCompressor::~ChunkCompressor() { release(); }

void ChunkCompressor::release() {
  ZSTD_freeCCtx(zstd_);
  zstd_ = nullptr;
  if (lz4_ != nullptr) LZ4F_freeCompressionContext(lz4_);
  lz4_ = nullptr;
}

bool ChunkCompressor::init(Compression c, int level, std::string* error) {
  release();
  compression_ = c;
  level_ = level;
  if (c == Compression::kZstd) {
    zstd_ = ZSTD_createCCtx();
    if (zstd_ == nullptr) {
      *error = "cannot create a zstd compression context";
      return false;
    }
    const size_t rc = ZSTD_CCtx_setParameter(zstd_, ZSTD_c_compressionLevel, level);
    if (ZSTD_isError(rc)) {
      *error = std::string("zstd level ") + std::to_string(level) + ": " + ZSTD_getErrorName(rc);
      return false;
    }
  } else if (c == Compression::kLz4) {
    const LZ4F_errorCode_t rc = LZ4F_createCompressionContext(&lz4_, LZ4F_VERSION);
    if (LZ4F_isError(rc)) {
      *error = std::string("cannot create an lz4 compression context: ") + LZ4F_getErrorName(rc);
      return false;
    }
  }
  return true;
}

size_t ChunkCompressor::bound(size_t input_size) const {
  switch (compression_) {
    case Compression::kZstd:
      return ZSTD_compressBound(input_size);
    case Compression::kLz4: {
      const LZ4F_preferences_t prefs = lz4Preferences(level_, input_size);
      return LZ4F_HEADER_SIZE_MAX + LZ4F_compressBound(input_size, &prefs) +
             LZ4F_compressBound(0, &prefs);
    }
    case Compression::kNone:
      break;
  }
  return input_size;
}

size_t ChunkCompressor::compress(const uint8_t* data, size_t size, uint8_t* out,
                                 size_t out_capacity, std::string* error) {
  switch (compression_) {
    case Compression::kZstd:
      return compressZstd(data, size, out, out_capacity, error);
    case Compression::kLz4:
      return compressLz4(data, size, out, out_capacity, error);
    case Compression::kNone:
      break;
  }
  if (out_capacity < size) {
    *error = "compression buffer too small";
    return 0;
  }
  std::memcpy(out, data, size);
  return size;
}

size_t ChunkCompressor::compressZstd(const uint8_t* data, size_t size, uint8_t* out, size_t cap,
                                     std::string* error) {
  const size_t n = ZSTD_compress2(zstd_, out, cap, data, size);
  if (ZSTD_isError(n)) {
    *error = std::string("zstd compression failed: ") + ZSTD_getErrorName(n);
    return 0;
  }
  return n;
}

size_t ChunkCompressor::compressLz4(const uint8_t* data, size_t size, uint8_t* out, size_t cap,
                                    std::string* error) {
  const LZ4F_preferences_t prefs = lz4Preferences(level_, size);
  size_t total = LZ4F_compressBegin(lz4_, out, cap, &prefs);
  if (!LZ4F_isError(total)) {
    const size_t body = LZ4F_compressUpdate(lz4_, out + total, cap - total, data, size, nullptr);
    if (LZ4F_isError(body)) {
      total = body;
    } else {
      total += body;
      const size_t end = LZ4F_compressEnd(lz4_, out + total, cap - total, nullptr);
      total = LZ4F_isError(end) ? end : total + end;
    }
  }
  if (LZ4F_isError(total)) {
    *error = std::string("lz4 compression failed: ") + LZ4F_getErrorName(total);
    return 0;
  }
  return total;
}

ChunkDecompressor::~ChunkDecompressor() {
  ZSTD_freeDCtx(zstd_);
  if (lz4_ != nullptr) LZ4F_freeDecompressionContext(lz4_);
}

bool ChunkDecompressor::decompress(std::string_view compression, const uint8_t* data, size_t size,
                                   uint8_t* out, size_t out_size, std::string* error) {
  if (compression.empty()) {
    if (size != out_size) {
      *error = "uncompressed chunk holds " + std::to_string(size) + " bytes, header says " +
               std::to_string(out_size);
      return false;
    }
    if (size > 0) std::memcpy(out, data, size);
    return true;
  }
  if (compression == "zstd") return decompressZstd(data, size, out, out_size, error);
  if (compression == "lz4") return decompressLz4(data, size, out, out_size, error);
  *error = "unsupported chunk compression '" + std::string(compression) + "'";
  return false;
}

bool ChunkDecompressor::decompressZstd(const uint8_t* data, size_t size, uint8_t* out,
                                       size_t out_size, std::string* error) {
  if (zstd_ == nullptr) zstd_ = ZSTD_createDCtx();
  if (zstd_ == nullptr) {
    *error = "cannot create a zstd decompression context";
    return false;
  }
  const size_t n = ZSTD_decompressDCtx(zstd_, out, out_size, data, size);
  if (ZSTD_isError(n)) {
    *error = std::string("zstd: ") + ZSTD_getErrorName(n);
    return false;
  }
  if (n != out_size) {
    *error = "zstd chunk decompressed to " + std::to_string(n) + " bytes, header says " +
             std::to_string(out_size);
    return false;
  }
  return true;
}

bool ChunkDecompressor::decompressLz4(const uint8_t* data, size_t size, uint8_t* out,
                                      size_t out_size, std::string* error) {
  if (lz4_ == nullptr) {
    const LZ4F_errorCode_t rc = LZ4F_createDecompressionContext(&lz4_, LZ4F_VERSION);
    if (LZ4F_isError(rc)) {
      lz4_ = nullptr;
      *error = "cannot create an lz4 decompression context";
      return false;
    }
  }
  LZ4F_resetDecompressionContext(lz4_);  // a previous corrupt chunk may have left it mid-frame
  size_t in_pos = 0;
  size_t out_pos = 0;
  size_t hint = 1;
  while (hint != 0) {
    size_t in_n = size - in_pos;
    size_t out_n = out_size - out_pos;
    hint = LZ4F_decompress(lz4_, out + out_pos, &out_n, data + in_pos, &in_n, nullptr);
    if (LZ4F_isError(hint)) {
      *error = std::string("lz4: ") + LZ4F_getErrorName(hint);
      return false;
    }
    in_pos += in_n;
    out_pos += out_n;
    if (hint != 0 && in_n == 0 && out_n == 0) {
      *error = "lz4 frame ends early or decompresses to more than " + std::to_string(out_size) +
               " bytes";
      return false;
    }
  }
  if (out_pos != out_size || in_pos != size) {
    *error = "lz4 chunk decompressed to " + std::to_string(out_pos) + " bytes from " +
             std::to_string(in_pos) + " of " + std::to_string(size) + ", header says " +
             std::to_string(out_size);
    return false;
  }
  return true;
}

}  // namespace deepnav::mcap
