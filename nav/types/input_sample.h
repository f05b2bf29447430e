#pragma once
#include <variant>

#include "nav/types/attitude_sample.h"
#include "nav/types/depth_sample.h"
#include "nav/types/dvl_sample.h"
#include "nav/types/heading_sample.h"
#include "nav/types/imu_sample.h"
#include "nav/types/vision_result.h"

namespace deepnav {

// Every input the nav loop consumes. Drivers (live or replay) produce these; the loop records each one
// it consumes, in consumption order, so that a replay reproduces the outputs bit for bit.
using InputSample = std::variant<ImuSample, DvlSample, HeadingSample, AttitudeSample, DepthSample, VisionResult>;

inline TimeUs sampleTimeUs(const InputSample& s) {
  return std::visit([](const auto& v) { return v.t_us; }, s);
}

}  // namespace deepnav
