#pragma once
#include <string>
#include <vector>

#include "tools/sim/environment_config.h"
#include "tools/sim/faults/fault_spec.h"
#include "tools/sim/panel_geometry.h"
#include "tools/sim/sensor_timing.h"
#include "tools/sim/sensors/attitude_model.h"
#include "tools/sim/sensors/camera_rig.h"
#include "tools/sim/sensors/compass_model.h"
#include "tools/sim/sensors/depth_model.h"
#include "tools/sim/sensors/dvl_model.h"
#include "tools/sim/sensors/imu_model.h"
#include "tools/sim/trajectory_config.h"
#include "tools/sim/water_config.h"

namespace deepnav::sim {

// Everything a simulated dive needs, as read from a scenario file (tools/sim/scenarios/*.yaml; every
// key with unit, range and default is listed in tools/sim/README.md). Default-constructed = default.yaml.
struct Scenario {
  std::string name = "default";
  std::string description;
  double duration_s = 120.0;  // streams cover [0, duration_s]
  EnvironmentConfig environment;
  WaterConfig water;
  PanelGeometry panel;
  TrajectoryConfig trajectory;
  ImuConfig imu;
  DvlConfig dvl;
  CompassConfig compass;
  DepthConfig depth;
  AttitudeConfig attitude;
  CameraConfig camera;
  TimingConfig timing;  // per-stream latency, clock offset and drift of the stamps
  std::vector<FaultSpec> faults;

  bool operator==(const Scenario&) const = default;
};

}  // namespace deepnav::sim
