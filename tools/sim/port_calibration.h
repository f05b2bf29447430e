#pragma once
#include <string>

#include "board/config/vehicle_setup.h"
#include "tools/sim/scenario.h"

namespace deepnav::sim {

// A scenario rendered through a flat port (camera.port) gives raw images. When the board names no
// calibration, the recording describes the simulated cameras as a vehicle's board would: the stored
// board gets camera.calibration_file and camera.port.* (model flat, the scenario's glass and indices),
// and the calibration itself (the scenario's in-air pinhole pair: no distortion, R = I, T = -baseline
// along x) is stored beside it (deepnav.calibration), so `deepnav replay` applies PinAx to the dive;
// `--set camera.port.model=none` replays it uncorrected. *described is false when nothing was changed
// (no port, or the board already names a calibration: it is the user's description of the rig).
bool describeSimulatedPort(const Scenario& scenario, VehicleSetup* setup, bool* described, std::string* error);

// The name the simulated calibration is stored under in the board (camera.calibration_file).
inline constexpr const char* kSimulatedCalibrationName = "simulated_in_air_calibration.yaml";

}  // namespace deepnav::sim
