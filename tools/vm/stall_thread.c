// stall-thread PID NAME SECONDS: stops one thread of a running process (the first whose
// /proc/PID/task/TID/comm is NAME) for SECONDS while every other thread keeps running, as a hung
// nav loop would. SIGSTOP cannot do that (it stops the whole thread group); a ptrace stop is per
// thread: PTRACE_SEIZE then PTRACE_INTERRUPT puts only that thread in a ptrace-stop, and the thread
// resumes when this program detaches or exits. Used by tools/vm/run-systemd-test.sh to stall deepnav's
// nav thread under systemd's watchdog. Exit code 0 once the thread was stopped and the time is up (or
// the process died meanwhile), 1 when the thread was not found or could not be stopped.
#define _GNU_SOURCE
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ptrace.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static pid_t find_thread(pid_t pid, const char* name) {
  char dir_path[64];
  snprintf(dir_path, sizeof dir_path, "/proc/%d/task", (int)pid);
  DIR* dir = opendir(dir_path);
  if (dir == NULL) return -1;
  pid_t found = -1;
  for (struct dirent* e = readdir(dir); e != NULL && found < 0; e = readdir(dir)) {
    if (e->d_name[0] < '0' || e->d_name[0] > '9') continue;
    char comm_path[384], comm[64] = {0};
    snprintf(comm_path, sizeof comm_path, "%s/%s/comm", dir_path, e->d_name);
    FILE* f = fopen(comm_path, "r");
    if (f == NULL) continue;
    if (fgets(comm, sizeof comm, f) != NULL) {
      comm[strcspn(comm, "\n")] = '\0';
      if (strcmp(comm, name) == 0) found = (pid_t)atoi(e->d_name);
    }
    fclose(f);
  }
  closedir(dir);
  return found;
}

int main(int argc, char** argv) {
  if (argc != 4) {
    fprintf(stderr, "usage: stall-thread PID THREAD_NAME SECONDS\n");
    return 2;
  }
  const pid_t pid = (pid_t)atoi(argv[1]);
  const double seconds = atof(argv[3]);
  const pid_t tid = find_thread(pid, argv[2]);
  if (tid < 0) {
    fprintf(stderr, "stall-thread: no thread '%s' in process %d\n", argv[2], (int)pid);
    return 1;
  }
  if (ptrace(PTRACE_SEIZE, tid, NULL, NULL) != 0 || ptrace(PTRACE_INTERRUPT, tid, NULL, NULL) != 0) {
    fprintf(stderr, "stall-thread: cannot stop thread %d: %s\n", (int)tid, strerror(errno));
    return 1;
  }
  int status = 0;
  if (waitpid(tid, &status, __WALL) != tid) {
    fprintf(stderr, "stall-thread: thread %d did not stop: %s\n", (int)tid, strerror(errno));
    return 1;
  }
  printf("stall-thread: thread %d (%s) of process %d stopped for %.1f s\n", (int)tid, argv[2], (int)pid, seconds);
  fflush(stdout);
  // Hold the stop; a signal that kills the process ends the wait early (the tracee's exit is reported).
  struct timespec end;
  clock_gettime(CLOCK_MONOTONIC, &end);
  end.tv_sec += (time_t)seconds;
  for (;;) {
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    if (now.tv_sec > end.tv_sec || (now.tv_sec == end.tv_sec && now.tv_nsec >= end.tv_nsec)) break;
    const pid_t r = waitpid(tid, &status, __WALL | WNOHANG);
    if (r == tid && (WIFEXITED(status) || WIFSIGNALED(status))) return 0;
    // Any other stop (a signal for the thread, a group stop) is left pending: the thread stays stopped.
    usleep(20000);
  }
  ptrace(PTRACE_DETACH, tid, NULL, NULL);
  return 0;
}
