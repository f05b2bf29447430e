// libFuzzer harness: arbitrary bytes through the PD0 framer, ensemble decoder and DVL conversion; and
// the intact-frames property: three good ensembles after the input are all decoded (intact_frames.h).
#include <cstddef>
#include <cstdint>
#include <memory>

#include "drivers/parsers/pd0_dvl_sample.h"
#include "drivers/parsers/pd0_ensemble.h"
#include "drivers/parsers/pd0_framer.h"
#include "tests/support/sensor_frames.h"
#include "tools/fuzz/intact_frames.h"

namespace {

void checkIntactEnsembles(const uint8_t* data, size_t size, deepnav::Pd0Ensemble* ensemble) {
  using namespace deepnav;
  std::vector<std::string> frames;
  for (uint16_t i = 1; i <= 3; ++i) {
    test::Pd0Spec s;
    s.ensemble = i;
    frames.push_back(fuzz::str(test::buildPd0(s)));
  }
  fuzz::IntactFrames intact(data, size, frames, frames);
  Pd0Framer framer;
  framer.init(65535);
  framer.waitForCertainty();
  fuzz::frameToEnd(&framer, intact.stream(), [&](const RawFrame& f) {
    intact.framed(f.offset, f.size);
    const char* why = "";
    if (decodePd0Ensemble(f.data, f.size, ensemble, &why)) intact.delivered(f.offset, f.data, f.size);
  });
  intact.verify("pd0");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace deepnav;
  static auto ensemble = std::make_unique<Pd0Ensemble>();
  // The whole input as one ensemble (decoder bounds checks without the checksum's protection) ...
  const char* why = "";
  DvlSample s;
  if (decodePd0Ensemble(data, size, ensemble.get(), &why)) pd0ToDvlSample(*ensemble, 0, &s);
  // ... and as a stream, pushed in uneven pieces.
  Pd0Framer framer;
  framer.init(4096);
  size_t pos = 0;
  for (int guard = 0; guard < 100000; ++guard) {
    RawFrame f;
    FrameError e;
    const FrameStatus st = framer.next(&f, &e);
    if (st == FrameStatus::kFrame && decodePd0Ensemble(f.data, f.size, ensemble.get(), &why)) pd0ToDvlSample(*ensemble, 0, &s);
    if (st != FrameStatus::kNeedMore) continue;
    if (pos == size) break;
    pos += framer.push(data + pos, std::min<size_t>(size - pos, 1 + (pos % 251)));
  }
  checkIntactEnsembles(data, size, ensemble.get());
  return 0;
}
