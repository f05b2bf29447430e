#pragma once
#include "board/service/deepnav_service.h"

namespace deepnav {

// `deepnav run`: blocks the stop signals, validates the board, runs the service until stopped.
// Exit codes: 0 clean stop, 2 the board is not fit to run (message names the key or device), 1 a
// runtime failure. validate_only: stop after the validation ("<board>: valid" on stdout).
int runServiceCommand(const ServiceOptions& options, bool validate_only);

}  // namespace deepnav
