#pragma once
#include <variant>

#include "nav/types/attitude_sample.h"
#include "nav/types/depth_sample.h"
#include "nav/types/dvl_sample.h"
#include "nav/types/heading_sample.h"
#include "nav/types/imu_sample.h"
#include "nav/types/time.h"
#include "tools/sim/camera_tick.h"
#include "tools/sim/ground_truth_sample.h"
#include "tools/sim/sim_stream.h"

namespace deepnav::sim {

using SimSample = std::variant<GroundTruthSample, ImuSample, DvlSample, HeadingSample, AttitudeSample,
                               DepthSample, CameraTick>;

// One element of the simulator's time-ordered output: the stream it belongs to, when it reaches the
// vehicle (the sample's own stamp t_us, except under a clock_jump fault, where only the stamp jumps) and
// the sample. The variant's alternatives follow SimStream's order, so
// sample.index() == static_cast<size_t>(stream).
struct SimEvent {
  TimeUs t_us = 0;
  SimStream stream = SimStream::kGroundTruth;
  SimSample sample;
};

}  // namespace deepnav::sim
