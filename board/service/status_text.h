#pragma once
#include <cstdint>
#include <string>

#include "drivers/outputs/nav_output.h"

namespace deepnav {

// One line for systemd's STATUS= (and the log): stage, health words, loop counters and each sensor's
// state, e.g. "stage 1 workspace | health ok | ticks 1200, late 0, overruns 0/0 | imu ok (1210), dvl stale
// (40), ...". Called off the loop (it allocates).
std::string formatStatus(const NavOutput& out);

// The health bits as words ("ok" when none): "stalled late nav-overrun ...".
std::string healthWords(std::uint32_t health);

const char* stageName(NavStage stage);

}  // namespace deepnav
