#include "drivers/foreign/topic_map.h"

namespace deepnav::foreign {

std::string_view sensorName(ForeignSensor s) {
  switch (s) {
    case ForeignSensor::kImu: return "imu";
    case ForeignSensor::kAttitude: return "attitude";
    case ForeignSensor::kHeading: return "heading";
    case ForeignSensor::kDvl: return "dvl";
    case ForeignSensor::kDepth: return "depth";
    case ForeignSensor::kCompass: return "compass";
    case ForeignSensor::kCameraLeft: return "camera_left";
    case ForeignSensor::kCameraRight: return "camera_right";
    case ForeignSensor::kCount: break;
  }
  return "?";
}

}  // namespace deepnav::foreign
