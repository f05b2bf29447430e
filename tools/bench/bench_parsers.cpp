// Throughput of the serial and CAN decoders: bytes in, samples out, as a driver thread runs them.
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "drivers/parsers/candump_line.h"
#include "drivers/parsers/n2k_assembler.h"
#include "drivers/parsers/n2k_heading_pgns.h"
#include "drivers/parsers/sensor_stream_decoder.h"
#include "tests/support/sensor_frames.h"

namespace deepnav {
namespace {

struct Count : SampleSink {
  long samples = 0;
  bool onDvl(const DvlSample&) override { return ++samples, true; }
  bool onHeading(const HeadingSample&) override { return ++samples, true; }
  bool onImu(const ImuSample&) override { return ++samples, true; }
  bool onAttitude(const AttitudeSample&) override { return ++samples, true; }
};

std::vector<uint8_t> stream(SensorProtocol p) {
  std::vector<uint8_t> s;
  for (int i = 0; i < 200; ++i) {
    if (p == SensorProtocol::kPd0) {
      test::Pd0Spec spec;
      spec.ensemble = uint16_t(i);
      const auto e = test::buildPd0(spec);
      s.insert(s.end(), e.begin(), e.end());
    } else if (p == SensorProtocol::kNmea0183) {
      // One full turn per pass, so that replayed passes join without a heading jump (plausibility).
      const std::string l = test::nmeaSentence("HEHDT," + std::to_string(i * 9 / 5 % 360) + ".5,T");
      s.insert(s.end(), l.begin(), l.end());
    } else if (p == SensorProtocol::kWlA50) {
      const std::string l = test::wlSentence("wrz,0.100,0.200,0.010,y,1.90,0.002,1e-06;0;0;0;1e-06;0;0;0;1e-06,1000,1040,250.0,0");
      s.insert(s.end(), l.begin(), l.end());
    } else {
      const float q[4] = {1, 0, 0, 0}, a[3] = {0, 0, 9.81f}, g[3] = {0, 0, 0};
      const auto m = test::buildMtData2(uint16_t(i), q, a, g);
      s.insert(s.end(), m.begin(), m.end());
    }
  }
  return s;
}

// One driver read is up to 4 KiB; the decoder sees the stream in 256-byte reads here.
void BM_SerialDecode(benchmark::State& state) {
  const SensorProtocol p = SensorProtocol(state.range(0));
  const auto bytes = stream(p);
  SensorStreamDecoder decoder;
  decoder.init(p);
  Count sink;
  for (auto _ : state) {
    for (size_t i = 0; i < bytes.size(); i += 256) decoder.feed(bytes.data() + i, std::min<size_t>(256, bytes.size() - i), 0, &sink);
  }
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(bytes.size()));
  state.SetItemsProcessed(int64_t(state.iterations()) * 200);
  state.SetLabel(sensorProtocolName(p));
  state.counters["samples_per_pass"] = double(sink.samples) / double(state.iterations());
  state.counters["bad_frames"] = double(decoder.counters().bad_frames);
}
BENCHMARK(BM_SerialDecode)
    ->Arg(int(SensorProtocol::kPd0))
    ->Arg(int(SensorProtocol::kNmea0183))
    ->Arg(int(SensorProtocol::kWlA50))
    ->Arg(int(SensorProtocol::kXsens));

void BM_N2kHeadingFrame(benchmark::State& state) {
  CanFrame f;
  double t = 0;
  const char* why = "";
  parseCandumpLine("  can0  09F11280   [8]  00 9C 99 FF 7F F6 F5 FD", &f, &t, &why);
  N2kAssembler assembler;
  for (auto _ : state) {
    N2kMessage m;
    N2kVesselHeading h;
    HeadingSample s;
    assembler.add(f, &m, &why);
    decodeN2kVesselHeading(m, &h, &why);
    benchmark::DoNotOptimize(headingSampleFromN2k(h, 0, &s));
  }
  state.SetItemsProcessed(int64_t(state.iterations()));
}
BENCHMARK(BM_N2kHeadingFrame);

}  // namespace
}  // namespace deepnav

BENCHMARK_MAIN();
