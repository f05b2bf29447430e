// libFuzzer harness: arbitrary bytes through the Xbus framer and the MTData2 decoder.
#include <cstddef>
#include <cstdint>

#include "drivers/parsers/xbus_framer.h"
#include "drivers/parsers/xsens_mtdata2.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace deepnav;
  const auto decode = [](const uint8_t* p, size_t n) {
    XsensMtData2 d;
    ImuSample imu;
    AttitudeSample att;
    const char* why = "";
    if (decodeXsensMtData2(p, n, &d, &why)) {
      imuSampleFromXsens(d, 0, &imu);
      attitudeSampleFromXsens(d, 0, &att);
    }
  };
  decode(data, size);  // the input as an MTData2 payload
  XbusFramer framer;
  framer.init(2048);
  size_t pos = 0;
  for (int guard = 0; guard < 100000; ++guard) {
    RawFrame f;
    FrameError e;
    const FrameStatus st = framer.next(&f, &e);
    XbusMessage m;
    if (st == FrameStatus::kFrame && splitXbusFrame(f.data, f.size, &m)) decode(m.payload, m.payload_size);
    if (st != FrameStatus::kNeedMore) continue;
    if (pos == size) break;
    pos += framer.push(data + pos, std::min<size_t>(size - pos, 1 + (pos % 53)));
  }
  return 0;
}
