// All sensor drivers at once, each in its thread, feeding the nav loop's rings: a PD0 DVL and an Xsens
// AHRS on pty serial lines, NMEA 2000 on a socketpair carrying struct can_frame, a Modbus RTU depth
// sensor on a pty; the consumer side reads the rings as the loop does.
#include <linux/can.h>
#include <pty.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "drivers/sensor_io/sensor_threads.h"
#include "tests/support/fake_modbus_sensor.h"
#include "tests/support/sensor_frames.h"

namespace deepnav {
namespace {

struct Pty {
  int master = -1, slave = -1;
  std::string path;
  Pty() {
    char name[128];
    if (openpty(&master, &slave, name, nullptr, nullptr) == 0) path = name;
  }
  ~Pty() {
    ::close(master);
    ::close(slave);
  }
  void send(const std::vector<uint8_t>& b) {
    for (size_t i = 0; i < b.size(); i += 64) {
      const size_t n = std::min<size_t>(64, b.size() - i);
      if (::write(master, b.data() + i, n) != ssize_t(n)) return;
    }
  }
};

template <typename T>
size_t drainRing(SpscRing<T>* ring, std::vector<T>* out) {
  T s;
  while (ring->tryPop(s)) out->push_back(s);
  return out->size();
}

TEST(SensorThreads, EveryDriverFeedsItsRing) {
  Pty dvl_line, ahrs_line;
  ASSERT_FALSE(dvl_line.path.empty());
  ASSERT_FALSE(ahrs_line.path.empty());
  test::FakeSensor depth_sensor(1);
  ASSERT_FALSE(depth_sensor.path().empty());
  depth_sensor.setPressure(101325.0f + 1025.0f * 9.80665f * 55.0f);
  int can_fds[2];
  ASSERT_EQ(::socketpair(AF_UNIX, SOCK_SEQPACKET, 0, can_fds), 0);

  SensorThreadsConfig config;
  config.dvl = SerialSensorConfig{dvl_line.path, 115200, SerialPort::Parity::kNone, 1, SensorProtocol::kPd0, 1.0};
  config.ahrs = SerialSensorConfig{ahrs_line.path, 921600, SerialPort::Parity::kNone, 1, SensorProtocol::kXsens, 1.0};
  config.can = CanSensorConfig{};
  config.can->interface = "test";
  config.can_socket_fd = can_fds[1];
  config.depth = ModbusDepthConfig{};
  config.depth->device = depth_sensor.path();
  config.depth->baud = 115200;
  config.depth->map.address = 10;
  config.depth_rate_hz = 50;
  // Xsens gives IMU and attitude, so the CAN bus gives only the heading.
  EXPECT_EQ(SensorThreads::canKinds(config), kSampleHeading);

  LiveInputs inputs;
  ASSERT_TRUE(inputs.allocate(LiveInputCapacities{512, 256, 256, 256, 256, 2, 16, 16, 1}));
  SensorThreads threads;
  std::string error;
  ASSERT_TRUE(threads.start(config, &inputs, &error)) << error;

  // The sensors talk.
  std::vector<uint8_t> pd0;
  for (uint16_t i = 1; i <= 20; ++i) {
    test::Pd0Spec spec;
    spec.ensemble = i;
    spec.bt_velocity_mmps[1] = -300;
    const auto e = test::buildPd0(spec);
    pd0.insert(pd0.end(), e.begin(), e.end());
  }
  std::vector<uint8_t> xsens;
  const float q[4] = {1, 0, 0, 0}, acc[3] = {0, 0, 9.81f}, gyr[3] = {0, 0, 0.2f};
  for (uint16_t i = 0; i < 100; ++i) {
    const auto m = test::buildMtData2(i, q, acc, gyr);
    xsens.insert(xsens.end(), m.begin(), m.end());
  }
  std::thread dvl_writer([&] { dvl_line.send(pd0); });
  std::thread ahrs_writer([&] { ahrs_line.send(xsens); });
  for (int i = 0; i < 30; ++i) {
    can_frame heading{};
    heading.can_id = CAN_EFF_FLAG | (2u << 26) | (127250u << 8) | 128;
    heading.can_dlc = 8;
    const uint8_t payload[8] = {uint8_t(i), 0x10, 0x27, 0xFF, 0x7F, 0xFF, 0x7F, 0xFC};
    std::copy(payload, payload + 8, heading.data);
    can_frame attitude = heading;  // forwarded by nobody: the AHRS owns the attitude ring
    attitude.can_id = CAN_EFF_FLAG | (3u << 26) | (127257u << 8) | 128;
    ASSERT_EQ(::write(can_fds[0], &heading, sizeof heading), ssize_t(sizeof heading));
    ASSERT_EQ(::write(can_fds[0], &attitude, sizeof attitude), ssize_t(sizeof attitude));
  }
  dvl_writer.join();
  ahrs_writer.join();

  // The loop's side.
  std::vector<DvlSample> dvl;
  std::vector<ImuSample> imu;
  std::vector<AttitudeSample> attitude;
  std::vector<HeadingSample> heading;
  std::vector<DepthSample> depth;
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (std::chrono::steady_clock::now() < until) {
    drainRing(&inputs.ring<DvlSample>(), &dvl);
    drainRing(&inputs.ring<ImuSample>(), &imu);
    drainRing(&inputs.ring<AttitudeSample>(), &attitude);
    drainRing(&inputs.ring<HeadingSample>(), &heading);
    drainRing(&inputs.ring<DepthSample>(), &depth);
    if (dvl.size() == 20 && imu.size() == 100 && heading.size() == 30 && depth.size() >= 5) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  threads.stop();
  ::close(can_fds[0]);
  EXPECT_EQ(dvl.size(), 20u);
  EXPECT_EQ(imu.size(), 100u);
  EXPECT_EQ(attitude.size(), 100u);  // from the AHRS only
  EXPECT_EQ(heading.size(), 30u);
  EXPECT_GE(depth.size(), 5u);
  ASSERT_FALSE(dvl.empty());
  EXPECT_NEAR(dvl.back().v_dvl_mps.x(), 0.3, 1e-12);
  ASSERT_FALSE(depth.empty());
  EXPECT_NEAR(depth.back().depth_m, 55.0, 1e-3);
  const SensorThreads::Status status = threads.status();
  EXPECT_EQ(status.dvl.frames, 20u);
  EXPECT_EQ(status.ahrs.bad_frames, 0u);
  EXPECT_EQ(status.can.frames, 60u);
  EXPECT_EQ(status.depth_failures, 0u);
}

TEST(SensorThreads, MissingDeviceFailsStartWithItsName) {
  SensorThreadsConfig config;
  config.ahrs = SerialSensorConfig{"/dev/no-ahrs", 115200, SerialPort::Parity::kNone, 1, SensorProtocol::kXsens, 1.0};
  LiveInputs inputs;
  ASSERT_TRUE(inputs.allocate(LiveInputCapacities{16, 16, 16, 16, 16, 2, 16, 16, 1}));
  SensorThreads threads;
  std::string error;
  EXPECT_FALSE(threads.start(config, &inputs, &error));
  EXPECT_NE(error.find("AHRS: /dev/no-ahrs"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav
