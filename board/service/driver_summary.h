#pragma once
#include <string>

#include "drivers/sensor_io/sensor_threads.h"

namespace deepnav {

// One line for the journal when `deepnav run` stops: what each sensor driver thread received and lost
// (frames, bad frames, samples the full rings refused, serial ports reopened after vanishing, the CAN
// controller's state and error counters, Modbus depth reads that failed), so a flaky cable or a bus
// near error-passive shows after a dive. Empty when no driver ran (replay, simulator).
std::string formatDriverSummary(const SensorThreads::Status& s);

}  // namespace deepnav
