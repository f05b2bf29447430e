#pragma once
#include <signal.h>

#include "nav/types/time.h"

namespace deepnav {

// The service stops on SIGTERM (systemd's stop), SIGINT (Ctrl-C) and SIGHUP. They are blocked in the
// calling thread, and so in every thread it creates afterwards, and taken synchronously by
// waitStopSignal(): no handler runs in an arbitrary thread, and the loop is never interrupted.
class StopSignals {
 public:
  StopSignals();   // blocks them
  ~StopSignals();  // restores the previous mask
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // Waits up to timeout_us; returns the signal taken, 0 when none came.
  int wait(TimeUs timeout_us);

 private:
  sigset_t previous_;  // the caller's signal mask
};

}  // namespace deepnav
