// libFuzzer harness: the first line of the input as a CAN field mapping spec, the rest as frames.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "drivers/parsers/can_field_mapping.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace deepnav;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const size_t nl = std::min(text.find('\n'), text.size());
  CanFieldMapping map;
  std::string error;
  if (!map.parse(text.substr(0, nl), &error)) return 0;
  for (size_t i = nl + 1; i + 13 <= size; i += 13) {
    CanFrame f;
    f.id = (uint32_t(data[i]) << 24 | uint32_t(data[i + 1]) << 16 | uint32_t(data[i + 2]) << 8 | data[i + 3]);
    f.extended = (f.id & 0x80000000u) != 0;
    f.id &= f.extended ? 0x1FFFFFFFu : 0x7FFu;
    f.dlc = data[i + 4] % 9;
    std::copy(data + i + 5, data + i + 13, f.data.begin());
    CanFieldMapping::Output out;
    map.apply(f, 0, &out);
  }
  return 0;
}
