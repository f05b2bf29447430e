// libFuzzer harness: arbitrary bytes through the Xbus framer and the MTData2 decoder; and the
// intact-frames property: three good messages after the input are all decoded (intact_frames.h).
#include <cstddef>
#include <cstdint>

#include "drivers/parsers/xbus_framer.h"
#include "drivers/parsers/xsens_mtdata2.h"
#include "tests/support/sensor_frames.h"
#include "tools/fuzz/intact_frames.h"

namespace {

void checkIntactMessages(const uint8_t* data, size_t size) {
  using namespace deepnav;
  std::vector<std::string> frames;
  const float q[4] = {1, 0, 0, 0}, acc[3] = {0, 0, 9.81f}, gyr[3] = {0.01f, 0, 0.5f};
  for (uint16_t i = 1; i <= 3; ++i) frames.push_back(fuzz::str(test::buildMtData2(i, q, acc, gyr)));
  fuzz::IntactFrames intact(data, size, frames, frames);
  XbusFramer framer;
  framer.init(65535);
  framer.waitForCertainty();
  fuzz::frameToEnd(&framer, intact.stream(), [&](const RawFrame& f) {
    intact.framed(f.offset, f.size);
    XbusMessage m;
    XsensMtData2 d;
    const char* why = "";
    if (splitXbusFrame(f.data, f.size, &m) && decodeXsensMtData2(m.payload, m.payload_size, &d, &why)) {
      intact.delivered(f.offset, f.data, f.size);
    }
  });
  intact.verify("xsens");
}

}  // namespace

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
  checkIntactMessages(data, size);
  return 0;
}
