// libFuzzer harness: arbitrary bytes through the PD0 framer, ensemble decoder and DVL conversion.
#include <cstddef>
#include <cstdint>
#include <memory>

#include "drivers/parsers/pd0_dvl_sample.h"
#include "drivers/parsers/pd0_ensemble.h"
#include "drivers/parsers/pd0_framer.h"

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
  return 0;
}
