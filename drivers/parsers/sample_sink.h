#pragma once
#include "nav/types/attitude_sample.h"
#include "nav/types/depth_sample.h"
#include "nav/types/dvl_sample.h"
#include "nav/types/heading_sample.h"
#include "nav/types/imu_sample.h"

namespace deepnav {

// Where decoders hand their samples (a driver forwards them to the nav loop's rings; a test collects
// them). Each method returns false when the sample could not be taken (ring full); the decoder counts it.
class SampleSink {
 public:
  virtual ~SampleSink() = default;
  virtual bool onDvl(const DvlSample&) { return true; }
  virtual bool onHeading(const HeadingSample&) { return true; }
  virtual bool onAttitude(const AttitudeSample&) { return true; }
  virtual bool onImu(const ImuSample&) { return true; }
  virtual bool onDepth(const DepthSample&) { return true; }
};

}  // namespace deepnav
