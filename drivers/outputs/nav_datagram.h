#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "drivers/outputs/nav_output.h"

namespace deepnav {

// The UDP solution datagram for the topside (board/service/README.md, "UDP datagram"): one per tick,
// fixed size, little-endian, doubles in IEEE-754 binary64, ending with a CRC-32 (zlib's) of every byte
// before it. Offsets:
//   0 char[4] "DNAV"           4 u16 version (1)        6 u16 length (336)      8 u32 sequence
//  12 i64 t_us                20 u8 stage, 3 bytes 0   24 u32 status           28 u32 faults
//  32 u32 health              36 f64[3] p_robot_in_odom_m                      60 f64[4] q_odom_robot (x y z w)
//  92 f64[3] v_robot_in_odom_mps     116 f64[3] w_robot_radps
// 140 f64[6] pose covariance diagonal (x y z roll pitch yaw)   188 f64[3] velocity covariance diagonal
// 212 f64 image_quality      220 u64[14] rejected_total, dropped_late_total, ticks, late_ticks,
//                                nav_overruns, vision_overruns, recorder_drops, inputs_refused,
//                                imu, dvl, depth, heading, attitude, vision
// 332 u32 crc32 of bytes [0, 332)
constexpr std::size_t kNavDatagramSize = 336;
constexpr std::uint16_t kNavDatagramVersion = 1;

void encodeNavDatagram(const NavOutput& out, std::uint8_t* buffer);

// Checks magic, version, length and CRC; on failure says which.
bool decodeNavDatagram(const std::uint8_t* data, std::size_t size, NavOutput* out, std::string* error);

}  // namespace deepnav
