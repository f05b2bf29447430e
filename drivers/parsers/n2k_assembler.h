#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

#include "drivers/parsers/can_frame.h"
#include "drivers/parsers/n2k_message.h"

namespace deepnav {

// Turns NMEA 2000 CAN frames into messages. Single-frame PGNs pass straight through; PGNs listed as
// fast packet are reassembled: the first frame holds a sequence counter (bits 5-7 of byte 0), frame
// counter 0 (bits 0-4) and the total length (byte 1) followed by 6 bytes, each later frame its counter
// and 7 bytes. One reassembly slot per (source, PGN) in a fixed table; a frame out of order drops the
// message in progress and is reported.
class N2kAssembler {
 public:
  static constexpr int kSlots = 32;
  static constexpr int kMaxFastPacketPgns = 64;

  enum class Result { kNone, kMessage, kError };

  N2kAssembler();
  // Replaces the built-in list of fast-packet PGNs (at most kMaxFastPacketPgns).
  bool setFastPacketPgns(const uint32_t* pgns, int n);
  bool isFastPacket(uint32_t pgn) const;

  // kMessage: *message is complete. kError: *error says why the frame was dropped.
  Result add(const CanFrame& frame, N2kMessage* message, const char** error);

 private:
  struct Slot {
    bool used = false;
    uint8_t source = 0;
    uint32_t pgn = 0;
    uint8_t sequence = 0;
    uint8_t next_frame = 0;
    size_t expected = 0;
    N2kMessage message;
  };
  Slot* findSlot(uint8_t source, uint32_t pgn, bool create);

  std::array<uint32_t, kMaxFastPacketPgns> fast_pgns_{};
  int num_fast_pgns_ = 0;
  std::array<Slot, kSlots> slots_{};
  int next_victim_ = 0;
};

}  // namespace deepnav
