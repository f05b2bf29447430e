#include "drivers/rosbag/chunk_decompression.h"

#include <bzlib.h>
#include <lz4frame.h>

#include <algorithm>
#include <cstring>
#include <memory>

namespace deepnav::rosbag {
namespace {

// bzip2's stream API consumes `unsigned int` counts: feed at most this much per call.
constexpr size_t kBzStep = size_t(1) << 30;

void bz2Prefix(const uint8_t* in, size_t in_size, size_t out_size, std::vector<uint8_t>* out) {
  bz_stream s;
  std::memset(&s, 0, sizeof(s));
  if (BZ2_bzDecompressInit(&s, 0, 0) != BZ_OK) {
    out->clear();
    return;
  }
  size_t in_pos = 0;
  size_t out_pos = 0;
  for (;;) {
    const size_t in_n = std::min(in_size - in_pos, kBzStep);
    const size_t out_n = std::min(out_size - out_pos, kBzStep);
    s.next_in = const_cast<char*>(reinterpret_cast<const char*>(in + in_pos));
    s.avail_in = unsigned(in_n);
    s.next_out = reinterpret_cast<char*>(out->data() + out_pos);
    s.avail_out = unsigned(out_n);
    const int rc = BZ2_bzDecompress(&s);
    in_pos += in_n - s.avail_in;
    out_pos += out_n - s.avail_out;
    const bool progress = s.avail_in != in_n || s.avail_out != out_n;
    if (rc != BZ_OK || !progress || out_pos == out_size) break;
  }
  BZ2_bzDecompressEnd(&s);
  out->resize(out_pos);
}

void lz4Prefix(const uint8_t* in, size_t in_size, size_t out_size, std::vector<uint8_t>* out) {
  LZ4F_dctx* raw = nullptr;
  if (LZ4F_isError(LZ4F_createDecompressionContext(&raw, LZ4F_VERSION))) {
    out->clear();
    return;
  }
  std::unique_ptr<LZ4F_dctx, decltype(&LZ4F_freeDecompressionContext)> ctx(
      raw, &LZ4F_freeDecompressionContext);
  size_t in_pos = 0;
  size_t out_pos = 0;
  for (;;) {
    size_t in_n = in_size - in_pos;
    size_t out_n = out_size - out_pos;
    const size_t hint =
        LZ4F_decompress(ctx.get(), out->data() + out_pos, &out_n, in + in_pos, &in_n, nullptr);
    if (LZ4F_isError(hint)) break;
    in_pos += in_n;
    out_pos += out_n;
    if (hint == 0 || (in_n == 0 && out_n == 0)) break;
  }
  out->resize(out_pos);
}

}  // namespace

bool isKnownCompression(std::string_view compression) {
  return compression == "none" || compression == "bz2" || compression == "lz4";
}

bool ChunkDecompressor::decompress(std::string_view compression, const uint8_t* in,
                                   size_t in_size, size_t out_size, std::vector<uint8_t>* out,
                                   std::string* what) {
  if (compression == "none") {
    if (in_size != out_size) {
      *what = "uncompressed chunk holds " + std::to_string(in_size) + " bytes, field 'size' says " +
              std::to_string(out_size);
      return false;
    }
    out->assign(in, in + in_size);
    return true;
  }
  if (compression == "lz4" && out_size / 256 > in_size) {
    // LZ4 expands at most ~255 times (a literal run of one byte), so this 'size' is corrupt.
    *what = "lz4 chunk of " + std::to_string(in_size) + " bytes cannot hold field 'size' (" +
            std::to_string(out_size) + " bytes)";
    return false;
  }
  out->resize(out_size);
  if (compression == "bz2") return bz2(in, in_size, out_size, out, what);
  if (compression == "lz4") {
    if (!lz4_.decompress("lz4", in, in_size, out->data(), out_size, what)) {
      *what = "lz4 chunk (field 'size' " + std::to_string(out_size) + "): " + *what;
      return false;
    }
    return true;
  }
  *what = "field 'compression' is '" + std::string(compression) +
          "', this reader knows none, bz2 and lz4";
  return false;
}

bool ChunkDecompressor::bz2(const uint8_t* in, size_t in_size, size_t out_size,
                            std::vector<uint8_t>* out, std::string* what) {
  if (in_size > kBzStep || out_size > kBzStep) {
    *what = "bz2 chunk larger than 1 GiB";
    return false;
  }
  unsigned produced = unsigned(out_size);
  char empty = 0;
  char* dest = out_size > 0 ? reinterpret_cast<char*>(out->data()) : &empty;
  const int rc = BZ2_bzBuffToBuffDecompress(dest, &produced,
                                            const_cast<char*>(reinterpret_cast<const char*>(in)),
                                            unsigned(in_size), 0, 0);
  if (rc == BZ_OUTBUFF_FULL) {
    *what = "bz2 chunk decompresses to more than field 'size' (" + std::to_string(out_size) +
            " bytes)";
    return false;
  }
  if (rc != BZ_OK) {
    *what = "bz2 chunk is corrupt (libbz2 error " + std::to_string(rc) + ")";
    return false;
  }
  if (produced != out_size) {
    *what = "bz2 chunk decompressed to " + std::to_string(produced) + " bytes, field 'size' says " +
            std::to_string(out_size);
    return false;
  }
  return true;
}

void ChunkDecompressor::decompressPrefix(std::string_view compression, const uint8_t* in,
                                         size_t in_size, size_t out_size,
                                         std::vector<uint8_t>* out) {
  out->assign(out_size, 0);
  if (compression == "none") {
    const size_t n = std::min(in_size, out_size);
    if (n > 0) std::memcpy(out->data(), in, n);
    out->resize(n);
  } else if (compression == "bz2") {
    bz2Prefix(in, in_size, out_size, out);
  } else if (compression == "lz4") {
    lz4Prefix(in, in_size, out_size, out);
  } else {
    out->clear();
  }
}

}  // namespace deepnav::rosbag
