// libFuzzer harness: arbitrary bytes as PD6 lines, through the parser and the DVL assembler.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "drivers/parsers/pd6_sentence.h"

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
  return 0;
}
