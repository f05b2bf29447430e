#include "drivers/parsers/nmea0183_heading.h"

#include <cmath>

namespace deepnav {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

bool headingField(std::string_view f, bool* has, double* rad, const char** error) {
  double deg = 0;
  *has = false;
  if (f.empty()) return true;
  if (!nmeaDouble(f, &deg) || deg < 0.0 || deg > 360.0) return *error = "NMEA heading out of [0, 360] deg", false;
  *has = true;
  *rad = std::fmod(deg, 360.0) * kDegToRad;
  return true;
}

// Signed angle with an E/W hemisphere letter (east positive).
bool eastWestField(std::string_view value, std::string_view hemisphere, bool* has, double* rad, const char** error) {
  double deg = 0;
  *has = false;
  if (value.empty()) return true;
  if (!nmeaDouble(value, &deg) || std::abs(deg) > 180.0) return *error = "NMEA deviation/variation out of range", false;
  if (hemisphere != "E" && hemisphere != "W") return *error = "NMEA deviation/variation without E/W", false;
  *has = true;
  *rad = (hemisphere == "W" ? -deg : deg) * kDegToRad;
  return true;
}

}  // namespace

NmeaDecode decodeNmea0183Heading(const Nmea0183Sentence& s, Nmea0183HeadingRecord* out, const char** error) {
  *out = Nmea0183HeadingRecord{};
  out->talker = s.talker;
  const auto invalid = [&](const char* why) { return *error = why, NmeaDecode::kInvalid; };
  if (s.type == "HDT" || s.type == "HDM") {
    const bool is_true = s.type == "HDT";
    out->kind = is_true ? Nmea0183HeadingRecord::Kind::kHdt : Nmea0183HeadingRecord::Kind::kHdm;
    if (s.num_fields < 2) return invalid("NMEA HDT/HDM needs 2 fields");
    if (s.fields[1] != (is_true ? "T" : "M")) return invalid("NMEA HDT/HDM reference letter is wrong");
    if (!headingField(s.fields[0], &out->has_heading, &out->heading_rad, error)) return NmeaDecode::kInvalid;
    return NmeaDecode::kDecoded;
  }
  if (s.type == "HDG") {
    out->kind = Nmea0183HeadingRecord::Kind::kHdg;
    if (s.num_fields < 5) return invalid("NMEA HDG needs 5 fields");
    if (!headingField(s.fields[0], &out->has_heading, &out->heading_rad, error) ||
        !eastWestField(s.fields[1], s.fields[2], &out->has_deviation, &out->deviation_rad, error) ||
        !eastWestField(s.fields[3], s.fields[4], &out->has_variation, &out->variation_rad, error)) {
      return NmeaDecode::kInvalid;
    }
    return NmeaDecode::kDecoded;
  }
  if (s.type == "ROT") {
    out->kind = Nmea0183HeadingRecord::Kind::kRot;
    if (s.num_fields < 2) return invalid("NMEA ROT needs 2 fields");
    if (s.fields[1] != "A" && s.fields[1] != "V") return invalid("NMEA ROT status is not A or V");
    out->rate_valid = s.fields[1] == "A";
    if (!s.fields[0].empty()) {
      double deg_per_min = 0;
      if (!nmeaDouble(s.fields[0], &deg_per_min) || std::abs(deg_per_min) > 1e5) return invalid("NMEA ROT rate is not a number");
      out->has_rate = true;
      out->rate_radps = deg_per_min * kDegToRad / 60.0;
    }
    return NmeaDecode::kDecoded;
  }
  return NmeaDecode::kOtherSentence;
}

bool headingSampleFromNmea(const Nmea0183HeadingRecord& r, TimeUs t_us, HeadingSample* sample) {
  if (r.kind == Nmea0183HeadingRecord::Kind::kRot || !r.has_heading) return false;
  double heading = r.heading_rad + (r.has_deviation ? r.deviation_rad : 0.0);
  heading = std::fmod(heading, 2.0 * M_PI);
  if (heading < 0) heading += 2.0 * M_PI;
  *sample = HeadingSample{};
  sample->t_us = t_us;
  sample->heading_rad = heading;
  sample->is_true = r.kind == Nmea0183HeadingRecord::Kind::kHdt;
  return true;
}

}  // namespace deepnav
