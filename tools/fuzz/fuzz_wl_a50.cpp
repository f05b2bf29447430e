// libFuzzer harness: arbitrary bytes as Water Linked serial sentences and JSON reports.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "drivers/parsers/json_scan.h"
#include "drivers/parsers/wl_dvl_protocol.h"

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
  return 0;
}
