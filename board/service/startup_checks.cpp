#include "board/service/startup_checks.h"

#include <arpa/inet.h>
#include <linux/can.h>
#include <net/if.h>
#include <net/if_arp.h>
#include <netinet/in.h>
#include <pthread.h>
#include <sys/ioctl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

namespace deepnav {
namespace {

namespace fs = std::filesystem;

class Socket {
 public:
  explicit Socket(int fd) : fd_(fd) {}
  ~Socket() {
    if (fd_ >= 0) ::close(fd_);
  }
  Socket(const Socket&) = delete;
  Socket& operator=(const Socket&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

}  // namespace

bool directoryUsable(const std::string& path, std::string* reason) {
  std::error_code ec;
  fs::path p = path;
  if (fs::exists(p, ec) && !fs::is_directory(p, ec)) {
    *reason = path + " exists and is not a directory";
    return false;
  }
  // The directories run would create: the nearest existing ancestor must take them.
  while (!p.empty() && !fs::exists(p, ec)) p = p.parent_path();
  const fs::path existing = p.empty() ? fs::path(".") : p;
  if (!fs::is_directory(existing, ec)) {
    *reason = path + " cannot be created: " + existing.string() + " is not a directory";
    return false;
  }
  if (::access(existing.c_str(), W_OK | X_OK) != 0) {
    *reason = path + (existing == fs::path(path) ? " is not writable" : " cannot be created in " + existing.string()) +
              ": " + std::strerror(errno);
    return false;
  }
  return true;
}

bool tcpListenable(const std::string& address, int port, std::string* reason, bool* foreign) {
  *foreign = false;
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  if (::inet_pton(AF_INET, address.c_str(), &a.sin_addr) != 1) {
    *reason = "'" + address + "' is not an IPv4 address";
    return false;
  }
  Socket s(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0));
  const int on = 1;
  if (s.get() < 0 || ::setsockopt(s.get(), SOL_SOCKET, SO_REUSEADDR, &on, sizeof on) != 0) {
    *reason = std::string("cannot create a TCP socket: ") + std::strerror(errno);
    return false;
  }
  if (::bind(s.get(), reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0) {
    const int e = errno;
    *foreign = e == EADDRNOTAVAIL;
    *reason = std::string("cannot listen: ") + std::strerror(e) +
              (e == EADDRNOTAVAIL ? " (not an address of this host)"
               : e == EADDRINUSE  ? " (another program, or a running deepnav, listens there)"
               : e == EACCES      ? " (ports below 1024 need CAP_NET_BIND_SERVICE)"
                                  : "");
    return false;
  }
  return true;
}

bool canInterfaceUsable(const std::string& name, std::string* reason) {
  Socket s(::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0));
  ifreq ifr{};
  std::strncpy(ifr.ifr_name, name.c_str(), IFNAMSIZ - 1);
  if (s.get() < 0 || ::ioctl(s.get(), SIOCGIFHWADDR, &ifr) != 0) {
    *reason = std::string("cannot read the interface type: ") + std::strerror(errno);
    return false;
  }
  if (ifr.ifr_hwaddr.sa_family != ARPHRD_CAN) {
    *reason = std::string("is not a CAN interface (link type ") + std::to_string(ifr.ifr_hwaddr.sa_family) +
              (ifr.ifr_hwaddr.sa_family == ARPHRD_LOOPBACK ? ", loopback"
               : ifr.ifr_hwaddr.sa_family == ARPHRD_ETHER  ? ", Ethernet"
                                                           : "") +
              "; a SocketCAN interface has link type " + std::to_string(ARPHRD_CAN) + ")";
    return false;
  }
  {
    Socket can(::socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC, CAN_RAW));
    if (can.get() < 0) {
      *reason = std::string("this kernel has no CAN sockets: ") + std::strerror(errno) + " (modprobe can_raw)";
      return false;
    }
  }
  return true;
}

bool cpusAvailable(const cpu_set_t& cpus, std::string* reason) {
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (::sched_getaffinity(0, sizeof allowed, &allowed) != 0) return true;  // unknown: leave it to run
  cpu_set_t both;
  CPU_AND(&both, &cpus, &allowed);
  if (CPU_COUNT(&both) > 0) return true;
  std::string list;
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
    if (!CPU_ISSET(cpu, &allowed)) continue;
    if (!list.empty()) list += ',';
    list += std::to_string(cpu);
  }
  *reason = "none of these CPUs is available to this process (it may use " + list + ")";
  return false;
}

bool memoryLockable(std::string* reason) {
  rlimit limit{};
  if (::getrlimit(RLIMIT_MEMLOCK, &limit) == 0 && limit.rlim_cur == RLIM_INFINITY) return true;
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("CapEff:", 0) != 0) continue;
    constexpr unsigned kCapIpcLock = 14;  // linux/capability.h
    if ((std::stoull(line.substr(7), nullptr, 16) >> kCapIpcLock) & 1u) return true;
  }
  *reason = std::string("cannot lock the memory (mlockall): the memory lock limit is ") +
            std::to_string(limit.rlim_cur / 1024) +
            " KiB and the process lacks CAP_IPC_LOCK (LimitMEMLOCK=infinity or AmbientCapabilities=CAP_IPC_LOCK "
            "in the unit)";
  return false;
}

bool fifoPriorityAllowed(int priority, std::string* reason) {
  int rc = 0;
  std::thread probe([&] {
    sched_param param{};
    param.sched_priority = priority;
    rc = ::pthread_setschedparam(::pthread_self(), SCHED_FIFO, &param);
  });
  probe.join();
  if (rc == 0) return true;
  *reason = std::string("cannot switch a thread to SCHED_FIFO priority ") + std::to_string(priority) + ": " + std::strerror(rc) +
            (rc == EPERM ? " (needs CAP_SYS_NICE or LimitRTPRIO=" + std::to_string(priority) + " in the unit)" : "");
  return false;
}

}  // namespace deepnav
