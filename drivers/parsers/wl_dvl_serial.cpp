#include "drivers/parsers/wl_dvl_protocol.h"

#include <array>
#include <cmath>

#include "drivers/parsers/crc8.h"
#include "drivers/parsers/nmea0183_sentence.h"

namespace deepnav {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

int split(std::string_view s, char sep, std::string_view* f, int max) {
  int n = 0;
  while (n < max) {
    const size_t c = s.find(sep);
    f[n++] = s.substr(0, c);
    if (c == std::string_view::npos) return n;
    s = s.substr(c + 1);
  }
  return -1;
}

bool numbers(const std::string_view* f, int n, double* out) {
  for (int i = 0; i < n; ++i) {
    if (!nmeaDouble(f[i], &out[i])) return false;
  }
  return true;
}

// Status words are small integers; anything else is a damaged field (and would overflow an int).
bool statusValue(double v, int* out) {
  if (v < 0 || v > 65535 || v != std::floor(v)) return false;
  *out = int(v);
  return true;
}

bool micros(std::string_view f, int64_t* out) {
  double v = 0;
  if (!nmeaDouble(f, &v) || v < 0 || v > 9.2e18) return false;
  *out = int64_t(v);
  return true;
}

}  // namespace

bool wlStatusValue(double v, int* out) { return statusValue(v, out); }

bool wlMicros(double v, int64_t* out) {
  if (!(v >= 0 && v <= 9.2e18)) return false;
  *out = int64_t(v);
  return true;
}

WlDecode parseWlDvlSerialLine(std::string_view line, WlDvlReport* out, const char** error) {
  *out = WlDvlReport{};
  const auto invalid = [&](const char* why) { return *error = why, WlDecode::kInvalid; };
  if (line.size() < 3 || line[0] != 'w') return invalid("not a Water Linked sentence");
  const size_t star = line.rfind('*');
  if (star == std::string_view::npos || star + 3 != line.size()) return invalid("Water Linked sentence without checksum");
  const int hi = hexValue(line[star + 1]), lo = hexValue(line[star + 2]);
  if (hi < 0 || lo < 0) return invalid("Water Linked checksum is not hex");
  if (crc8(reinterpret_cast<const uint8_t*>(line.data()), star) != hi * 16 + lo) return invalid("Water Linked CRC-8 mismatch");
  std::array<std::string_view, 16> f{};
  const int n = split(line.substr(0, star), ',', f.data(), int(f.size()));
  if (n < 0) return invalid("Water Linked sentence has too many fields");
  const std::string_view type = f[0];
  std::array<double, 12> v{};
  if (type == "wrz") {
    if (n != 12) return invalid("wrz needs 11 fields");
    if (!numbers(&f[1], 3, &v[0]) || !numbers(&f[5], 2, &v[3])) return invalid("wrz field is not a number");
    if (f[4] != "y" && f[4] != "n") return invalid("wrz valid flag is not y or n");
    std::array<std::string_view, 10> c{};
    if (split(f[7], ';', c.data(), int(c.size())) != 9 || !numbers(c.data(), 9, out->covariance_m2ps2.data())) {
      return invalid("wrz covariance is not 9 numbers");
    }
    double since_ms = 0, status = 0;
    if (!micros(f[8], &out->time_of_validity_us) || !micros(f[9], &out->time_of_transmission_us) ||
        !nmeaDouble(f[10], &since_ms) || !nmeaDouble(f[11], &status)) {
      return invalid("wrz time or status is not a number");
    }
    out->kind = WlDvlReport::Kind::kVelocity;
    out->vx_mps = v[0], out->vy_mps = v[1], out->vz_mps = v[2];
    out->velocity_valid = f[4] == "y";
    out->altitude_m = v[3], out->fom_mps = v[4];
    out->has_covariance = true;
    out->time_since_last_ms = since_ms;
    if (!statusValue(status, &out->status)) return invalid("wrz status is not a small integer");
    return WlDecode::kDecoded;
  }
  if (type == "wrx") {
    if (n != 9) return invalid("wrx needs 8 fields");
    if (!numbers(&f[1], 6, v.data()) || (f[7] != "y" && f[7] != "n") || !nmeaDouble(f[8], &v[6])) {
      return invalid("wrx field is not valid");
    }
    out->kind = WlDvlReport::Kind::kVelocity;
    out->time_since_last_ms = v[0];
    out->vx_mps = v[1], out->vy_mps = v[2], out->vz_mps = v[3], out->fom_mps = v[4], out->altitude_m = v[5];
    out->velocity_valid = f[7] == "y";
    if (!statusValue(v[6], &out->status)) return invalid("wrx status is not a small integer");
    return WlDecode::kDecoded;
  }
  if (type == "wru") {
    if (n != 6 || !numbers(&f[1], 5, v.data())) return invalid("wru needs 5 numbers");
    if (v[0] < 0 || v[0] > 3) return invalid("wru transducer id out of range");
    out->kind = WlDvlReport::Kind::kTransducer;
    out->num_transducers = 1;
    out->transducers[0] = {int(v[0]), v[1], v[2], v[3], v[4], v[2] > 0};
    return WlDecode::kDecoded;
  }
  if (type == "wrp") {
    if (n != 10 || !numbers(&f[1], 9, v.data())) return invalid("wrp needs 9 numbers");
    out->kind = WlDvlReport::Kind::kDeadReckoning;
    out->ts_s = v[0], out->x_m = v[1], out->y_m = v[2], out->z_m = v[3], out->pos_std_m = v[4];
    out->roll_rad = v[5] * kDegToRad, out->pitch_rad = v[6] * kDegToRad, out->yaw_rad = v[7] * kDegToRad;
    if (!statusValue(v[8], &out->status)) return invalid("wrp status is not a small integer");
    return WlDecode::kDecoded;
  }
  return WlDecode::kOtherSentence;
}

}  // namespace deepnav
