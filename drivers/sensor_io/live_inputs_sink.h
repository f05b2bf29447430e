#pragma once
#include <atomic>
#include <cstdint>

#include "drivers/buffers/live_inputs.h"
#include "drivers/parsers/sample_sink.h"

namespace deepnav {

// Kinds of samples a driver may forward to the nav loop's rings.
enum SampleKind : uint8_t {
  kSampleDvl = 1,
  kSampleHeading = 2,
  kSampleAttitude = 4,
  kSampleImu = 8,
  kSampleDepth = 16,
};

// A driver thread's sink: forwards the sample kinds in `kinds` to the LiveInputs rings (each ring has
// exactly one producing thread: SensorThreads gives each kind to one driver) and drops the others.
// A full ring refuses the sample (the ring counts it) and the driver counts the refusal.
class LiveInputsSink : public SampleSink {
 public:
  LiveInputsSink(LiveInputs* inputs, uint8_t kinds) : inputs_(inputs), kinds_(kinds) {}
  bool onDvl(const DvlSample& s) override { return !(kinds_ & kSampleDvl) || inputs_->ring<DvlSample>().push(s); }
  bool onHeading(const HeadingSample& s) override { return !(kinds_ & kSampleHeading) || inputs_->ring<HeadingSample>().push(s); }
  bool onAttitude(const AttitudeSample& s) override { return !(kinds_ & kSampleAttitude) || inputs_->ring<AttitudeSample>().push(s); }
  bool onImu(const ImuSample& s) override { return !(kinds_ & kSampleImu) || inputs_->ring<ImuSample>().push(s); }
  bool onDepth(const DepthSample& s) override { return !(kinds_ & kSampleDepth) || inputs_->ring<DepthSample>().push(s); }

 private:
  LiveInputs* inputs_;
  uint8_t kinds_;
};

}  // namespace deepnav
