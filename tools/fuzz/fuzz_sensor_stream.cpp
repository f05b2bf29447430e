// libFuzzer harness: the first byte picks a serial protocol, the rest is the byte stream a driver
// would read, fed through SensorStreamDecoder (framing, checks, sample conversion) in uneven reads.
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "drivers/parsers/sensor_stream_decoder.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace deepnav;
  if (size == 0) return 0;
  static const SensorProtocol kProtocols[] = {SensorProtocol::kPd0, SensorProtocol::kPd6, SensorProtocol::kWlA50,
                                              SensorProtocol::kNmea0183, SensorProtocol::kXsens};
  SensorStreamDecoder decoder;
  if (!decoder.init(kProtocols[data[0] % 5])) return 0;
  SampleSink sink;
  for (size_t pos = 1; pos < size;) {
    const size_t n = std::min<size_t>(size - pos, 1 + (data[pos] % 64));
    decoder.feed(data + pos, n, TimeUs(pos), &sink);
    pos += n;
  }
  return 0;
}
