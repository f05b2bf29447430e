#pragma once
#include <array>
#include <string_view>

#include "nav/types/dvl_sample.h"

namespace deepnav {

// One line of Teledyne RDI PD6 (ASCII, no checksum), converted to SI units:
//   :SA,±PP.PP,±RR.RR,HHH.HH              pitch, roll, heading (deg -> rad)
//   :TS,YYMMDDHHmmsshh,SS.S,+TT.T,DDDD.D,CCCC.C,BBB  time, then values salinity ppt, temperature degC,
//                                           depth m, speed of sound m/s; BIT
//   :WI / :BI,±X,±Y,±Z,±E,S               water-mass / bottom-track velocity, instrument frame (mm/s)
//   :WS / :BS,±T,±L,±N,S                  ship frame (transverse, longitudinal, normal)
//   :WE / :BE,±E,±N,±U,S                  earth frame
//   :WD / :BD,±E,±N,±U,range,time         distance made good (m), range to bottom (m), time since the
//                                           last good velocity (s)
// Velocities are of the instrument relative to the water or the bottom; -32768 marks a bad component;
// S is 'A' (good) or 'V' (bad).
struct Pd6Record {
  enum class Kind { kSA, kTS, kWI, kWS, kWE, kWD, kBI, kBS, kBE, kBD };
  Kind kind = Kind::kSA;
  std::array<double, 5> value{};        // SI units, order as listed above
  std::array<bool, 5> value_valid{};    // false for -32768 components
  int num_values = 0;
  bool status_good = false;             // S == 'A' (velocity lines)
  std::string_view time;                // TS: YYMMDDHHmmsshh
  int bit = 0;                          // TS: built-in test result
};

bool parsePd6Line(std::string_view line, Pd6Record* out, const char** error);

const char* pd6KindName(Pd6Record::Kind kind);

// Builds a DvlSample from one ensemble's lines: :BI gives the velocity, :BD (the last bottom line of an
// ensemble) the altitude and emits the sample. Instrument frame X stbd, Y fwd, Z up -> FLU (Y, -X, Z).
class Pd6DvlAssembler {
 public:
  // True when the record completed a sample.
  bool add(const Pd6Record& record, TimeUs t_us, DvlSample* sample);

 private:
  bool have_velocity_ = false;
  DvlSample pending_;
};

}  // namespace deepnav
