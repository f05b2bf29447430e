#pragma once
#include <cstddef>
#include <type_traits>
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

// The alternatives follow SimStream's order (the simulator builds a stream's sample by its enum): checked
// here, so reordering either does not compile.
template <SimStream stream>
using SimSampleOf = std::variant_alternative_t<static_cast<std::size_t>(stream), SimSample>;
static_assert(std::variant_size_v<SimSample> == static_cast<std::size_t>(kSimStreamCount));
static_assert(std::is_same_v<SimSampleOf<SimStream::kGroundTruth>, GroundTruthSample>);
static_assert(std::is_same_v<SimSampleOf<SimStream::kImu>, ImuSample>);
static_assert(std::is_same_v<SimSampleOf<SimStream::kDvl>, DvlSample>);
static_assert(std::is_same_v<SimSampleOf<SimStream::kCompass>, HeadingSample>);
static_assert(std::is_same_v<SimSampleOf<SimStream::kAttitude>, AttitudeSample>);
static_assert(std::is_same_v<SimSampleOf<SimStream::kDepth>, DepthSample>);
static_assert(std::is_same_v<SimSampleOf<SimStream::kCamera>, CameraTick>);

// One element of the simulator's time-ordered output: the stream it belongs to, when it reaches the
// vehicle (the sample's own stamp t_us, except under a clock_jump fault, where only the stamp jumps) and
// the sample, whose alternative is SimSampleOf<stream>.
struct SimEvent {
  TimeUs t_us = 0;
  SimStream stream = SimStream::kGroundTruth;
  SimSample sample;
};

}  // namespace deepnav::sim
