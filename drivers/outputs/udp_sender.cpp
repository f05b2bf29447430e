#include "drivers/outputs/udp_sender.h"

#include <arpa/inet.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace deepnav {

UdpSender::~UdpSender() {
  if (fd_ >= 0) ::close(fd_);
}

bool UdpSender::parseDestinations(const std::string& text, std::vector<sockaddr_in>* out, std::string* error) {
  out->clear();
  std::size_t start = 0;
  while (start <= text.size() && !text.empty()) {
    const std::size_t comma = text.find(',', start);
    std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    while (!item.empty() && item.front() == ' ') item.erase(item.begin());
    while (!item.empty() && item.back() == ' ') item.pop_back();
    const std::size_t colon = item.rfind(':');
    sockaddr_in a{};
    a.sin_family = AF_INET;
    char* end = nullptr;
    const long port = colon == std::string::npos ? 0 : std::strtol(item.c_str() + colon + 1, &end, 10);
    if (colon == std::string::npos || *end != '\0' || port < 1 || port > 65535 ||
        ::inet_pton(AF_INET, item.substr(0, colon).c_str(), &a.sin_addr) != 1) {
      if (error) *error = "'" + item + "' is not an IPv4 address and port (e.g. 192.168.1.20:5600)";
      return false;
    }
    a.sin_port = htons(static_cast<std::uint16_t>(port));
    out->push_back(a);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return true;
}

bool UdpSender::open(const std::string& destinations, std::string* error) {
  if (!parseDestinations(destinations, &destinations_, error)) return false;
  fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd_ < 0) {
    if (error) *error = std::string("UDP output: cannot create a socket: ") + std::strerror(errno);
    return false;
  }
  // Broadcast destinations (e.g. 192.168.1.255) need SO_BROADCAST; harmless for unicast ones.
  const int on = 1;
  ::setsockopt(fd_, SOL_SOCKET, SO_BROADCAST, &on, sizeof on);
  return true;
}

void UdpSender::send(const std::uint8_t* data, std::size_t size) {
  for (const sockaddr_in& a : destinations_) {
    const ssize_t n = ::sendto(fd_, data, size, MSG_DONTWAIT | MSG_NOSIGNAL, reinterpret_cast<const sockaddr*>(&a),
                               sizeof a);
    if (n == static_cast<ssize_t>(size)) {
      ++sent_;
    } else {
      ++failures_;
    }
  }
}

}  // namespace deepnav
