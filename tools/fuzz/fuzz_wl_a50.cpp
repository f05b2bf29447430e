// libFuzzer harness: arbitrary bytes as Water Linked serial sentences and JSON reports; and the
// intact-frames property: three good serial sentences after the input, through the line framer, are
// all decoded (intact_frames.h).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "drivers/parsers/json_scan.h"
#include "drivers/parsers/line_framer.h"
#include "drivers/parsers/wl_dvl_protocol.h"
#include "tests/support/sensor_frames.h"
#include "tools/fuzz/intact_frames.h"

namespace {

void checkIntactSentences(const uint8_t* data, size_t size) {
  using namespace deepnav;
  std::vector<std::string> frames, lines;
  for (const char* body : {"wrz,0.100,0.200,0.010,y,1.90,0.002,1e-06;0;0;0;1e-06;0;0;0;1e-06,1000,1040,250.0,0",
                           "wru,0,0.1,2.0,-40,-90", "wrp,49056.809,0.41,0.18,0.10,0.45,0.3,-1.2,92.1,0"}) {
    frames.push_back(test::wlSentence(body));
    lines.push_back(frames.back().substr(0, frames.back().size() - 2));
  }
  fuzz::IntactFrames intact(data, size, frames, lines);
  LineFramer framer;
  framer.init("w{", 4096, true, "{");
  fuzz::frameToEnd(&framer, intact.stream(), [&](const RawFrame& f) {
    const std::string_view line(reinterpret_cast<const char*>(f.data), f.size);
    WlDvlReport r;
    const char* why = "";
    size_t junk = 0;
    if (parseWlDvlLine(line, &r, &why, &junk) == WlDecode::kDecoded) intact.delivered(f.offset + junk, line.substr(junk));
  });
  intact.verify("wl-a50");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace deepnav;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  WlDvlReport r;
  DvlSample s;
  const char* why = "";
  if (parseWlDvlSerialLine(text, &r, &why) == WlDecode::kDecoded) dvlSampleFromWlReport(r, 0, &s);
  if (parseWlDvlJson(text, &r, &why) == WlDecode::kDecoded) dvlSampleFromWlReport(r, 0, &s);
  // The JSON scanner's array walk on whatever the input holds.
  std::string_view rest, element;
  if (JsonScan::arrayBegin(text, &rest)) {
    for (int i = 0; i < 1000 && JsonScan::arrayNext(&rest, &element); ++i) {
    }
  }
  checkIntactSentences(data, size);
  return 0;
}
