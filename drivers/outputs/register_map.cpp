#include "drivers/outputs/register_map.h"

#include <cmath>
#include <cstring>
#include <sstream>

namespace deepnav {
namespace {

constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;

void putU32(std::uint16_t* regs, std::uint16_t a, std::uint32_t v) {
  regs[a] = static_cast<std::uint16_t>(v >> 16);
  regs[a + 1] = static_cast<std::uint16_t>(v & 0xFFFFu);
}

// Counters are cumulative u64 on our side; the PLC sees them modulo 2^32 (wrap-aware differences work).
void putCount(std::uint16_t* regs, std::uint16_t a, std::uint64_t v) { putU32(regs, a, static_cast<std::uint32_t>(v)); }

void putF32(std::uint16_t* regs, std::uint16_t a, double v) {
  const float f = static_cast<float>(v);
  std::uint32_t bits = 0;
  std::memcpy(&bits, &f, sizeof bits);
  putU32(regs, a, bits);
}

struct FieldDoc {
  std::uint16_t address;
  const char* type;
  const char* name;
  const char* unit;
  const char* meaning;
};

constexpr FieldDoc kFields[] = {
    {reg::kMagic, "u16", "magic", "-", "0x444E ('DN'): this is a deepnav map"},
    {reg::kVersion, "u16", "version", "-", "register map version (1)"},
    {reg::kSequence, "u32", "sequence", "-", "tick sequence number; changes every tick (freshness)"},
    {reg::kTimeUs, "u64", "t_us", "us", "solution time on the vehicle's monotonic clock"},
    {reg::kStage, "u16", "stage", "-", "0 init, 1 workspace definition, 2 optimised (stage 2)"},
    {reg::kStatus, "u16", "status", "bits",
     "attitude, velocity, depth, position valid; panel fixed; map ready; compass magnetically disturbed (bit 6)"},
    {reg::kFaults, "u32", "faults", "bits", "per source: stale bit 2k, rejected bit 2k+1 (imu, dvl, depth, heading, attitude, markers, vo_orb, vo_planes, camera)"},
    {reg::kHealth, "u32", "health", "bits", "service health in the last window (README: health bits)"},
    {reg::kEast, "f32", "east_m", "m", "position of the robot in odom, x (east)"},
    {reg::kNorth, "f32", "north_m", "m", "y (north)"},
    {reg::kUp, "f32", "up_m", "m", "z (up)"},
    {reg::kDepth, "f32", "depth_m", "m", "depth, positive down (= -up)"},
    {reg::kRoll, "f32", "roll_deg", "deg", "ZYX Euler angles of q_odom_robot"},
    {reg::kPitch, "f32", "pitch_deg", "deg", ""},
    {reg::kYaw, "f32", "yaw_deg", "deg", "ENU yaw, counter-clockwise from east"},
    {reg::kHeading, "f32", "heading_deg", "deg", "compass convention, clockwise from north, [0, 360)"},
    {reg::kQx, "f32", "qx", "-", "q_odom_robot (x, y, z, w)"},
    {reg::kQy, "f32", "qy", "-", ""},
    {reg::kQz, "f32", "qz", "-", ""},
    {reg::kQw, "f32", "qw", "-", ""},
    {reg::kVelEast, "f32", "vel_east_mps", "m/s", "velocity in odom"},
    {reg::kVelNorth, "f32", "vel_north_mps", "m/s", ""},
    {reg::kVelUp, "f32", "vel_up_mps", "m/s", ""},
    {reg::kVelForward, "f32", "vel_forward_mps", "m/s", "velocity in the robot frame (FLU)"},
    {reg::kVelLeft, "f32", "vel_left_mps", "m/s", ""},
    {reg::kVelRobotUp, "f32", "vel_robot_up_mps", "m/s", ""},
    {reg::kRateRoll, "f32", "rate_roll_dps", "deg/s", "angular rate in the robot frame (x, y, z)"},
    {reg::kRatePitch, "f32", "rate_pitch_dps", "deg/s", ""},
    {reg::kRateYaw, "f32", "rate_yaw_dps", "deg/s", ""},
    {reg::kVarEast, "f32", "var_east_m2", "m^2", "pose covariance diagonal"},
    {reg::kVarNorth, "f32", "var_north_m2", "m^2", ""},
    {reg::kVarUp, "f32", "var_up_m2", "m^2", ""},
    {reg::kVarRoll, "f32", "var_roll_rad2", "rad^2", "rotation errors about the odom axes"},
    {reg::kVarPitch, "f32", "var_pitch_rad2", "rad^2", ""},
    {reg::kVarYaw, "f32", "var_yaw_rad2", "rad^2", ""},
    {reg::kVarVelEast, "f32", "var_vel_east_m2ps2", "(m/s)^2", "velocity covariance diagonal"},
    {reg::kVarVelNorth, "f32", "var_vel_north_m2ps2", "(m/s)^2", ""},
    {reg::kVarVelUp, "f32", "var_vel_up_m2ps2", "(m/s)^2", ""},
    {reg::kImageQuality, "f32", "image_quality", "-", "last MDM score in [0, 1]; -1 before the first image"},
    {reg::kRejected, "u32", "rejected_total", "count", "measurements gated out by the filter"},
    {reg::kDroppedLate, "u32", "dropped_late_total", "count", "measurements older than the fusion window"},
    {reg::kTicks, "u32", "ticks", "count", "nav loop ticks"},
    {reg::kLateTicks, "u32", "late_ticks", "count", "ticks started late"},
    {reg::kNavOverruns, "u32", "nav_overruns", "count", "nav ticks over budget"},
    {reg::kVisionOverruns, "u32", "vision_overruns", "count", "stereo pairs over the vision budget"},
    {reg::kRecorderDrops, "u32", "recorder_drops", "count", "records refused by the recorder queue"},
    {reg::kInputsRefused, "u32", "inputs_refused", "count", "samples and frames refused by full input buffers"},
    {reg::kImuCount, "u32", "imu_samples", "count", "samples consumed per sensor"},
    {reg::kDvlCount, "u32", "dvl_samples", "count", ""},
    {reg::kDepthCount, "u32", "depth_samples", "count", ""},
    {reg::kHeadingCount, "u32", "heading_samples", "count", ""},
    {reg::kAttitudeCount, "u32", "attitude_samples", "count", ""},
    {reg::kVisionCount, "u32", "vision_results", "count", "vision results fused"},
};

int registersOf(const char* type) {
  if (std::strcmp(type, "u16") == 0) return 1;
  if (std::strcmp(type, "u64") == 0) return 4;
  return 2;
}

}  // namespace

void encodeRegisters(const NavOutput& out, std::uint16_t* regs) {
  const NavSolution& s = out.solution;
  const NavCounters& c = out.counters;
  regs[reg::kMagic] = kRegisterMagic;
  regs[reg::kVersion] = kRegisterMapVersion;
  putU32(regs, reg::kSequence, out.sequence);
  const auto t = static_cast<std::uint64_t>(s.t_us);
  putU32(regs, reg::kTimeUs, static_cast<std::uint32_t>(t >> 32));
  putU32(regs, reg::kTimeUs + 2, static_cast<std::uint32_t>(t & 0xFFFFFFFFu));
  regs[reg::kStage] = static_cast<std::uint16_t>(s.stage);
  regs[reg::kStatus] = static_cast<std::uint16_t>(s.status & 0xFFFFu);
  putU32(regs, reg::kFaults, s.faults);
  putU32(regs, reg::kHealth, out.health);
  const Eigen::Vector3d& p = s.p_robot_in_odom_m;
  putF32(regs, reg::kEast, p.x());
  putF32(regs, reg::kNorth, p.y());
  putF32(regs, reg::kUp, p.z());
  putF32(regs, reg::kDepth, -p.z());
  double roll = 0, pitch = 0, yaw = 0;
  eulerZyxRad(s.q_odom_robot, &roll, &pitch, &yaw);
  putF32(regs, reg::kRoll, roll * kDegPerRad);
  putF32(regs, reg::kPitch, pitch * kDegPerRad);
  putF32(regs, reg::kYaw, yaw * kDegPerRad);
  // Compass heading = 90 deg - ENU yaw, wrapped to [0, 360).
  double heading = std::fmod(90.0 - yaw * kDegPerRad, 360.0);
  if (heading < 0) heading += 360.0;
  putF32(regs, reg::kHeading, heading);
  putF32(regs, reg::kQx, s.q_odom_robot.x());
  putF32(regs, reg::kQy, s.q_odom_robot.y());
  putF32(regs, reg::kQz, s.q_odom_robot.z());
  putF32(regs, reg::kQw, s.q_odom_robot.w());
  const Eigen::Vector3d& v = s.v_robot_in_odom_mps;
  putF32(regs, reg::kVelEast, v.x());
  putF32(regs, reg::kVelNorth, v.y());
  putF32(regs, reg::kVelUp, v.z());
  const Eigen::Vector3d v_robot = s.q_odom_robot.normalized().conjugate() * v;
  putF32(regs, reg::kVelForward, v_robot.x());
  putF32(regs, reg::kVelLeft, v_robot.y());
  putF32(regs, reg::kVelRobotUp, v_robot.z());
  putF32(regs, reg::kRateRoll, s.w_robot_radps.x() * kDegPerRad);
  putF32(regs, reg::kRatePitch, s.w_robot_radps.y() * kDegPerRad);
  putF32(regs, reg::kRateYaw, s.w_robot_radps.z() * kDegPerRad);
  for (int i = 0; i < 6; ++i) putF32(regs, static_cast<std::uint16_t>(reg::kVarEast + 2 * i), s.cov_pose(i, i));
  for (int i = 0; i < 3; ++i) putF32(regs, static_cast<std::uint16_t>(reg::kVarVelEast + 2 * i), s.cov_v_mps2(i, i));
  putF32(regs, reg::kImageQuality, s.image_quality);
  putCount(regs, reg::kRejected, s.rejected_total);
  putCount(regs, reg::kDroppedLate, s.dropped_late_total);
  putCount(regs, reg::kTicks, c.ticks);
  putCount(regs, reg::kLateTicks, c.late_ticks);
  putCount(regs, reg::kNavOverruns, c.nav_overruns);
  putCount(regs, reg::kVisionOverruns, c.vision_overruns);
  putCount(regs, reg::kRecorderDrops, c.recorder_drops);
  putCount(regs, reg::kInputsRefused, c.inputs_refused);
  putCount(regs, reg::kImuCount, c.imu);
  putCount(regs, reg::kDvlCount, c.dvl);
  putCount(regs, reg::kDepthCount, c.depth);
  putCount(regs, reg::kHeadingCount, c.heading);
  putCount(regs, reg::kAttitudeCount, c.attitude);
  putCount(regs, reg::kVisionCount, c.vision);
}

std::uint32_t registerU32(const std::uint16_t* regs, std::uint16_t a) {
  return (static_cast<std::uint32_t>(regs[a]) << 16) | regs[a + 1];
}

std::uint64_t registerU64(const std::uint16_t* regs, std::uint16_t a) {
  return (static_cast<std::uint64_t>(registerU32(regs, a)) << 32) | registerU32(regs, static_cast<std::uint16_t>(a + 2));
}

float registerFloat(const std::uint16_t* regs, std::uint16_t a) {
  const std::uint32_t bits = registerU32(regs, a);
  float f = 0;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

std::string describeRegisterMap() {
  std::ostringstream s;
  s << "| address | registers | type | name | unit | meaning |\n|---|---|---|---|---|---|\n";
  for (const FieldDoc& f : kFields) {
    s << "| " << f.address << " | " << registersOf(f.type) << " | " << f.type << " | `" << f.name << "` | " << f.unit
      << " | " << f.meaning << " |\n";
  }
  return s.str();
}

}  // namespace deepnav
