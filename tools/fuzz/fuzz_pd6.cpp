// libFuzzer harness: arbitrary bytes as PD6 lines, through the parser and the DVL assembler; and the
// intact-frames property: four good lines after the input, through the line framer, are all decoded
// (intact_frames.h).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "drivers/parsers/line_framer.h"
#include "drivers/parsers/pd6_sentence.h"
#include "tools/fuzz/intact_frames.h"

namespace {

void checkIntactLines(const uint8_t* data, size_t size) {
  using namespace deepnav;
  const std::vector<std::string> lines = {":SA, -2.31, +1.12,123.45", ":TS,21051012345612,35.0,+12.5,  12.0,1500.0,  0",
                                          ":BI,  +100,  -500,   +20,     5,A", ":BD,     +12.30,     -4.50,      0.20,  8.25,  0.10"};
  std::vector<std::string> frames;
  for (const std::string& l : lines) frames.push_back(l + "\r\n");
  fuzz::IntactFrames intact(data, size, frames, lines);
  LineFramer framer;
  framer.init(":", 120);
  fuzz::frameToEnd(&framer, intact.stream(), [&](const RawFrame& f) {
    const std::string_view line(reinterpret_cast<const char*>(f.data), f.size);
    Pd6Record r;
    const char* why = "";
    if (parsePd6Line(line, &r, &why)) intact.delivered(f.offset, line);
  });
  intact.verify("pd6");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace deepnav;
  std::string_view text(reinterpret_cast<const char*>(data), size);
  Pd6DvlAssembler assembler;
  while (!text.empty()) {
    const size_t nl = text.find('\n');
    const std::string_view line = text.substr(0, nl);
    Pd6Record r;
    DvlSample s;
    const char* why = "";
    if (parsePd6Line(line, &r, &why)) assembler.add(r, 0, &s);
    if (nl == std::string_view::npos) break;
    text.remove_prefix(nl + 1);
  }
  checkIntactLines(data, size);
  return 0;
}
