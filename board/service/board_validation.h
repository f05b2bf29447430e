#pragma once
#include <sched.h>

#include <string>

#include "board/config/vehicle_setup.h"

namespace deepnav {

// What `deepnav run` learns from validating a board, besides the setup itself.
struct ValidatedBoard {
  std::string replay_path;  // resolved recording to play as the sensors; empty: the board's devices
  bool has_devices = false;
  bool has_loop_cpus = false, has_process_cpus = false;
  cpu_set_t loop_cpus{}, process_cpus{};
};

// Checks everything a run needs before anything starts: there is a source; a replay recording opens and
// its images fit camera.*; every listed device answers (serial ports open, the CAN interface is up, GigE
// cameras answer a discovery); calibration is consistent (principal point inside the image); output
// addresses and CPU lists parse. replay_override (from --replay) replaces sources.replay_path. The first
// problem fails with one message "<board>: <key>: <what>" naming the key and the device or file.
bool validateBoard(const VehicleSetup& setup, const std::string& board_path, const std::string& replay_override,
                   ValidatedBoard* out, std::string* error);

}  // namespace deepnav
