#pragma once
#include <array>
#include <cstdint>

#include "drivers/parsers/n2k_message.h"
#include "nav/types/attitude_sample.h"
#include "nav/types/heading_sample.h"

namespace deepnav {

// NMEA 2000 PGNs of a compass or attitude sensor, in SI units. Angles are stored as 1e-4 rad
// (heading unsigned, others signed), the rate of turn as a signed 32-bit count of 1e-6/32 rad/s;
// 0xFFFF / 0x7FFF / 0x7FFFFFFF mean "not available" and give has_* = false.
constexpr uint32_t kPgnVesselHeading = 127250;
constexpr uint32_t kPgnRateOfTurn = 127251;
constexpr uint32_t kPgnAttitude = 127257;

struct N2kVesselHeading {  // 127250
  uint8_t sid = 0;
  bool has_heading = false, has_deviation = false, has_variation = false;
  double heading_rad = 0, deviation_rad = 0, variation_rad = 0;
  uint8_t reference = 3;  // 0 true, 1 magnetic, 2 error, 3 null
};

struct N2kRateOfTurn {  // 127251
  uint8_t sid = 0;
  bool has_rate = false;
  double rate_radps = 0;  // positive: bow turns to starboard
  std::array<uint8_t, 3> reserved{};
};

struct N2kAttitude {  // 127257
  uint8_t sid = 0;
  bool has_yaw = false, has_pitch = false, has_roll = false;
  double yaw_rad = 0, pitch_rad = 0, roll_rad = 0;  // NED: pitch positive bow up, roll positive starboard down
};

// False (with *error) when the payload is shorter than the PGN's fixed size or a value is out of range.
bool decodeN2kVesselHeading(const N2kMessage& m, N2kVesselHeading* out, const char** error);
bool decodeN2kRateOfTurn(const N2kMessage& m, N2kRateOfTurn* out, const char** error);
bool decodeN2kAttitude(const N2kMessage& m, N2kAttitude* out, const char** error);

// Samples: 127250 -> heading (magnetic + deviation when given; variation left to the EKF's
// declination); 127257 -> roll and pitch in REP-103 (roll unchanged, pitch negated: FLU pitch is
// positive nose down).
bool headingSampleFromN2k(const N2kVesselHeading& h, TimeUs t_us, HeadingSample* sample);
bool attitudeSampleFromN2k(const N2kAttitude& a, TimeUs t_us, AttitudeSample* sample);

}  // namespace deepnav
