#pragma once
#include <array>
#include <cstddef>
#include <string_view>

namespace deepnav {

// One NMEA 0183 sentence split into fields: "$HEHDT,4.0,T*2B" -> talker "HE", type "HDT",
// fields {"4.0", "T"}. The views point into the caller's line.
struct Nmea0183Sentence {
  static constexpr int kMaxFields = 40;
  std::string_view talker;  // two characters ("HE", "GP", ...); empty for proprietary sentences
  std::string_view type;    // "HDT", "HDG", ... (for proprietary "$P..." sentences: the whole address)
  std::array<std::string_view, kMaxFields> fields{};
  int num_fields = 0;
  bool had_checksum = false;
};

// Splits and checks one line (without CR LF). The checksum (XOR of the characters between '$' and '*',
// two hex digits) is verified when present; require_checksum rejects sentences without one. Returns
// false with *error set on a malformed line or a checksum mismatch.
bool parseNmea0183Sentence(std::string_view line, bool require_checksum, Nmea0183Sentence* out, const char** error);

// Field helpers: false when the field is empty or not a complete number.
bool nmeaDouble(std::string_view field, double* value);

}  // namespace deepnav
