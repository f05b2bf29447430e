#include "drivers/probe/device_probe.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <net/if.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

namespace deepnav {
namespace {

constexpr std::uint16_t kGvcpDiscoveryCmd = 0x0002;
constexpr std::uint16_t kGvcpDiscoveryAck = 0x0003;
constexpr std::uint16_t kGvcpDiscoveryBody = 0xF8;

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

bool probeGigeCamera(const std::string& address, int timeout_ms, std::string* reason, int port) {
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(static_cast<std::uint16_t>(port));
  if (::inet_pton(AF_INET, address.c_str(), &to.sin_addr) != 1) {
    *reason = "is not an IPv4 address";
    return false;
  }
  Fd fd(::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0));
  if (fd.get() < 0) {
    *reason = std::string("cannot create a socket: ") + std::strerror(errno);
    return false;
  }
  if (::connect(fd.get(), reinterpret_cast<const sockaddr*>(&to), sizeof to) != 0) {
    *reason = std::string("no route: ") + std::strerror(errno);
    return false;
  }
  const std::uint16_t request_id = 0x0D4E;
  const std::uint8_t cmd[8] = {0x42, 0x01, 0x00, kGvcpDiscoveryCmd & 0xFF, 0x00, 0x00,
                               static_cast<std::uint8_t>(request_id >> 8), static_cast<std::uint8_t>(request_id & 0xFF)};
  if (::send(fd.get(), cmd, sizeof cmd, 0) != static_cast<ssize_t>(sizeof cmd)) {
    *reason = std::string("cannot send the GVCP discovery: ") + std::strerror(errno);
    return false;
  }
  pollfd p{fd.get(), POLLIN, 0};
  std::uint8_t ack[8 + kGvcpDiscoveryBody];
  while (::poll(&p, 1, timeout_ms) == 1) {
    const ssize_t n = ::recv(fd.get(), ack, sizeof ack, 0);
    if (n < 0) {
      // A closed UDP port on a reachable host comes back as ECONNREFUSED (ICMP port unreachable).
      *reason = std::string("no GigE Vision device answers: ") + std::strerror(errno);
      return false;
    }
    const auto u16 = [&](int at) { return static_cast<std::uint16_t>((ack[at] << 8) | ack[at + 1]); };
    if (n >= 8 && u16(2) == kGvcpDiscoveryAck && u16(6) == request_id) {
      if (u16(0) != 0) {
        *reason = "GVCP discovery answered with status " + std::to_string(u16(0));
        return false;
      }
      return true;
    }
  }
  *reason = "no answer to a GVCP discovery within " + std::to_string(timeout_ms) + " ms";
  return false;
}

}  // namespace deepnav
