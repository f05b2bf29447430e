#include "drivers/camera/camera_status.h"

#include <sstream>

namespace deepnav {

const char* frameStatusName(CameraFrameStatus status) {
  switch (status) {
    case CameraFrameStatus::kOk: return "ok";
    case CameraFrameStatus::kCleared: return "cleared";
    case CameraFrameStatus::kTimeout: return "timeout";
    case CameraFrameStatus::kMissingPackets: return "missing_packets";
    case CameraFrameStatus::kWrongPacketId: return "wrong_packet_id";
    case CameraFrameStatus::kSizeMismatch: return "size_mismatch";
    case CameraFrameStatus::kFilling: return "filling";
    case CameraFrameStatus::kAborted: return "aborted";
    case CameraFrameStatus::kPayloadNotSupported: return "payload_not_supported";
    case CameraFrameStatus::kUnknown: return "unknown";
    case CameraFrameStatus::kWrongFormat: return "wrong_format";
    case CameraFrameStatus::kDeviceError: return "device_error";
    case CameraFrameStatus::kCount: break;
  }
  return "invalid";
}

std::uint64_t CameraSideStatus::bad() const {
  std::uint64_t n = 0;
  for (std::size_t i = 1; i < kFrameStatusCount; ++i) n += frames[i];
  return n;
}

namespace {

CameraSideStatus snapshotSide(const CameraCounters::Side& s) {
  CameraSideStatus out;
  for (std::size_t i = 0; i < kFrameStatusCount; ++i) out.frames[i] = s.frames[i].load(std::memory_order_relaxed);
  out.connected = s.connected.load(std::memory_order_relaxed);
  out.stale = s.stale.load(std::memory_order_relaxed);
  out.stale_events = s.stale_events.load(std::memory_order_relaxed);
  out.reconnects = s.reconnects.load(std::memory_order_relaxed);
  out.reconnect_failures = s.reconnect_failures.load(std::memory_order_relaxed);
  out.control_lost = s.control_lost.load(std::memory_order_relaxed);
  out.triggers = s.triggers.load(std::memory_order_relaxed);
  out.trigger_skips = s.trigger_skips.load(std::memory_order_relaxed);
  out.trigger_timeouts = s.trigger_timeouts.load(std::memory_order_relaxed);
  out.unattributed = s.unattributed.load(std::memory_order_relaxed);
  out.slow_triggers = s.slow_triggers.load(std::memory_order_relaxed);
  out.last_good_frame_us = s.last_good_frame_us.load(std::memory_order_relaxed);
  return out;
}

void sideJson(std::ostringstream& o, const CameraSideStatus& s) {
  o << "{\"connected\":" << (s.connected ? "true" : "false") << ",\"stale\":" << (s.stale ? "true" : "false")
    << ",\"stale_events\":" << s.stale_events << ",\"reconnects\":" << s.reconnects
    << ",\"reconnect_failures\":" << s.reconnect_failures << ",\"control_lost\":" << s.control_lost
    << ",\"triggers\":" << s.triggers << ",\"trigger_skips\":" << s.trigger_skips
    << ",\"trigger_timeouts\":" << s.trigger_timeouts << ",\"unattributed\":" << s.unattributed
    << ",\"slow_triggers\":" << s.slow_triggers
    << ",\"frames\":{";
  bool first = true;
  for (std::size_t i = 0; i < kFrameStatusCount; ++i) {
    if (s.frames[i] == 0 && i != 0) continue;
    o << (first ? "" : ",") << '"' << frameStatusName(static_cast<CameraFrameStatus>(i)) << "\":" << s.frames[i];
    first = false;
  }
  o << "}}";
}

}  // namespace

CameraStatus CameraCounters::snapshot() const {
  CameraStatus out;
  out.left = snapshotSide(left);
  out.right = snapshotSide(right);
  out.pairs = pairs.load(std::memory_order_relaxed);
  out.unpaired = unpaired.load(std::memory_order_relaxed);
  out.pool_exhausted = pool_exhausted.load(std::memory_order_relaxed);
  out.ring_full = ring_full.load(std::memory_order_relaxed);
  out.max_pair_skew_us = max_pair_skew_us.load(std::memory_order_relaxed);
  return out;
}

std::string cameraStatusJson(const CameraStatus& s) {
  std::ostringstream o;
  o << "{\"pairs\":" << s.pairs << ",\"unpaired\":" << s.unpaired << ",\"pool_exhausted\":" << s.pool_exhausted
    << ",\"ring_full\":" << s.ring_full
    << ",\"max_pair_skew_us\":" << s.max_pair_skew_us << ",\"left\":";
  sideJson(o, s.left);
  o << ",\"right\":";
  sideJson(o, s.right);
  o << '}';
  return o.str();
}

}  // namespace deepnav
