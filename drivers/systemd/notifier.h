#pragma once
#include <string>
#include <string_view>

#include "nav/types/time.h"

namespace deepnav {

// The service side of systemd's notify protocol (sd_notify(3)): newline-separated "KEY=VALUE" states sent
// as one datagram to the AF_UNIX socket named by $NOTIFY_SOCKET ("/path", or "@name" for the abstract
// namespace). Without $NOTIFY_SOCKET (not started by systemd) the notifier is disabled and send() does
// nothing, successfully. Written here rather than linked from libsystemd: it is one sendto(), and the
// aarch64 build then needs no libsystemd in its sysroot.
class SystemdNotifier {
 public:
  SystemdNotifier() = default;
  ~SystemdNotifier();
  SystemdNotifier(const SystemdNotifier&) = delete;
  SystemdNotifier& operator=(const SystemdNotifier&) = delete;

  // Reads $NOTIFY_SOCKET and opens the socket; false with a message naming the variable when it is set
  // but unusable.
  bool open(std::string* error);
  bool enabled() const { return fd_ >= 0; }
  // Sends e.g. "READY=1\nSTATUS=..." (never blocks: a full socket queue drops the datagram, counted).
  bool send(std::string_view state);
  unsigned long failures() const { return failures_; }

  // $WATCHDOG_USEC when it is set and meant for this process ($WATCHDOG_PID absent or equal to our pid);
  // 0 when the watchdog is off.
  static TimeUs watchdogIntervalUs();

 private:
  int fd_ = -1;
  std::string address_;  // sun_path bytes (a leading '\0' for the abstract namespace)
  unsigned long failures_ = 0;
};

}  // namespace deepnav
