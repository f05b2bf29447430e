#pragma once
#include <array>
#include <cstdint>

namespace deepnav {

// One classic CAN frame, independent of the OS (drivers/can converts to and from struct can_frame).
struct CanFrame {
  uint32_t id = 0;        // 11-bit or 29-bit identifier, without flag bits
  bool extended = false;  // 29-bit identifier
  bool rtr = false;
  uint8_t dlc = 0;        // 0..8
  std::array<uint8_t, 8> data{};
};

}  // namespace deepnav
