#pragma once
#include <string>
#include <vector>

#include "board/config/vehicle_setup.h"

namespace deepnav {

// Applies "key=value" overrides (e.g. "vision.vo_mode=all") to a loaded setup: the board text is
// rewritten with them and parsed again, so the overrides are validated by the parameter table like the
// file itself and the recording stores the board that actually ran. False with the key named on error.
bool applyBoardOverrides(const std::vector<std::string>& overrides, VehicleSetup* setup, std::string* error);

}  // namespace deepnav
