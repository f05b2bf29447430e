// `deepnav run` starts only on a valid board: every failure exits with code 2 and one message naming
// the key and the device or file; the shipped example vehicle fails on its first device, which is not
// here. Devices that are here pass: a pty as a serial port, Aravis's fake GigE Vision camera.
#include <pty.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "drivers/camera/gvcp_probe.h"
#include "tests/support/sensor_frames.h"
#include "tests/support/service_fixture.h"
#include "tests/support/test_dive.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

struct Outcome {
  int code;
  std::string err;
};

Outcome runDeepnav(const std::vector<std::string>& args) {
  testing::DeepnavProcess p(args);
  const int code = p.wait(20.0);
  return {code, p.stderrText()};
}

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

TEST(ServiceValidation, ExampleVehicleFailsNamingItsFirstMissingDevice) {
  const std::string board = deepnav::testing::sourceDir() + "/board/example-vehicle/board.yaml";
  for (const bool validate_only : {true, false}) {
    std::vector<std::string> args = {"run", "--board", board};
    if (validate_only) args.push_back("--validate");
    const Outcome o = runDeepnav(args);
    EXPECT_EQ(o.code, 2) << o.err;
    EXPECT_TRUE(has(o.err, "board/example-vehicle/board.yaml: camera.left: left camera 192.168.10.11 is not "
                           "reachable")) << o.err;
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << "one message: " << o.err;
  }
}

TEST(ServiceValidation, EachBadKeyIsNamed) {
  const std::string dive = testing::makeTestDive("validation_dive", 2.0, 7, false);
  const std::string missing = testing::tempPath("no_such_dive.mcap");
  const struct {
    std::map<std::string, std::string> settings;
    std::string expected;
  } cases[] = {
      {{{"sources.replay_path", missing}}, "sources.replay_path: recording " + missing + " not found; make one with "
                                           "build/bin/deepnav-sim"},
      {{{"sources.replay_path", "''"}}, "sources.replay_path: is empty and no device is listed"},
      {{{"sources.dvl_serial", "/dev/null"}}, "sources.dvl_serial: DVL serial port /dev/null is not reachable: is not "
                                              "a serial port"},
      {{{"sources.can_interface", "can7"}}, "sources.can_interface: CAN interface can7 is not reachable: no such "
                                            "network interface"},
      {{{"outputs.udp_destinations", "topside:5600"}}, "outputs.udp_destinations: 'topside:5600' is not an IPv4"},
      {{{"outputs.modbus_enabled", "true"}, {"outputs.modbus_address", "plc"}}, "outputs.modbus_address: 'plc'"},
      {{{"realtime.loop_cpus", "4096"}}, "realtime.loop_cpus: '4096' names CPU 4096"},
      {{{"camera.cx_px", "700"}}, "camera.cx_px: principal point outside the image width"},
      {{{"markers.panel_file", "no_panel.yaml"}}, "markers.panel_file"},
      {{{"loop.rate_hz", "5"}}, "key 'loop.rate_hz' is 5, out of range"},
  };
  for (const auto& c : cases) {
    const std::string board = testing::makeServiceBoard("bad_board", dive, c.settings);
    const Outcome o = runDeepnav({"run", "--board", board, "--no-record"});
    EXPECT_EQ(o.code, 2) << c.expected << "\n" << o.err;
    EXPECT_TRUE(has(o.err, c.expected)) << "expected: " << c.expected << "\ngot: " << o.err;
  }
}

TEST(ServiceValidation, BusyModbusPortIsNamed) {
  const std::string dive = testing::makeTestDive("busy_dive", 2.0, 7, false);
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
  ::listen(fd, 1);
  socklen_t len = sizeof a;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
  const std::string board = testing::makeServiceBoard(
      "busy_board", dive,
      {{"outputs.modbus_enabled", "true"}, {"outputs.modbus_address", "127.0.0.1"},
       {"outputs.modbus_port", std::to_string(ntohs(a.sin_port))}});
  const Outcome o = runDeepnav({"run", "--board", board, "--no-record"});
  ::close(fd);
  EXPECT_EQ(o.code, 2) << o.err;
  EXPECT_TRUE(has(o.err, "outputs.modbus_port: Modbus TCP server on 127.0.0.1:")) << o.err;
}

TEST(ServiceValidation, ReachableDevicesPass) {
  // GIVEN a pty as the DVL's serial port and Aravis's fake GigE Vision camera on loopback
  int master = -1, slave = -1;
  char name[256];
  ASSERT_EQ(::openpty(&master, &slave, name, nullptr, nullptr), 0);
  std::map<std::string, std::string> settings = {{"sources.replay_path", "''"}, {"sources.dvl_serial", name}};
  pid_t camera = -1;
  if (::access("/usr/bin/arv-fake-gv-camera-0.8", X_OK) == 0) {
    char arg0[] = "arv-fake-gv-camera-0.8", arg1[] = "-i", arg2[] = "127.0.0.1";
    char* argv[] = {arg0, arg1, arg2, nullptr};
    ASSERT_EQ(posix_spawn(&camera, "/usr/bin/arv-fake-gv-camera-0.8", nullptr, nullptr, argv, environ), 0);
    for (int i = 0; i < 100 && !gvcpDeviceAnswers("127.0.0.1", 50); ++i) {
    }  // until it serves GVCP (at most 5 s)
    settings["camera.driver"] = "aravis";
    settings["camera.left"] = "127.0.0.1";
    settings["camera.right"] = "127.0.0.1";
  }
  const std::string board = testing::makeServiceBoard("devices_board", "", settings);
  // WHEN the board is validated
  const Outcome o = runDeepnav({"run", "--board", board, "--validate"});
  if (camera > 0) {
    ::kill(camera, SIGTERM);
    ::waitpid(camera, nullptr, 0);
  }
  ::close(master);
  ::close(slave);
  // THEN it is valid
  EXPECT_EQ(o.code, 0) << o.err;
  if (camera <= 0) GTEST_SKIP() << "arv-fake-gv-camera-0.8 not installed: the GigE probe was not exercised";
}

// Issue 21: `run --validate` performs every start-up check `run` performs short of opening the devices, so
// a board it calls valid is one run starts with. Each case used to validate and then be refused by run (or,
// for the dense range, abort it in OpenCV); now both refuse it with the same message.
TEST(ServiceValidation, ValidateRefusesWhatRunRefuses) {
  const std::string dive = testing::makeTestDive("validate_like_run_dive", 2.0, 7, false);
  const std::string a_file = testing::tempPath("not_a_directory");
  std::ofstream(a_file) << "x";
  const struct {
    std::map<std::string, std::string> settings;
    std::string expected;
  } cases[] = {
      {{{"outputs.modbus_enabled", "true"}, {"outputs.modbus_address", "192.0.2.7"}},
       "outputs.modbus_address: Modbus TCP server on 192.0.2.7:1502: cannot listen: Cannot assign requested address "
       "(not an address of this host)"},
      {{{"service.recording_dir", a_file}}, "service.recording_dir: " + a_file + " exists and is not a directory"},
      {{{"service.recording_dir", a_file + "/run"}},
       "service.recording_dir: " + a_file + "/run cannot be created: " + a_file + " is not a directory"},
      {{{"service.state_dir", a_file}}, "service.state_dir: " + a_file + " exists and is not a directory"},
      {{{"sources.replay_path", "''"}, {"sources.can_interface", "lo"}},
       "sources.can_interface: CAN interface lo cannot be used: is not a CAN interface (link type 772, loopback"},
      {{{"sources.replay_path", "''"}, {"sources.can_interface", "lo"}, {"can.imu_mapping", "'garbage;;;'"}},
       "can.imu_mapping entry 1 'garbage': identifier is not hex"},
      {{{"camera.rate_hz", "0.3"}}, "camera.rate_hz: 0.300000 Hz: the vision task runs at the rate rounded to whole "
                                    "hertz, here 0"},
      {{{"camera.width_px", "512"}, {"camera.height_px", "384"}, {"camera.cx_px", "255.5"}, {"camera.cy_px", "191.5"},
        {"vision.dense_method", "sgbm"}, {"vision.dense_disparities", "256"}},
       "key 'vision.dense_disparities' (256) does not fit 'camera.width_px' (512 px"},
  };
  for (const auto& c : cases) {
    const std::string board = testing::makeServiceBoard("validate_like_run", dive, c.settings);
    for (const bool validate_only : {true, false}) {
      std::vector<std::string> args = {"run", "--board", board};
      args.push_back(validate_only ? "--validate" : "--no-record");
      const Outcome o = runDeepnav(args);
      EXPECT_EQ(o.code, 2) << (validate_only ? "--validate: " : "run: ") << c.expected << "\n" << o.err;
      EXPECT_TRUE(has(o.err, board + ": " + c.expected)) << "expected: " << c.expected << "\ngot: " << o.err;
    }
  }
  std::remove(a_file.c_str());
}

// Issue 21: the board file itself: a directory, an endless device, a repeated section are refused by name.
TEST(ServiceValidation, BoardFileThatYamlAcceptsSilentlyIsRefused) {
  const std::string dive = testing::makeTestDive("validate_board_file_dive", 2.0, 7, false);
  const std::string board = testing::makeServiceBoard("repeated_section", dive);
  std::ofstream(board, std::ios::app) << "loop:\n  rate_hz: 50\n";
  const std::string dir = testing::tempPath("board_dir");
  std::filesystem::create_directories(dir);
  const struct {
    std::string path, expected;
  } cases[] = {
      {board, board + ": line "},
      {dir, dir + ": is a directory, not the board file"},
      {"/dev/zero", "/dev/zero: the board file is larger than 4 MiB"},
  };
  for (const auto& c : cases) {
    const auto t0 = std::chrono::steady_clock::now();
    const Outcome o = runDeepnav({"run", "--board", c.path, "--validate"});
    EXPECT_EQ(o.code, 2) << o.err;
    EXPECT_TRUE(has(o.err, c.expected)) << "expected: " << c.expected << "\ngot: " << o.err;
    EXPECT_LT(testing::secondsSince(t0), 10.0) << c.path;
  }
  const Outcome o = runDeepnav({"run", "--board", board, "--validate"});
  EXPECT_TRUE(has(o.err, "key 'loop' repeats the one of line")) << o.err;
}

TEST(ServiceLive, ADvlOnASerialLineFeedsTheLiveLoop) {
  // GIVEN a board whose DVL is a serial line (a pty here) and no replay
  int master = -1, slave = -1;
  char name[256];
  ASSERT_EQ(::openpty(&master, &slave, name, nullptr, nullptr), 0);
  const std::string board = testing::makeServiceBoard(
      "live_dvl_board", "", {{"sources.replay_path", "''"}, {"sources.dvl_serial", name}, {"serial.dvl_protocol", "pd0"}});
  // WHEN deepnav runs on it for 3 s while the DVL sends PD0 bottom-track ensembles at 5 Hz
  std::atomic<bool> sending{true};
  std::thread dvl([&] {
    for (std::uint16_t n = 1; sending.load(); ++n) {
      test::Pd0Spec spec;
      spec.ensemble = n;
      spec.bt_velocity_mmps[0] = 100;
      const std::vector<std::uint8_t> bytes = test::buildPd0(spec);
      if (::write(master, bytes.data(), bytes.size()) < 0) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
  });
  const Outcome r = runDeepnav({"run", "--board", board, "--no-record", "--duration", "3"});
  sending.store(false);
  dvl.join();
  ::close(master);
  ::close(slave);
  // THEN the service ran on its live sources and the loop consumed the DVL's samples
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.err, "sources live devices")) << r.err;
  const std::size_t last = r.err.find("; last: ");  // the final status line: "dvl ok (N)"
  ASSERT_NE(last, std::string::npos) << r.err;
  const std::size_t at = r.err.find("dvl ", last);
  ASSERT_NE(at, std::string::npos) << r.err;
  const std::size_t open = r.err.find('(', at);
  ASSERT_NE(open, std::string::npos) << r.err;
  EXPECT_GT(std::stoll(r.err.substr(open + 1)), 5) << r.err;
  // AND the DVL driver's own counters reach the journal at stop
  const std::string drivers = "sensor drivers at stop: dvl ";
  const std::size_t d = r.err.find(drivers);
  ASSERT_NE(d, std::string::npos) << r.err;
  EXPECT_GT(std::stoll(r.err.substr(d + drivers.size())), 5) << r.err;
  EXPECT_TRUE(has(r.err.substr(d), "0 reopens")) << r.err;
}

}  // namespace
}  // namespace deepnav
