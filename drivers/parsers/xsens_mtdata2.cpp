#include "drivers/parsers/xsens_mtdata2.h"

#include <algorithm>
#include <cmath>

#include "drivers/parsers/byte_order.h"

namespace deepnav {
namespace {

constexpr uint16_t kPacketCounter = 0x1020;
constexpr uint16_t kSampleTimeFine = 0x1060;
constexpr uint16_t kQuaternion = 0x2010;
constexpr uint16_t kEulerAngles = 0x2030;
constexpr uint16_t kAcceleration = 0x4020;
constexpr uint16_t kRateOfTurn = 0x8020;
constexpr uint16_t kMagneticField = 0xC020;
constexpr uint16_t kStatusWord = 0xE020;

// Size of one value in the XDI's number format.
size_t valueSize(uint16_t xdi) {
  switch (xdi & 0x3) {
    case 0: return 4;  // float32
    case 1: return 4;  // fixed point 12.20
    case 2: return 6;  // fixed point 16.32
    default: return 8; // float64
  }
}

double readValue(const uint8_t* p, uint16_t xdi) {
  switch (xdi & 0x3) {
    case 0: return readBeF32(p);
    case 1: return int32_t(readBe32(p)) / double(1 << 20);
    case 2: {
      // 16.32: 4 bytes fraction then 2 bytes signed integer part.
      const int64_t raw = (int64_t(int16_t(readBe16(p + 4))) << 32) | readBe32(p);
      return double(raw) / 4294967296.0;
    }
    default: return readBeF64(p);
  }
}

template <size_t N>
bool readVector(const uint8_t* p, size_t size, uint16_t xdi, std::array<double, N>* out) {
  if (size != N * valueSize(xdi)) return false;
  for (size_t i = 0; i < N; ++i) {
    (*out)[i] = readValue(p + i * valueSize(xdi), xdi);
    if (!std::isfinite((*out)[i])) return false;
  }
  return true;
}

}  // namespace

bool decodeXsensMtData2(const uint8_t* d, size_t size, XsensMtData2* out, const char** error) {
  *out = XsensMtData2{};
  size_t i = 0;
  while (i < size) {
    if (i + 3 > size) return *error = "MTData2 packet header runs past the message", false;
    const uint16_t xdi = readBe16(d + i);
    const size_t n = d[i + 2];
    const uint8_t* p = d + i + 3;
    if (i + 3 + n > size) return *error = "MTData2 packet runs past the message", false;
    const uint16_t type = xdi & 0xFFF0;
    const uint8_t frame = (xdi >> 2) & 0x3;
    bool ok = true;
    switch (type) {
      case kPacketCounter:
        ok = n == 2;
        if (ok) out->packet_counter = readBe16(p), out->has_packet_counter = true;
        break;
      case kSampleTimeFine:
        ok = n == 4;
        if (ok) out->sample_time_fine = readBe32(p), out->has_sample_time_fine = true;
        break;
      case kQuaternion:
        ok = readVector(p, n, xdi, &out->quaternion);
        out->has_quaternion = ok, out->quaternion_frame = frame;
        break;
      case kEulerAngles:
        ok = readVector(p, n, xdi, &out->euler_rad);
        for (double& a : out->euler_rad) a *= M_PI / 180.0;
        out->has_euler = ok, out->euler_frame = frame;
        break;
      case kAcceleration:
        ok = out->has_acceleration = readVector(p, n, xdi, &out->acceleration_mps2);
        break;
      case kRateOfTurn:
        ok = out->has_rate_of_turn = readVector(p, n, xdi, &out->rate_of_turn_radps);
        break;
      case kMagneticField:
        ok = out->has_magnetic_field = readVector(p, n, xdi, &out->magnetic_field);
        break;
      case kStatusWord:
        ok = n == 4;
        if (ok) out->status_word = readBe32(p), out->has_status_word = true;
        break;
      default:
        break;
    }
    if (!ok) return *error = "MTData2 packet size does not match its data identifier", false;
    ++out->num_packets;
    i += 3 + n;
  }
  return true;
}

bool imuSampleFromXsens(const XsensMtData2& m, TimeUs t_us, ImuSample* s) {
  if (!m.has_rate_of_turn && !m.has_acceleration) return false;
  ImuSample out;
  out.t_us = t_us;
  if (m.has_rate_of_turn) out.w_imu_radps = Eigen::Vector3d(m.rate_of_turn_radps[0], m.rate_of_turn_radps[1], m.rate_of_turn_radps[2]);
  if (m.has_acceleration) out.f_imu_mps2 = Eigen::Vector3d(m.acceleration_mps2[0], m.acceleration_mps2[1], m.acceleration_mps2[2]);
  if (m.has_quaternion && m.quaternion_frame == XsensMtData2::kEnu) {
    Eigen::Quaterniond q(m.quaternion[0], m.quaternion[1], m.quaternion[2], m.quaternion[3]);
    if (q.norm() > 0.5) {
      out.has_orientation = true;
      out.q_odom_imu = q.normalized();
    }
  }
  *s = out;
  return true;
}

bool attitudeSampleFromXsens(const XsensMtData2& m, TimeUs t_us, AttitudeSample* s) {
  double roll = 0, pitch = 0;
  if (m.has_quaternion && m.quaternion_frame == XsensMtData2::kEnu) {
    const double w = m.quaternion[0], x = m.quaternion[1], y = m.quaternion[2], z = m.quaternion[3];
    roll = std::atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y));
    pitch = std::asin(std::clamp(2 * (w * y - z * x), -1.0, 1.0));
  } else if (m.has_euler && m.euler_frame == XsensMtData2::kEnu) {
    roll = m.euler_rad[0];
    pitch = m.euler_rad[1];
  } else {
    return false;
  }
  *s = AttitudeSample{};
  s->t_us = t_us;
  s->roll_rad = roll;
  s->pitch_rad = pitch;
  return true;
}

}  // namespace deepnav
