#include "drivers/probe/device_probe.h"

#include <fcntl.h>
#include <net/if.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace deepnav {
namespace {

class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

}  // namespace

bool probeSerialPort(const std::string& path, std::string* reason) {
  Fd fd(::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC));
  if (fd.get() < 0) {
    *reason = errno == ENOENT ? "no such device" : std::string("cannot open: ") + std::strerror(errno);
    return false;
  }
  if (!::isatty(fd.get())) {
    *reason = "is not a serial port (not a terminal device)";
    return false;
  }
  return true;
}

bool probeCanInterface(const std::string& name, std::string* reason) {
  if (name.size() >= IFNAMSIZ || ::if_nametoindex(name.c_str()) == 0) {
    *reason = "no such network interface";
    return false;
  }
  Fd fd(::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0));
  ifreq ifr{};
  std::memcpy(ifr.ifr_name, name.c_str(), name.size());
  if (fd.get() < 0 || ::ioctl(fd.get(), SIOCGIFFLAGS, &ifr) != 0) {
    *reason = std::string("cannot read the interface flags: ") + std::strerror(errno);
    return false;
  }
  if ((ifr.ifr_flags & IFF_UP) == 0) {
    *reason = "interface is down (ip link set " + name + " up type can bitrate ...)";
    return false;
  }
  return true;
}

bool probeVideoDevice(const std::string& path, std::string* reason) {
  Fd fd(::open(path.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC));
  if (fd.get() < 0) {
    *reason = errno == ENOENT ? "no such device" : std::string("cannot open: ") + std::strerror(errno);
    return false;
  }
  return true;
}

}  // namespace deepnav
