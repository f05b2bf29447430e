#pragma once
#include <cstdint>
#include <string>

#include "drivers/outputs/nav_output.h"

namespace deepnav {

// The Modbus register map of the solution for the vehicle PLC (board/service/README.md has the table,
// printed by describeRegisterMap()). The same block is served as holding registers (function 3) and input
// registers (function 4), from address 0. 32-bit values take two registers, high word first; floats are
// IEEE-754 binary32 in that order ("ABCD", libmodbus modbus_get_float_abcd); u64 takes four registers,
// most significant first. Angles in degrees, positions in metres, frames as in the README (odom ENU,
// robot FLU).
namespace reg {
enum : std::uint16_t {
  kMagic = 0,          // u16 0x444E ("DN")
  kVersion = 1,        // u16 map version
  kSequence = 2,       // u32 tick sequence (wraps)
  kTimeUs = 4,         // u64 solution time, monotonic us
  kStage = 8,          // u16 NavStage
  kStatus = 9,         // u16 NavStatusBits
  kFaults = 10,        // u32 fault bits
  kHealth = 12,        // u32 NavHealthBits
  kEast = 14,          // f32 position in odom
  kNorth = 16,
  kUp = 18,
  kDepth = 20,         // f32 depth (positive down) = -up
  kRoll = 22,          // f32 deg, ZYX Euler of q_odom_robot
  kPitch = 24,
  kYaw = 26,           // f32 deg, ENU (counter-clockwise from east)
  kHeading = 28,       // f32 deg, clockwise from north in [0, 360)
  kQx = 30,            // f32 q_odom_robot
  kQy = 32,
  kQz = 34,
  kQw = 36,
  kVelEast = 38,       // f32 m/s in odom
  kVelNorth = 40,
  kVelUp = 42,
  kVelForward = 44,    // f32 m/s in the robot frame (FLU)
  kVelLeft = 46,
  kVelRobotUp = 48,
  kRateRoll = 50,      // f32 deg/s, robot frame
  kRatePitch = 52,
  kRateYaw = 54,
  kVarEast = 56,       // f32 pose covariance diagonal: m^2 (3), rad^2 (3)
  kVarNorth = 58,
  kVarUp = 60,
  kVarRoll = 62,
  kVarPitch = 64,
  kVarYaw = 66,
  kVarVelEast = 68,    // f32 (m/s)^2
  kVarVelNorth = 70,
  kVarVelUp = 72,
  kImageQuality = 74,  // f32 in [0, 1], -1 before the first image
  kRejected = 76,      // u32 counters, cumulative
  kDroppedLate = 78,
  kTicks = 80,
  kLateTicks = 82,
  kNavOverruns = 84,
  kVisionOverruns = 86,
  kRecorderDrops = 88,
  kInputsRefused = 90,
  kImuCount = 92,
  kDvlCount = 94,
  kDepthCount = 96,
  kHeadingCount = 98,
  kAttitudeCount = 100,
  kVisionCount = 102,
  kCount = 104,        // registers in the map
};
}  // namespace reg

constexpr std::uint16_t kRegisterMagic = 0x444E;
constexpr std::uint16_t kRegisterMapVersion = 1;

// Fills regs[0, reg::kCount) from one output.
void encodeRegisters(const NavOutput& out, std::uint16_t* regs);

// Readers of the map's encodings (tests and PLC-side tools).
float registerFloat(const std::uint16_t* regs, std::uint16_t address);
std::uint32_t registerU32(const std::uint16_t* regs, std::uint16_t address);
std::uint64_t registerU64(const std::uint16_t* regs, std::uint16_t address);

// Markdown table of the map (address, type, name, unit, meaning).
std::string describeRegisterMap();

}  // namespace deepnav
