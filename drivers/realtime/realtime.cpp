#include "drivers/realtime/realtime.h"

#include <pthread.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace deepnav {

bool parseCpuList(const std::string& text, cpu_set_t* cpus, std::string* error) {
  CPU_ZERO(cpus);
  const long count = ::sysconf(_SC_NPROCESSORS_CONF);
  const char* p = text.c_str();
  auto fail = [&](const std::string& why) {
    if (error) *error = "'" + text + "' " + why;
    return false;
  };
  while (*p) {
    char* end = nullptr;
    const long first = std::strtol(p, &end, 10);
    if (end == p) return fail("is not a CPU list (e.g. '3' or '0-1,3')");
    long last = first;
    p = end;
    if (*p == '-') {
      last = std::strtol(p + 1, &end, 10);
      if (end == p + 1) return fail("is not a CPU list (e.g. '3' or '0-1,3')");
      p = end;
    }
    if (first < 0 || last < first) return fail("has an empty or negative range");
    if (last >= count || last >= CPU_SETSIZE) {
      return fail("names CPU " + std::to_string(last) + " but this machine has CPUs 0-" + std::to_string(count - 1));
    }
    for (long c = first; c <= last; ++c) CPU_SET(static_cast<int>(c), cpus);
    if (*p == ',') ++p;
    else if (*p) return fail("is not a CPU list (e.g. '3' or '0-1,3')");
  }
  if (CPU_COUNT(cpus) == 0) return fail("names no CPU");
  return true;
}

bool setThreadCpus(const cpu_set_t& cpus, std::string* error) {
  const int rc = ::pthread_setaffinity_np(::pthread_self(), sizeof cpus, &cpus);
  if (rc != 0 && error) *error = std::string("cannot set the CPU affinity: ") + std::strerror(rc);
  return rc == 0;
}

bool setThreadFifo(int priority, std::string* error) {
  sched_param param{};
  param.sched_priority = priority;
  const int rc = ::pthread_setschedparam(::pthread_self(), SCHED_FIFO, &param);
  if (rc != 0 && error) {
    *error = "cannot switch to SCHED_FIFO priority " + std::to_string(priority) + ": " + std::strerror(rc) +
             (rc == EPERM ? " (needs CAP_SYS_NICE or LimitRTPRIO=" + std::to_string(priority) + " in the unit)" : "");
  }
  return rc == 0;
}

void setThreadName(const char* name) {
  char truncated[16] = {};
  std::strncpy(truncated, name, sizeof truncated - 1);
  ::pthread_setname_np(::pthread_self(), truncated);
}

bool lockAllMemory(std::string* error) {
  if (::mlockall(MCL_CURRENT | MCL_FUTURE) == 0) return true;
  const int e = errno;
  if (error) {
    *error = std::string("cannot lock the memory (mlockall): ") + std::strerror(e) +
             (e == EPERM || e == ENOMEM ? " (needs CAP_IPC_LOCK or LimitMEMLOCK=infinity in the unit)" : "");
  }
  return false;
}

}  // namespace deepnav
