#include "drivers/camera/gvcp_probe.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <cstdint>

namespace deepnav {

bool gvcpDeviceAnswers(const std::string& ipv4, int timeout_ms) {
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(3956);  // GVCP
  if (inet_pton(AF_INET, ipv4.c_str(), &to.sin_addr) != 1) return false;
  const int fd = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return false;
  // GVCP command header (GigE Vision 2.0, 15.1): key 0x42, flags (0x01: acknowledge), command
  // DISCOVERY_CMD 0x0002, payload length 0, request id.
  const std::array<std::uint8_t, 8> command = {0x42, 0x01, 0x00, 0x02, 0x00, 0x00, 0x4e, 0x44};
  bool answered = false;
  if (connect(fd, reinterpret_cast<const sockaddr*>(&to), sizeof(to)) == 0 &&
      send(fd, command.data(), command.size(), 0) == static_cast<ssize_t>(command.size())) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, timeout_ms) == 1) {
      // Acknowledge header: status, answer DISCOVERY_ACK 0x0003, length, the request id.
      std::array<std::uint8_t, 512> ack{};
      const ssize_t n = recv(fd, ack.data(), ack.size(), 0);
      answered = n >= 8 && ack[2] == 0x00 && ack[3] == 0x03 && ack[6] == 0x4e && ack[7] == 0x44;
    }
  }
  close(fd);
  return answered;
}

}  // namespace deepnav
