#pragma once
#include <cstddef>
#include <cstdint>

#include "drivers/parsers/binary_framer.h"
#include "drivers/parsers/frame_result.h"

namespace deepnav {

// Finds Teledyne RDI PD0 ensembles in a byte stream. An ensemble starts with the header ID 0x7F 0x7F,
// bytes 2-3 hold its length N (little-endian, without the checksum), byte 5 the number of data types,
// the offsets of the data types follow (each inside the ensemble, increasing), and the 16-bit sum of
// bytes [0, N) follows at N. A frame whose length or offsets are out of range or whose checksum fails
// is reported and the search restarts one byte after its header, so a good ensemble that a corrupted
// length had swallowed is still found. While an ensemble is incomplete, the bytes
// already held are probed for a later complete, checksum-valid ensemble followed by a header: one is
// taken as proof that the first header was false (a live line then does not wait for bytes that belong
// to later ensembles). After endOfInput() an incomplete ensemble is dropped one byte at a time so the
// ensembles inside it are found. After skipped bytes, a checksum-valid ensemble is refused when a
// valid ensemble starting inside it runs past its end and is followed by a header.
class Pd0Framer : public BinaryFramer<Pd0Framer, 0x7F> {
 public:
  static constexpr size_t kMinEnsembleBytes = 6;
  // max_ensemble_bytes bounds the length field (and sizes the buffer).
  bool init(size_t max_ensemble_bytes);
  FrameStatus next(RawFrame* frame, FrameError* error);

 private:
  friend class BinaryFramer<Pd0Framer, 0x7F>;
  using Check = FrameCheck;
  // The candidate ensemble whose header starts `at` bytes into the buffer.
  Check checkAt(size_t at, size_t* frame_bytes, const char** reason, bool check_offsets = true) const;
  bool headerAt(size_t at) const;

  size_t max_bytes_ = 0;
};

}  // namespace deepnav
