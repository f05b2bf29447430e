#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

#include "drivers/parsers/can_frame.h"

namespace deepnav {

// An NMEA 2000 message: the 29-bit CAN identifier split per ISO 11783 / J1939 (priority, PGN, source,
// destination) and the payload, which a fast-packet PGN spreads over several frames.
struct N2kMessage {
  static constexpr size_t kMaxPayload = 223;  // fast packet: 6 + 31 * 7 bytes
  uint8_t priority = 0;
  uint32_t pgn = 0;
  uint8_t source = 0;
  uint8_t destination = 255;
  size_t size = 0;
  std::array<uint8_t, kMaxPayload> data{};
};

// Priority (bits 26-28), PGN and addresses of an extended identifier. In PDU1 format (PF < 240) the
// PS byte is the destination and is not part of the PGN; in PDU2 it is, and the message is broadcast.
inline void splitN2kId(uint32_t id, N2kMessage* m) {
  m->priority = uint8_t((id >> 26) & 0x7);
  const uint32_t dp = (id >> 24) & 0x3;  // EDP and DP
  const uint32_t pf = (id >> 16) & 0xFF;
  const uint32_t ps = (id >> 8) & 0xFF;
  m->source = uint8_t(id & 0xFF);
  if (pf < 240) {
    m->pgn = (dp << 16) | (pf << 8);
    m->destination = uint8_t(ps);
  } else {
    m->pgn = (dp << 16) | (pf << 8) | ps;
    m->destination = 255;
  }
}

}  // namespace deepnav
