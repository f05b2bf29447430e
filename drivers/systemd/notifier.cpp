#include "drivers/systemd/notifier.h"

#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <cstring>

namespace deepnav {

SystemdNotifier::~SystemdNotifier() {
  if (fd_ >= 0) ::close(fd_);
}

bool SystemdNotifier::open(std::string* error) {
  const char* env = std::getenv("NOTIFY_SOCKET");
  if (!env || !*env) return true;  // not under systemd: a disabled notifier
  std::string path = env;
  if (path[0] != '/' && path[0] != '@') {
    if (error) *error = "NOTIFY_SOCKET='" + path + "' is neither a path nor an abstract socket name (@name)";
    return false;
  }
  if (path.size() >= sizeof(sockaddr_un{}.sun_path)) {
    if (error) *error = "NOTIFY_SOCKET='" + path + "' is longer than a socket address";
    return false;
  }
  if (path[0] == '@') path[0] = '\0';
  fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (fd_ < 0) {
    if (error) *error = std::string("NOTIFY_SOCKET: cannot create a datagram socket: ") + std::strerror(errno);
    return false;
  }
  address_ = path;
  return true;
}

bool SystemdNotifier::send(std::string_view state) {
  if (fd_ < 0) return true;
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  std::memcpy(addr.sun_path, address_.data(), address_.size());
  const auto len = static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + address_.size());
  const ssize_t n = ::sendto(fd_, state.data(), state.size(), MSG_NOSIGNAL, reinterpret_cast<sockaddr*>(&addr), len);
  if (n != static_cast<ssize_t>(state.size())) {
    ++failures_;
    return false;
  }
  return true;
}

TimeUs SystemdNotifier::watchdogIntervalUs() {
  const char* usec = std::getenv("WATCHDOG_USEC");
  if (!usec || !*usec) return 0;
  if (const char* pid = std::getenv("WATCHDOG_PID"); pid && *pid) {
    char* end = nullptr;
    const long long p = std::strtoll(pid, &end, 10);
    if (*end != '\0' || p != static_cast<long long>(::getpid())) return 0;
  }
  char* end = nullptr;
  const long long v = std::strtoll(usec, &end, 10);
  return (*end == '\0' && v > 0) ? static_cast<TimeUs>(v) : 0;
}

}  // namespace deepnav
