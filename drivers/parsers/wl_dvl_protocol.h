#pragma once
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "drivers/parsers/wl_dvl_report.h"

namespace deepnav {

// One line of the Water Linked DVL serial protocol (without CR LF), checked and decoded:
//   wrz,vx,vy,vz,valid,altitude,fom,c11;c12;...;c33,time_of_validity,time_of_transmission,time,status*cc
//   wru,id,velocity,distance,rssi,nsd*cc
//   wrp,time_stamp,x,y,z,pos_std,roll,pitch,yaw,status*cc         (angles in degrees)
//   wrx,time,vx,vy,vz,fom,altitude,valid,status*cc                (deprecated velocity report)
// cc is the CRC-8 (crc8.h) of every byte before '*', as two hex digits. Lines are rejected when the
// checksum is missing or wrong, a field is not a number, or the field count is off. Other responses
// (wra, wrn, wrv...) return kOtherSentence.
enum class WlDecode { kDecoded, kOtherSentence, kInvalid };

WlDecode parseWlDvlSerialLine(std::string_view line, WlDvlReport* out, const char** error);

// Range-checked conversions shared by both protocols: a status must be an integer in [0, 65535], a
// time in microseconds in [0, 9.2e18]; false otherwise.
bool wlStatusValue(double v, int* out);
bool wlMicros(double v, int64_t* out);

// The same for one TCP JSON v3 report ("type": "velocity" or "position_local").
WlDecode parseWlDvlJson(std::string_view text, WlDvlReport* out, const char** error);

// One framed line of either protocol ('{': JSON report, else serial sentence). A line that does not
// decode but holds a later "wr" is decoded again from there: junk glued before a sentence (a cut JSON
// object, noise without a line end) does not cost the sentence. *junk_bytes is how many leading bytes
// were dropped that way (0 otherwise).
WlDecode parseWlDvlLine(std::string_view line, WlDvlReport* out, const char** error, size_t* junk_bytes);

}  // namespace deepnav
