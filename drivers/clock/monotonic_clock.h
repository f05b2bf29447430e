#pragma once
#include "nav/types/time.h"

namespace deepnav {

// The system's one monotonic clock (CLOCK_MONOTONIC), in microseconds.
TimeUs monotonicUs();

// Sleeps until the monotonic clock reaches t_us (absolute, so periods do not drift). Returns at once
// when t_us is already past.
void sleepUntilUs(TimeUs t_us);

}  // namespace deepnav
