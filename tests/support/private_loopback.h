#pragma once
// Two loopback addresses for two fake GigE Vision cameras (127.0.0.1 and 127.0.0.2), without touching
// the machine's own interfaces: a private network namespace (unshare(CLONE_NEWNET), as root) whose
// loopback carries both. Used by drivers_aravis_test and service_cameras_test; a child process spawned
// afterwards (e.g. `deepnav run`) inherits the namespace and reaches the cameras.
#include <arpa/inet.h>
#include <ifaddrs.h>
#include <net/if.h>
#include <sched.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace deepnav::testing {

inline bool hasAddress(const char* ip) {
  ifaddrs* list = nullptr;
  if (getifaddrs(&list) != 0) return false;
  bool found = false;
  for (ifaddrs* a = list; a != nullptr; a = a->ifa_next) {
    if (a->ifa_addr == nullptr || a->ifa_addr->sa_family != AF_INET) continue;
    char text[INET_ADDRSTRLEN] = {};
    inet_ntop(AF_INET, &reinterpret_cast<sockaddr_in*>(a->ifa_addr)->sin_addr, text, sizeof(text));
    if (std::strcmp(text, ip) == 0) found = true;
  }
  freeifaddrs(list);
  return found;
}

// Call from the main thread before any other thread exists (a namespace belongs to the thread that
// made it and to the threads it creates afterwards). Returns "" when ready, else why not.
inline std::string prepareLoopback() {
  if (hasAddress("127.0.0.2")) return "";
  if (unshare(CLONE_NEWNET) != 0) {
    return std::string("two loopback addresses needed: unshare(CLONE_NEWNET) failed (") + std::strerror(errno) +
           ") and 127.0.0.2 is not on lo (ip addr add 127.0.0.2/8 dev lo)";
  }
  const int fd = socket(AF_INET, SOCK_DGRAM, 0);
  ifreq up{};
  std::strncpy(up.ifr_name, "lo", IFNAMSIZ - 1);
  bool ok = fd >= 0 && ioctl(fd, SIOCGIFFLAGS, &up) == 0;
  up.ifr_flags = static_cast<short>(up.ifr_flags | IFF_UP | IFF_RUNNING);
  ok = ok && ioctl(fd, SIOCSIFFLAGS, &up) == 0;
  ifreq alias{};
  std::strncpy(alias.ifr_name, "lo:1", IFNAMSIZ - 1);
  auto* sin = reinterpret_cast<sockaddr_in*>(&alias.ifr_addr);
  sin->sin_family = AF_INET;
  inet_pton(AF_INET, "127.0.0.2", &sin->sin_addr);
  ok = ok && ioctl(fd, SIOCSIFADDR, &alias) == 0;
  if (fd >= 0) close(fd);
  if (!ok || !hasAddress("127.0.0.2")) {
    return std::string("could not put 127.0.0.2 on the private loopback: ") + std::strerror(errno);
  }
  return "";
}

}  // namespace deepnav::testing
