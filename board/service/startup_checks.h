#pragma once
#include <sched.h>

#include <string>

namespace deepnav {

// Probes of what `deepnav run` needs at start-up besides its devices, so that `deepnav run --validate`
// refuses what run would refuse. Each returns false with a short reason (the caller names the board key);
// none keeps anything open or changes anything.

// A directory run creates if missing and writes into (service.recording_dir, service.state_dir): it is a
// writable directory, or it does not exist and its nearest existing ancestor is a writable directory.
bool directoryUsable(const std::string& path, std::string* reason);

// A TCP server can listen on address:port (the Modbus output): the address belongs to this host and the
// port is free. Binds a socket the way libmodbus's modbus_tcp_listen() does (SO_REUSEADDR), then closes it.
// *foreign: the failure is that the address is not this host's (EADDRNOTAVAIL).
bool tcpListenable(const std::string& address, int port, std::string* reason, bool* foreign);

// The network interface is a SocketCAN interface and the kernel has CAN sockets (run opens a CAN_RAW
// socket on it). Call after probeCanInterface() (it exists and is up).
bool canInterfaceUsable(const std::string& name, std::string* reason);

// At least one of the CPUs is one this process may run on (sched_setaffinity() refuses a set without any).
bool cpusAvailable(const cpu_set_t& cpus, std::string* reason);

// mlockall(MCL_CURRENT | MCL_FUTURE) can succeed: RLIMIT_MEMLOCK is unlimited or the process has
// CAP_IPC_LOCK (with neither, it fails with EPERM or, past the limit, ENOMEM).
bool memoryLockable(std::string* reason);

// This process may make a thread SCHED_FIFO at the priority (tried on a short-lived thread).
bool fifoPriorityAllowed(int priority, std::string* reason);

}  // namespace deepnav
