#pragma once
#include <cstdint>
#include <string>

#include "drivers/parsers/n2k_message.h"
#include "drivers/parsers/nmea0183_heading.h"
#include "drivers/parsers/pd0_ensemble.h"
#include "drivers/parsers/pd6_sentence.h"
#include "drivers/parsers/wl_dvl_report.h"
#include "drivers/parsers/xsens_mtdata2.h"

namespace deepnav {

// One JSON object (one line, no trailing newline) per decoded record, in SI units. `offset` is the
// record's byte offset in the capture.
std::string pd0Json(const Pd0Ensemble& e, uint64_t offset);
std::string pd6Json(const Pd6Record& r, uint64_t offset);
std::string wlDvlJson(const WlDvlReport& r, uint64_t offset);
std::string nmeaHeadingJson(const Nmea0183HeadingRecord& r, uint64_t offset);
// 127250/127251/127257 with named fields; other PGNs with their payload in hex. `t_s` < 0: no time.
std::string n2kJson(const N2kMessage& m, uint64_t offset, double t_s);
std::string xsensJson(uint8_t message_id, const XsensMtData2* data, size_t payload_bytes, uint64_t offset);

}  // namespace deepnav
