#pragma once
#include <netinet/in.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace deepnav {

// Sends each datagram to a fixed list of IPv4 destinations from one non-blocking socket: a full socket
// buffer or an unreachable host drops that datagram and counts it; nothing ever waits.
class UdpSender {
 public:
  UdpSender() = default;
  ~UdpSender();
  UdpSender(const UdpSender&) = delete;
  UdpSender& operator=(const UdpSender&) = delete;

  // destinations: "a.b.c.d:port[,a.b.c.d:port...]"; on error the message names the bad entry.
  static bool parseDestinations(const std::string& text, std::vector<sockaddr_in>* out, std::string* error);

  bool open(const std::string& destinations, std::string* error);
  void send(const std::uint8_t* data, std::size_t size);
  std::size_t destinationCount() const { return destinations_.size(); }
  std::uint64_t sent() const { return sent_; }
  std::uint64_t failures() const { return failures_; }

 private:
  int fd_ = -1;
  std::vector<sockaddr_in> destinations_;
  std::uint64_t sent_ = 0;
  std::uint64_t failures_ = 0;
};

}  // namespace deepnav
