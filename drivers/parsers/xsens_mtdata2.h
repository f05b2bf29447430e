#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

#include "nav/types/attitude_sample.h"
#include "nav/types/imu_sample.h"

namespace deepnav {

// Content of one Xsens MTData2 message (Xbus message ID 0x36): a sequence of packets, each a 16-bit
// data identifier (XDI, big-endian), a size byte and big-endian values. The low two bits of the XDI
// give the number format (float32, fixed 12.20, fixed 16.32, float64), bits 2-3 the orientation frame
// (ENU, NED, NWU). Units: quaternion (w, x, y, z) sensor -> local frame; Euler roll, pitch, yaw (rad);
// acceleration m/s^2; rate of turn rad/s; magnetic field arbitrary units (normalised); sample time fine
// in 1e-4 s ticks. Unknown XDIs are skipped.
struct XsensMtData2 {
  enum Frame : uint8_t { kEnu = 0, kNed = 1, kNwu = 2 };
  bool has_packet_counter = false;
  uint16_t packet_counter = 0;
  bool has_sample_time_fine = false;
  uint32_t sample_time_fine = 0;
  bool has_quaternion = false;
  std::array<double, 4> quaternion{};  // w, x, y, z
  uint8_t quaternion_frame = kEnu;
  bool has_euler = false;
  std::array<double, 3> euler_rad{};    // roll, pitch, yaw
  uint8_t euler_frame = kEnu;
  bool has_acceleration = false;
  std::array<double, 3> acceleration_mps2{};
  bool has_rate_of_turn = false;
  std::array<double, 3> rate_of_turn_radps{};
  bool has_magnetic_field = false;
  std::array<double, 3> magnetic_field{};
  bool has_status_word = false;
  uint32_t status_word = 0;
  int num_packets = 0;
};

constexpr uint8_t kXbusMtData2 = 0x36;

// Decodes an MTData2 payload; false (with *error) when a packet runs past the payload or has a size
// that does not match its XDI's number format.
bool decodeXsensMtData2(const uint8_t* payload, size_t size, XsensMtData2* out, const char** error);

// ImuSample (rates, specific force, orientation when the quaternion is in ENU) and AttitudeSample
// (roll, pitch from the ENU quaternion or Euler angles). The Xsens sensor frame is x forward, y left,
// z up: already FLU. False when the message has neither rate nor acceleration (resp. no orientation).
bool imuSampleFromXsens(const XsensMtData2& m, TimeUs t_us, ImuSample* sample);
bool attitudeSampleFromXsens(const XsensMtData2& m, TimeUs t_us, AttitudeSample* sample);

}  // namespace deepnav
