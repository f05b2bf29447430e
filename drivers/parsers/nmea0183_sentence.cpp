#include "drivers/parsers/nmea0183_sentence.h"

#include <charconv>
#include <cmath>
#include <cstdint>

namespace deepnav {
namespace {

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

}  // namespace

bool parseNmea0183Sentence(std::string_view line, bool require_checksum, Nmea0183Sentence* out, const char** error) {
  *out = Nmea0183Sentence{};
  if (line.size() < 6 || (line[0] != '$' && line[0] != '!')) return *error = "not an NMEA 0183 sentence", false;
  std::string_view body = line.substr(1);
  const size_t star = body.find('*');
  if (star != std::string_view::npos) {
    if (star + 3 != body.size()) return *error = "NMEA checksum must be two hex digits at the end", false;
    const int hi = hexDigit(body[star + 1]), lo = hexDigit(body[star + 2]);
    if (hi < 0 || lo < 0) return *error = "NMEA checksum is not hex", false;
    uint8_t x = 0;
    for (size_t i = 0; i < star; ++i) x ^= uint8_t(body[i]);
    if (x != uint8_t(hi * 16 + lo)) return *error = "NMEA checksum mismatch", false;
    body = body.substr(0, star);
    out->had_checksum = true;
  } else if (require_checksum) {
    return *error = "NMEA sentence without checksum", false;
  }
  for (char c : body) {
    if (c < 0x20 || c > 0x7E || c == '$' || c == '!' || c == '*') return *error = "NMEA sentence holds a reserved character", false;
  }
  const size_t comma = body.find(',');
  const std::string_view address = body.substr(0, comma);
  if (address.size() < 2) return *error = "NMEA address field too short", false;
  if (address[0] == 'P') {
    out->type = address;
  } else {
    if (address.size() != 5) return *error = "NMEA address field is not talker + 3-letter type", false;
    out->talker = address.substr(0, 2);
    out->type = address.substr(2);
  }
  if (comma == std::string_view::npos) return true;
  std::string_view rest = body.substr(comma + 1);
  while (true) {
    if (out->num_fields == Nmea0183Sentence::kMaxFields) return *error = "NMEA sentence has too many fields", false;
    const size_t next = rest.find(',');
    out->fields[out->num_fields++] = rest.substr(0, next);
    if (next == std::string_view::npos) break;
    rest = rest.substr(next + 1);
  }
  return true;
}

bool nmeaDouble(std::string_view field, double* value) {
  if (field.empty()) return false;
  const char* begin = field.data();
  if (*begin == '+') ++begin;
  const char* end = field.data() + field.size();
  double v = 0;
  const auto r = std::from_chars(begin, end, v);
  if (r.ec != std::errc() || r.ptr != end || !std::isfinite(v)) return false;
  *value = v;
  return true;
}

}  // namespace deepnav
