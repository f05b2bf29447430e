#include "drivers/systemd/stop_signals.h"

#include <pthread.h>
#include <signal.h>

namespace deepnav {
namespace {

sigset_t stopSet() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGTERM);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGHUP);
  return set;
}

}  // namespace

StopSignals::StopSignals() {
  const sigset_t set = stopSet();
  ::pthread_sigmask(SIG_BLOCK, &set, &previous_);
}

StopSignals::~StopSignals() {
  ::pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
}

int StopSignals::wait(TimeUs timeout_us) {
  const sigset_t set = stopSet();
  if (timeout_us < 0) timeout_us = 0;
  timespec timeout{static_cast<time_t>(timeout_us / kUsPerS), static_cast<long>((timeout_us % kUsPerS) * 1000)};
  const int sig = ::sigtimedwait(&set, nullptr, &timeout);
  return sig > 0 ? sig : 0;
}

}  // namespace deepnav
