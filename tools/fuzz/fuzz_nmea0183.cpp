// libFuzzer harness: arbitrary bytes through the line framer and the NMEA 0183 heading decoder.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "drivers/parsers/line_framer.h"
#include "drivers/parsers/nmea0183_heading.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace deepnav;
  const auto decode = [](std::string_view line) {
    Nmea0183Sentence s;
    Nmea0183HeadingRecord r;
    HeadingSample h;
    const char* why = "";
    if (parseNmea0183Sentence(line, false, &s, &why) && decodeNmea0183Heading(s, &r, &why) == NmeaDecode::kDecoded) {
      headingSampleFromNmea(r, 0, &h);
    }
  };
  decode(std::string_view(reinterpret_cast<const char*>(data), size));
  LineFramer framer;
  framer.init("$!", 82);
  size_t pos = 0;
  for (int guard = 0; guard < 100000; ++guard) {
    RawFrame f;
    FrameError e;
    const FrameStatus st = framer.next(&f, &e);
    if (st == FrameStatus::kFrame) decode(std::string_view(reinterpret_cast<const char*>(f.data), f.size));
    if (st != FrameStatus::kNeedMore) continue;
    if (pos == size) break;
    pos += framer.push(data + pos, std::min<size_t>(size - pos, 1 + (pos % 37)));
  }
  return 0;
}
