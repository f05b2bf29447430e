#include "drivers/parsers/n2k_assembler.h"

#include <algorithm>

namespace deepnav {
namespace {

// Fast-packet PGNs of NMEA 2000 that a navigation bus commonly carries (product information,
// GNSS position and satellites, ...). 127250/127251/127257 are single-frame PGNs.
constexpr uint32_t kDefaultFastPgns[] = {126208, 126464, 126720, 126983, 126984, 126985, 126986, 126987, 126988,
                                         126996, 126998, 127233, 127237, 127489, 127496, 127497, 127498, 127503,
                                         127504, 127506, 127507, 127509, 128275, 128520, 129029, 129038, 129039,
                                         129040, 129041, 129044, 129045, 129284, 129285, 129301, 129302, 129538,
                                         129540, 129541, 129542, 129545, 129547, 129549, 129551, 129556, 129792,
                                         129793, 129794, 129795, 129796, 129797, 129798, 129800, 129801, 129802,
                                         129808, 129809, 129810, 130074, 130577};

}  // namespace

N2kAssembler::N2kAssembler() {
  setFastPacketPgns(kDefaultFastPgns, int(std::size(kDefaultFastPgns)));
}

bool N2kAssembler::setFastPacketPgns(const uint32_t* pgns, int n) {
  if (n < 0 || n > kMaxFastPacketPgns) return false;
  std::copy(pgns, pgns + n, fast_pgns_.begin());
  num_fast_pgns_ = n;
  return true;
}

bool N2kAssembler::isFastPacket(uint32_t pgn) const {
  return std::find(fast_pgns_.begin(), fast_pgns_.begin() + num_fast_pgns_, pgn) != fast_pgns_.begin() + num_fast_pgns_;
}

N2kAssembler::Slot* N2kAssembler::findSlot(uint8_t source, uint32_t pgn, bool create) {
  for (Slot& s : slots_) {
    if (s.used && s.source == source && s.pgn == pgn) return &s;
  }
  if (!create) return nullptr;
  for (Slot& s : slots_) {
    if (!s.used) return &s;
  }
  Slot* victim = &slots_[next_victim_];  // table full: recycle the slots in turn
  next_victim_ = (next_victim_ + 1) % kSlots;
  return victim;
}

N2kAssembler::Result N2kAssembler::add(const CanFrame& f, N2kMessage* out, const char** error) {
  if (!f.extended || f.rtr) return *error = "not an NMEA 2000 frame (standard identifier or RTR)", Result::kError;
  if (f.dlc > 8) return *error = "CAN frame length over 8", Result::kError;
  N2kMessage header;
  splitN2kId(f.id, &header);
  if (!isFastPacket(header.pgn)) {
    *out = header;
    out->size = f.dlc;
    std::copy(f.data.begin(), f.data.begin() + f.dlc, out->data.begin());
    return Result::kMessage;
  }
  if (f.dlc < 2) return *error = "fast-packet frame shorter than 2 bytes", Result::kError;
  const uint8_t sequence = f.data[0] >> 5;
  const uint8_t counter = f.data[0] & 0x1F;
  if (counter == 0) {
    Slot* s = findSlot(header.source, header.pgn, true);
    const bool interrupted = s->used && s->next_frame > 0;
    *s = Slot{};
    s->used = true;
    s->source = header.source;
    s->pgn = header.pgn;
    s->sequence = sequence;
    s->expected = f.data[1];
    s->message = header;
    if (s->expected > N2kMessage::kMaxPayload) {
      s->used = false;
      return *error = "fast-packet length over 223 bytes", Result::kError;
    }
    const size_t take = std::min<size_t>(s->expected, f.dlc - 2);
    std::copy(f.data.begin() + 2, f.data.begin() + 2 + take, s->message.data.begin());
    s->message.size = take;
    s->next_frame = 1;
    if (s->message.size == s->expected) {
      s->used = false;
      *out = s->message;
      return Result::kMessage;
    }
    if (interrupted) return *error = "fast-packet message restarted before it was complete", Result::kError;
    return Result::kNone;
  }
  Slot* s = findSlot(header.source, header.pgn, false);
  if (s == nullptr) return *error = "fast-packet continuation without a first frame", Result::kError;
  if (sequence != s->sequence || counter != s->next_frame) {
    s->used = false;
    return *error = "fast-packet frame out of order", Result::kError;
  }
  const size_t take = std::min<size_t>(s->expected - s->message.size, f.dlc - 1);
  std::copy(f.data.begin() + 1, f.data.begin() + 1 + take, s->message.data.begin() + s->message.size);
  s->message.size += take;
  ++s->next_frame;
  if (s->message.size < s->expected) return Result::kNone;
  s->used = false;
  *out = s->message;
  return Result::kMessage;
}

}  // namespace deepnav
