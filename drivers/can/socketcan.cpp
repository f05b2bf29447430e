#include "drivers/can/socketcan.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/netlink.h>
#include <linux/can/raw.h>
#include <linux/if_link.h>
#include <linux/netlink.h>
#include <linux/rtnetlink.h>
#include <net/if.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

namespace deepnav {

SocketCan::~SocketCan() { close(); }

void SocketCan::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void SocketCan::adopt(int fd) {
  close();
  fd_ = fd;
}

bool SocketCan::open(const std::string& interface, const CanFilter* filters, int num_filters, std::string* error) {
  close();
  if (num_filters < 0 || num_filters > kMaxFilters) return *error = interface + ": too many CAN filters", false;
  if (interface.empty() || interface.size() >= IFNAMSIZ) return *error = "CAN interface name '" + interface + "' is invalid", false;
  const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC | SOCK_NONBLOCK, CAN_RAW);
  if (fd < 0) return *error = interface + ": cannot create a CAN socket: " + std::strerror(errno), false;
  const auto fail = [&](const char* what) {
    *error = interface + ": " + what + ": " + std::strerror(errno);
    ::close(fd);
    return false;
  };
  const unsigned index = ::if_nametoindex(interface.c_str());
  if (index == 0) return fail("no such CAN interface");
  if (num_filters > 0) {
    can_filter kf[kMaxFilters];
    for (int i = 0; i < num_filters; ++i) {
      kf[i].can_id = filters[i].id | (filters[i].extended ? CAN_EFF_FLAG : 0);
      kf[i].can_mask = filters[i].mask | CAN_EFF_FLAG | CAN_RTR_FLAG;  // identifier length must match; no RTR
    }
    if (::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_FILTER, kf, socklen_t(sizeof(can_filter) * num_filters)) != 0) {
      return fail("cannot set the CAN filters");
    }
  }
  const can_err_mask_t err_mask = CAN_ERR_TX_TIMEOUT | CAN_ERR_CRTL | CAN_ERR_BUSOFF | CAN_ERR_BUSERROR |
                                  CAN_ERR_RESTARTED | CAN_ERR_PROT | CAN_ERR_TRX | CAN_ERR_ACK | CAN_ERR_CNT;
  if (::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &err_mask, sizeof err_mask) != 0) {
    return fail("cannot enable CAN error frames");
  }
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = int(index);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) return fail("cannot bind the CAN socket");
  fd_ = fd;
  return true;
}

SocketCan::Read SocketCan::read(CanFrame* frame, uint32_t* error_id, int timeout_ms) {
  if (fd_ < 0) return Read::kFailed;
  pollfd p{fd_, POLLIN, 0};
  const int r = ::poll(&p, 1, timeout_ms);
  if (r == 0 || (r < 0 && errno == EINTR)) return Read::kTimeout;
  if (r < 0 || (p.revents & (POLLERR | POLLHUP | POLLNVAL) && !(p.revents & POLLIN))) return Read::kFailed;
  can_frame kf{};
  const ssize_t n = ::read(fd_, &kf, sizeof kf);
  if (n < 0 && (errno == EAGAIN || errno == EINTR)) return Read::kTimeout;
  if (n != ssize_t(sizeof kf)) return Read::kFailed;  // short read or end of stream
  *frame = CanFrame{};
  frame->dlc = std::min<uint8_t>(kf.can_dlc, 8);
  std::copy(kf.data, kf.data + 8, frame->data.begin());
  if (kf.can_id & CAN_ERR_FLAG) {
    *error_id = kf.can_id & CAN_ERR_MASK;
    return Read::kErrorFrame;
  }
  frame->extended = (kf.can_id & CAN_EFF_FLAG) != 0;
  frame->rtr = (kf.can_id & CAN_RTR_FLAG) != 0;
  frame->id = kf.can_id & (frame->extended ? CAN_EFF_MASK : CAN_SFF_MASK);
  return Read::kFrame;
}

bool SocketCan::write(const CanFrame& f) {
  if (fd_ < 0 || f.dlc > 8) return false;
  can_frame kf{};
  kf.can_id = f.id | (f.extended ? CAN_EFF_FLAG : 0) | (f.rtr ? CAN_RTR_FLAG : 0);
  kf.can_dlc = f.dlc;
  std::copy(f.data.begin(), f.data.begin() + f.dlc, kf.data);
  return ::write(fd_, &kf, sizeof kf) == ssize_t(sizeof kf);
}

bool SocketCan::requestRestart(const std::string& interface, std::string* error) {
  const unsigned index = ::if_nametoindex(interface.c_str());
  if (index == 0) return *error = interface + ": no such interface", false;
  const int fd = ::socket(AF_NETLINK, SOCK_RAW | SOCK_CLOEXEC, NETLINK_ROUTE);
  if (fd < 0) return *error = std::string("netlink socket: ") + std::strerror(errno), false;
  // RTM_NEWLINK { ifinfomsg, IFLA_LINKINFO { IFLA_INFO_KIND "can", IFLA_INFO_DATA { IFLA_CAN_RESTART 1 } } }
  struct {
    nlmsghdr nh;
    ifinfomsg ifi;
    char attrs[128];
  } req{};
  req.nh.nlmsg_len = NLMSG_LENGTH(sizeof(ifinfomsg));
  req.nh.nlmsg_type = RTM_NEWLINK;
  req.nh.nlmsg_flags = NLM_F_REQUEST | NLM_F_ACK;
  req.ifi.ifi_family = AF_UNSPEC;
  req.ifi.ifi_index = int(index);
  const auto add = [&](rtattr* parent, unsigned short type, const void* data, size_t len) {
    rtattr* a = reinterpret_cast<rtattr*>(reinterpret_cast<char*>(&req) + NLMSG_ALIGN(req.nh.nlmsg_len));
    a->rta_type = type;
    a->rta_len = (unsigned short)RTA_LENGTH(len);
    if (len > 0) std::memcpy(RTA_DATA(a), data, len);
    req.nh.nlmsg_len = NLMSG_ALIGN(req.nh.nlmsg_len) + RTA_ALIGN(a->rta_len);
    if (parent) parent->rta_len = (unsigned short)(reinterpret_cast<char*>(&req) + req.nh.nlmsg_len - reinterpret_cast<char*>(parent));
    return a;
  };
  rtattr* linkinfo = add(nullptr, IFLA_LINKINFO, nullptr, 0);
  add(linkinfo, IFLA_INFO_KIND, "can", 3);
  rtattr* data = add(linkinfo, IFLA_INFO_DATA, nullptr, 0);
  const uint32_t one = 1;
  add(data, IFLA_CAN_RESTART, &one, sizeof one);
  linkinfo->rta_len = (unsigned short)(reinterpret_cast<char*>(&req) + req.nh.nlmsg_len - reinterpret_cast<char*>(linkinfo));
  sockaddr_nl kernel{};
  kernel.nl_family = AF_NETLINK;
  bool ok = ::sendto(fd, &req, req.nh.nlmsg_len, 0, reinterpret_cast<sockaddr*>(&kernel), sizeof kernel) >= 0;
  if (!ok) *error = std::string("netlink send: ") + std::strerror(errno);
  if (ok) {
    char reply[512];
    pollfd p{fd, POLLIN, 0};
    const ssize_t n = ::poll(&p, 1, 500) > 0 ? ::recv(fd, reply, sizeof reply, 0) : -1;
    const nlmsghdr* h = reinterpret_cast<const nlmsghdr*>(reply);
    if (n < ssize_t(NLMSG_LENGTH(sizeof(nlmsgerr))) || h->nlmsg_type != NLMSG_ERROR) {
      ok = false;
      *error = interface + ": no answer from the kernel to the CAN restart request";
    } else {
      const int code = reinterpret_cast<const nlmsgerr*>(NLMSG_DATA(h))->error;
      ok = code == 0;
      if (!ok) *error = interface + ": CAN restart refused: " + std::strerror(-code);
    }
  }
  ::close(fd);
  return ok;
}

}  // namespace deepnav
