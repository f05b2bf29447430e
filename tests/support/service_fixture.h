#pragma once
// Helpers of the service tests (tests/integration/service_*.cpp): a board for `deepnav run` around a
// test dive, free loopback ports, a child `deepnav` process, and a NOTIFY_SOCKET receiver that plays
// systemd's side of the notify protocol.
#include <netinet/in.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "tests/support/temp_path.h"
#include "tests/support/source_paths.h"

extern char** environ;

namespace deepnav::testing {

// board/sim/board.yaml with the panel file made absolute, the replay set to `dive`, outputs off unless
// set, and every `settings` entry ("group.key" -> YAML scalar) applied. Returns the new file's path.
inline std::string makeServiceBoard(const std::string& name, const std::string& dive,
                                    const std::map<std::string, std::string>& settings = {}) {
  const std::string sim = deepnav::testing::sourceDir() + "/board/sim/";
  YAML::Node board = YAML::LoadFile(sim + "board.yaml");
  board["markers"]["panel_file"] = sim + "panel.yaml";
  board["sources"]["replay_path"] = dive;
  board["outputs"]["modbus_enabled"] = false;
  board["outputs"]["udp_destinations"] = "";
  board["service"]["recording_dir"] = "";
  for (const auto& [key, value] : settings) {
    const auto dot = key.find('.');
    board[key.substr(0, dot)][key.substr(dot + 1)] = YAML::Load(value);
  }
  const std::string path = tempPath(name + ".yaml");
  YAML::Emitter out;
  out << board;
  std::ofstream(path) << out.c_str() << "\n";
  return path;
}

// A loopback port nobody listens on right now (bound once, then released).
inline int freePort(int type) {
  const int fd = ::socket(AF_INET, type, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a);
  socklen_t len = sizeof a;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
  ::close(fd);
  return ntohs(a.sin_port);
}

inline double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// `deepnav ARGS...` as a child process with extra environment variables; stderr goes to a file.
class DeepnavProcess {
 public:
  DeepnavProcess(const std::vector<std::string>& args, const std::map<std::string, std::string>& env = {}) {
    stderr_path_ = tempPath("stderr_" + std::to_string(counter()++) + ".txt");
    std::vector<std::string> argv_s = {deepnav::testing::binDir() + "/deepnav"};
    argv_s.insert(argv_s.end(), args.begin(), args.end());
    std::vector<std::string> env_s;
    for (char** e = environ; *e; ++e) {
      const std::string kv = *e;
      const std::string key = kv.substr(0, kv.find('='));
      if (!env.count(key) && key != "NOTIFY_SOCKET" && key != "WATCHDOG_USEC" && key != "WATCHDOG_PID") {
        env_s.push_back(kv);
      }
    }
    for (const auto& [k, v] : env) env_s.push_back(k + "=" + v);
    std::vector<char*> argv, envp;
    for (auto& s : argv_s) argv.push_back(s.data());
    for (auto& s : env_s) envp.push_back(s.data());
    argv.push_back(nullptr);
    envp.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 2, stderr_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    EXPECT_EQ(posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), envp.data()), 0);
    posix_spawn_file_actions_destroy(&actions);
  }
  ~DeepnavProcess() {
    if (pid_ > 0 && !exited_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  pid_t pid() const { return pid_; }
  void signal(int sig) { ::kill(pid_, sig); }
  // Exit code, or -1 when it did not exit within timeout_s (or died by a signal).
  int wait(double timeout_s) {
    const auto t0 = std::chrono::steady_clock::now();
    while (secondsSince(t0) < timeout_s) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        exited_ = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      ::usleep(5000);
    }
    return -1;
  }
  std::string stderrText() const {
    std::ifstream in(stderr_path_);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

 private:
  static int& counter() {
    static int n = 0;
    return n;
  }
  pid_t pid_ = -1;
  bool exited_ = false;
  std::string stderr_path_;
};

// systemd's side of the notify protocol: an AF_UNIX datagram socket whose path goes in NOTIFY_SOCKET.
class NotifyReceiver {
 public:
  struct Message {
    double t_s;  // since the receiver was created
    std::string text;
  };
  NotifyReceiver() {
    path_ = tempPath("notify.sock");
    ::unlink(path_.c_str());
    fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    sockaddr_un a{};
    a.sun_family = AF_UNIX;
    std::strncpy(a.sun_path, path_.c_str(), sizeof a.sun_path - 1);
    EXPECT_EQ(::bind(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a), 0) << path_;
    t0_ = std::chrono::steady_clock::now();
  }
  ~NotifyReceiver() {
    ::close(fd_);
    ::unlink(path_.c_str());
  }
  const std::string& path() const { return path_; }
  double now() const { return secondsSince(t0_); }
  // Receives for up to timeout_s; stops early at the first message containing `until` (if given).
  std::vector<Message> receive(double timeout_s, const std::string& until = "") {
    std::vector<Message> out;
    const auto start = std::chrono::steady_clock::now();
    while (secondsSince(start) < timeout_s) {
      pollfd p{fd_, POLLIN, 0};
      const int wait_ms = static_cast<int>((timeout_s - secondsSince(start)) * 1000) + 1;
      if (::poll(&p, 1, wait_ms) != 1) continue;
      char buf[4096];
      const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
      if (n <= 0) continue;
      out.push_back({secondsSince(t0_), std::string(buf, static_cast<std::size_t>(n))});
      if (!until.empty() && out.back().text.find(until) != std::string::npos) break;
    }
    return out;
  }

 private:
  std::string path_;
  int fd_ = -1;
  std::chrono::steady_clock::time_point t0_;
};

inline bool hasLine(const std::string& text, const std::string& line) {
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) {
    if (l == line) return true;
  }
  return false;
}

}  // namespace deepnav::testing
