#pragma once
#include <cstdint>
#include <string>

#include "drivers/parsers/can_frame.h"

namespace deepnav {

// Acceptance filter: a frame passes when (id & mask) == (filter id & mask), same identifier length.
struct CanFilter {
  uint32_t id = 0;
  uint32_t mask = 0;
  bool extended = true;
};

// A SocketCAN raw socket (CAN_RAW) bound to one interface, with acceptance filters and error frames
// (CAN_RAW_ERR_FILTER: controller problems, bus-off, restarts, bus errors, counters). Reads wait at most
// timeout_ms with poll(). The frame exchange works on any socket carrying struct can_frame, which is how
// the tests drive it through a socketpair.
class SocketCan {
 public:
  enum class Read { kFrame, kErrorFrame, kTimeout, kFailed };
  static constexpr int kMaxFilters = 16;

  SocketCan() = default;
  SocketCan(const SocketCan&) = delete;
  SocketCan& operator=(const SocketCan&) = delete;
  ~SocketCan();

  bool open(const std::string& interface, const CanFilter* filters, int num_filters, std::string* error);
  // Takes ownership of a connected socket that carries struct can_frame (tests: socketpair).
  void adopt(int fd);
  void close();
  bool isOpen() const { return fd_ >= 0; }
  int fd() const { return fd_; }

  // kFrame: *frame is a data frame. kErrorFrame: *frame holds the error data, *error_id the error class
  // bits (CAN_ERR_*). kFailed: the socket failed (interface down): close and reopen.
  Read read(CanFrame* frame, uint32_t* error_id, int timeout_ms);
  bool write(const CanFrame& frame);

  // Asks the kernel to restart the controller after bus-off (rtnetlink IFLA_CAN_RESTART; needs
  // CAP_NET_ADMIN and a real CAN controller). False with *error when refused.
  static bool requestRestart(const std::string& interface, std::string* error);

 private:
  int fd_ = -1;
};

}  // namespace deepnav
