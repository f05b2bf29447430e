#include "drivers/buffers/live_inputs.h"

#include <array>

namespace deepnav {
namespace {

using D = ParamDecl<LiveInputCapacities>;

const std::array kLiveInputCapacityParams = {
    D{"imu", ParamType::kSize, "samples", 8, 65536, "", "IMU ring capacity",
      DEEPNAV_PARAM_FIELD(LiveInputCapacities, imu)},
    D{"dvl", ParamType::kSize, "samples", 4, 65536, "", "DVL ring capacity",
      DEEPNAV_PARAM_FIELD(LiveInputCapacities, dvl)},
    D{"heading", ParamType::kSize, "samples", 4, 65536, "", "compass ring capacity",
      DEEPNAV_PARAM_FIELD(LiveInputCapacities, heading)},
    D{"attitude", ParamType::kSize, "samples", 4, 65536, "", "AHRS attitude ring capacity",
      DEEPNAV_PARAM_FIELD(LiveInputCapacities, attitude)},
    D{"depth", ParamType::kSize, "samples", 4, 65536, "", "depth ring capacity",
      DEEPNAV_PARAM_FIELD(LiveInputCapacities, depth)},
    D{"frames", ParamType::kSize, "pairs", 2, 64, "", "stereo frames in the preallocated pool",
      DEEPNAV_PARAM_FIELD(LiveInputCapacities, frames)},
};

}  // namespace

std::span<const ParamDecl<LiveInputCapacities>> liveInputCapacityParams() { return kLiveInputCapacityParams; }

bool validateLiveInputCapacities(const LiveInputCapacities& c, std::string* error) {
  return checkParamRanges(liveInputCapacityParams(), c, "LiveInputCapacities", kBuffersSection, error);
}

}  // namespace deepnav
