#pragma once
#include "drivers/parsers/nmea0183_sentence.h"
#include "nav/types/heading_sample.h"

namespace deepnav {

// The heading sentences of NMEA 0183 (IEC 61162-1), in SI units:
//   $--HDT,x.x,T         true heading, deg
//   $--HDM,x.x,M         magnetic heading, deg
//   $--HDG,x.x,d.d,E,v.v,W  magnetic sensor heading, deviation, variation (deg, E/W)
//   $--ROT,x.x,A         rate of turn, deg/min (negative: bow turns to port), A = valid, V = invalid
struct Nmea0183HeadingRecord {
  enum class Kind { kHdt, kHdm, kHdg, kRot };
  Kind kind = Kind::kHdt;
  std::string_view talker;
  bool has_heading = false;    // an empty field (e.g. "$GPHDT,,T") means no heading in this sentence
  double heading_rad = 0.0;    // HDT: true; HDM: magnetic; HDG: sensor reading (before deviation)
  bool has_deviation = false;  // HDG: magnetic = sensor + deviation (east positive)
  double deviation_rad = 0.0;
  bool has_variation = false;  // HDG: true = magnetic + variation (east positive)
  double variation_rad = 0.0;
  bool has_rate = false;       // ROT
  double rate_radps = 0.0;
  bool rate_valid = false;     // ROT status 'A'
};

enum class NmeaDecode { kDecoded, kOtherSentence, kInvalid };

NmeaDecode decodeNmea0183Heading(const Nmea0183Sentence& sentence, Nmea0183HeadingRecord* out, const char** error);

// Heading sample from HDT (true north), HDM or HDG (magnetic north, deviation applied). The variation
// of HDG is not applied: the EKF applies the board's declination. False when there is no heading.
bool headingSampleFromNmea(const Nmea0183HeadingRecord& record, TimeUs t_us, HeadingSample* sample);

}  // namespace deepnav
