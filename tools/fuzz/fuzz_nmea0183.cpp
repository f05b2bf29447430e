// libFuzzer harness: arbitrary bytes through the line framer and the NMEA 0183 heading decoder; and the
// intact-frames property: three good sentences after the input are all decoded (intact_frames.h).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "drivers/parsers/line_framer.h"
#include "drivers/parsers/nmea0183_heading.h"
#include "tests/support/sensor_frames.h"
#include "tools/fuzz/intact_frames.h"

namespace {

void checkIntactSentences(const uint8_t* data, size_t size) {
  using namespace deepnav;
  std::vector<std::string> frames, lines;
  for (const char* body : {"HEHDT,274.07,T", "HCHDG,101.1,2.0,W,3.5,E", "HEROT,-3.4,A"}) {
    frames.push_back(test::nmeaSentence(body));
    lines.push_back(frames.back().substr(0, frames.back().size() - 2));
  }
  fuzz::IntactFrames intact(data, size, frames, lines);
  LineFramer framer;
  framer.init("$!", 120);
  fuzz::frameToEnd(&framer, intact.stream(), [&](const RawFrame& f) {
    const std::string_view line(reinterpret_cast<const char*>(f.data), f.size);
    Nmea0183Sentence s;
    Nmea0183HeadingRecord r;
    const char* why = "";
    if (parseNmea0183Sentence(line, true, &s, &why) && decodeNmea0183Heading(s, &r, &why) == NmeaDecode::kDecoded) {
      intact.delivered(f.offset, line);
    }
  });
  intact.verify("nmea0183");
}

}  // namespace

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
  checkIntactSentences(data, size);
  return 0;
}
