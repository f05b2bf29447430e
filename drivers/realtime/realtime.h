#pragma once
#include <sched.h>

#include <string>

namespace deepnav {

// Real-time hygiene of the service (board keys realtime.*). Each call acts on the calling thread (Linux
// affinity and scheduling policy are per thread, and threads inherit them when created), and fails with a
// message that says what the process lacks.

// Parses a CPU list such as "3" or "0-1,3" against the CPUs this machine has.
bool parseCpuList(const std::string& text, cpu_set_t* cpus, std::string* error);

bool setThreadCpus(const cpu_set_t& cpus, std::string* error);
// SCHED_FIFO at the given priority (1..99).
bool setThreadFifo(int priority, std::string* error);
// Names the calling thread (top -H, ps -L, gdb); at most 15 characters are kept.
void setThreadName(const char* name);
// mlockall(MCL_CURRENT | MCL_FUTURE): no page fault will ever stall the loop.
bool lockAllMemory(std::string* error);

}  // namespace deepnav
