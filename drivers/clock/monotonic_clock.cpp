#include "drivers/clock/monotonic_clock.h"

#include <cerrno>
#include <ctime>

namespace deepnav {

TimeUs monotonicUs() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<TimeUs>(ts.tv_sec) * kUsPerS + ts.tv_nsec / 1000;
}

void sleepUntilUs(TimeUs t_us) {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(t_us / kUsPerS);
  ts.tv_nsec = static_cast<long>((t_us % kUsPerS) * 1000);
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
  }
}

}  // namespace deepnav
