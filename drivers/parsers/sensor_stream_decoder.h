#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>

#include "drivers/parsers/frame_plausibility.h"
#include "drivers/parsers/line_framer.h"
#include "drivers/parsers/pd0_framer.h"
#include "drivers/parsers/pd6_sentence.h"
#include "drivers/parsers/sample_sink.h"
#include "drivers/parsers/xbus_framer.h"

namespace deepnav {

struct Pd0Ensemble;

// The serial protocols a DVL, compass or AHRS speaks.
enum class SensorProtocol { kPd0, kPd6, kWlA50, kNmea0183, kXsens };

bool parseSensorProtocol(std::string_view name, SensorProtocol* protocol);
const char* sensorProtocolName(SensorProtocol protocol);

// Bytes in, samples out, for one serial sensor: framing with resynchronisation, checksum and field
// checks, conversion to the nav sample types. No OS access: the driver (drivers/serial) reads the
// port, the tests feed bytes directly. Every buffer is allocated by init().
class SensorStreamDecoder {
 public:
  struct Counters {
    uint64_t frames = 0;         // checksum-valid frames
    uint64_t bad_frames = 0;     // framing/checksum/field errors
    uint64_t bytes_skipped = 0;
    uint64_t samples = 0;        // samples handed to the sink
    uint64_t sink_refused = 0;   // samples the sink could not take
    uint64_t ignored = 0;        // valid messages with nothing for the nav loop
    uint64_t implausible = 0;    // checksum-valid frames rejected by FramePlausibility (counted in bad_frames too)
  };

  SensorStreamDecoder();
  ~SensorStreamDecoder();
  bool init(SensorProtocol protocol, const PlausibilityLimits& limits = {});
  // Feeds n bytes that arrived at t_us (the clock of the nav loop); samples go to `sink`.
  void feed(const uint8_t* data, size_t n, TimeUs t_us, SampleSink* sink);
  const Counters& counters() const { return counters_; }
  SensorProtocol protocol() const { return protocol_; }

 private:
  void onFrame(const RawFrame& frame, TimeUs t_us, SampleSink* sink);
  void deliver(bool accepted);
  bool plausibleFrame(FramePlausibility::Verdict v);
  bool next(RawFrame* frame, FrameError* error);
  size_t push(const uint8_t* data, size_t n);

  SensorProtocol protocol_ = SensorProtocol::kPd0;
  Pd0Framer pd0_;
  LineFramer lines_;
  XbusFramer xbus_;
  std::unique_ptr<Pd0Ensemble> ensemble_;
  Pd6DvlAssembler pd6_;
  FramePlausibility plausible_;
  Counters counters_;
};

}  // namespace deepnav
