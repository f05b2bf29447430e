#include "drivers/parsers/n2k_heading_pgns.h"

#include <cmath>

#include "drivers/parsers/byte_order.h"

namespace deepnav {
namespace {

constexpr double kAngleLsbRad = 1e-4;
constexpr double kRateLsbRadps = 1e-6 / 32.0;

bool unsignedAngle(const uint8_t* p, bool* has, double* rad) {
  const uint16_t raw = readLe16(p);
  *has = raw < 0xFFFD;  // 0xFFFD..0xFFFF: reserved, error, not available
  if (*has) *rad = raw * kAngleLsbRad;
  return !*has || *rad <= 2 * M_PI + kAngleLsbRad;
}

bool signedAngle(const uint8_t* p, bool* has, double* rad) {
  const int16_t raw = readLeI16(p);
  *has = raw < 0x7FFD;
  if (*has) *rad = raw * kAngleLsbRad;
  return !*has || std::abs(*rad) <= M_PI + kAngleLsbRad;
}

}  // namespace

bool decodeN2kVesselHeading(const N2kMessage& m, N2kVesselHeading* out, const char** error) {
  *out = N2kVesselHeading{};
  if (m.size < 8) return *error = "PGN 127250 shorter than 8 bytes", false;
  out->sid = m.data[0];
  if (!unsignedAngle(&m.data[1], &out->has_heading, &out->heading_rad) ||
      !signedAngle(&m.data[3], &out->has_deviation, &out->deviation_rad) ||
      !signedAngle(&m.data[5], &out->has_variation, &out->variation_rad)) {
    return *error = "PGN 127250 angle out of range", false;
  }
  out->reference = m.data[7] & 0x3;
  return true;
}

bool decodeN2kRateOfTurn(const N2kMessage& m, N2kRateOfTurn* out, const char** error) {
  *out = N2kRateOfTurn{};
  if (m.size < 8) return *error = "PGN 127251 shorter than 8 bytes", false;
  out->sid = m.data[0];
  const int32_t raw = readLeI32(&m.data[1]);
  out->has_rate = raw < 0x7FFFFFFD;
  if (out->has_rate) out->rate_radps = raw * kRateLsbRadps;
  out->reserved = {m.data[5], m.data[6], m.data[7]};
  return true;
}

bool decodeN2kAttitude(const N2kMessage& m, N2kAttitude* out, const char** error) {
  *out = N2kAttitude{};
  if (m.size < 7) return *error = "PGN 127257 shorter than 7 bytes", false;
  out->sid = m.data[0];
  if (!signedAngle(&m.data[1], &out->has_yaw, &out->yaw_rad) || !signedAngle(&m.data[3], &out->has_pitch, &out->pitch_rad) ||
      !signedAngle(&m.data[5], &out->has_roll, &out->roll_rad)) {
    return *error = "PGN 127257 angle out of range", false;
  }
  return true;
}

bool headingSampleFromN2k(const N2kVesselHeading& h, TimeUs t_us, HeadingSample* s) {
  if (!h.has_heading || h.reference > 1) return false;
  double heading = h.heading_rad + (h.reference == 1 && h.has_deviation ? h.deviation_rad : 0.0);
  heading = std::fmod(heading, 2 * M_PI);
  if (heading < 0) heading += 2 * M_PI;
  *s = HeadingSample{};
  s->t_us = t_us;
  s->heading_rad = heading;
  s->is_true = h.reference == 0;
  return true;
}

bool attitudeSampleFromN2k(const N2kAttitude& a, TimeUs t_us, AttitudeSample* s) {
  if (!a.has_pitch || !a.has_roll) return false;
  *s = AttitudeSample{};
  s->t_us = t_us;
  s->roll_rad = a.roll_rad;
  s->pitch_rad = -a.pitch_rad;
  return true;
}

}  // namespace deepnav
