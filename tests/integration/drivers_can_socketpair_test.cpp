// The CAN sensor driver's socket code through a socketpair carrying struct can_frame (this machine's
// kernel has no vcan): the real NMEA 2000 capture in, heading and attitude samples out; error frames
// drive the bus state (warning, passive, bus-off, restarted).
#include <linux/can.h>
#include <linux/can/error.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "drivers/can/can_sensor_driver.h"
#include "drivers/parsers/candump_line.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

struct Collect : SampleSink {
  std::vector<HeadingSample> heading;
  std::vector<AttitudeSample> attitude;
  std::vector<ImuSample> imu;
  bool onHeading(const HeadingSample& s) override { return heading.push_back(s), true; }
  bool onAttitude(const AttitudeSample& s) override { return attitude.push_back(s), true; }
  bool onImu(const ImuSample& s) override { return imu.push_back(s), true; }
};

class Pair {
 public:
  Pair() { ok_ = ::socketpair(AF_UNIX, SOCK_SEQPACKET, 0, fds_) == 0; }
  ~Pair() {
    if (fds_[0] >= 0) ::close(fds_[0]);
  }
  bool ok() const { return ok_; }
  int driverEnd() {  // ownership goes to the driver
    const int fd = fds_[1];
    fds_[1] = -1;
    return fd;
  }
  void send(const can_frame& f) { ASSERT_EQ(::write(fds_[0], &f, sizeof f), ssize_t(sizeof f)); }
  void send(const CanFrame& f) {
    can_frame k{};
    k.can_id = f.id | (f.extended ? CAN_EFF_FLAG : 0);
    k.can_dlc = f.dlc;
    std::copy(f.data.begin(), f.data.end(), k.data);
    send(k);
  }
  void sendError(uint32_t classes, uint8_t ctrl = 0, uint8_t tx = 0, uint8_t rx = 0) {
    can_frame k{};
    k.can_id = CAN_ERR_FLAG | classes;
    k.can_dlc = CAN_ERR_DLC;
    k.data[1] = ctrl;
    k.data[6] = tx;
    k.data[7] = rx;
    send(k);
  }
  void closeWriter() {
    ::close(fds_[0]);
    fds_[0] = -1;
  }

 private:
  int fds_[2] = {-1, -1};
  bool ok_ = false;
};

// Polls until the writer has closed its end and every frame is read (the read then fails).
void drain(CanSensorDriver* d, Collect* sink) {
  for (int i = 0; i < 100000 && d->poll(100, sink); ++i) {
  }
}

// The driver on one end of a socket pair, the test writing frames into the other; a test sets `config` then
// calls start().
class CanSocketpair : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(pair.ok());
    config.interface = "test";
  }
  void start() { ASSERT_TRUE(driver.initOnSocket(config, pair.driverEnd(), &error)) << error; }

  Pair pair;
  CanSensorDriver driver;
  CanSensorConfig config;
  std::string error;
};

TEST_F(CanSocketpair, Nmea2000CaptureGivesHeadingAndAttitude) {
  const auto file = deepnav::testing::sharedDataDir() / "can" / "candumpSample2.txt";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " absent";
  config.heading_source = 128;
  ASSERT_NO_FATAL_FAILURE(start());
  std::vector<CanFrame> frames;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    CanFrame f;
    double t = 0;
    const char* why = "";
    if (parseCandumpLine(line, &f, &t, &why) == CandumpLine::kFrame) frames.push_back(f);
  }
  // The writer runs beside the driver: a socket buffer holds only a few hundred frames.
  std::thread writer([&] {
    for (const CanFrame& f : frames) pair.send(f);
    pair.closeWriter();  // the driver reads to the end, then sees the socket fail
  });
  Collect sink;
  drain(&driver, &sink);
  writer.join();
  EXPECT_EQ(driver.counters().frames, frames.size());
  EXPECT_EQ(sink.heading.size(), 46u);
  EXPECT_EQ(sink.attitude.size(), 5u);
  EXPECT_NEAR(sink.heading.front().heading_rad, 3.9324, 1e-12);  // magnetic, no deviation given
  EXPECT_FALSE(sink.heading.front().is_true);
  EXPECT_NEAR(sink.attitude.front().pitch_rad, -0.0159, 1e-12);
  EXPECT_NEAR(sink.attitude.front().roll_rad, 0.0007, 1e-12);
}

TEST_F(CanSocketpair, HeadingFromAnotherSourceIsIgnored) {
  config.heading_source = 5;
  ASSERT_NO_FATAL_FAILURE(start());
  CanFrame f;
  f.extended = true;
  f.id = (2u << 26) | (127250u << 8) | 128;  // source 128, not 5
  f.dlc = 8;
  f.data = {0, 0x10, 0x27, 0xFF, 0x7F, 0xFF, 0x7F, 0xFC};
  pair.send(f);
  f.id = (f.id & ~0xFFu) | 5;
  pair.send(f);
  pair.closeWriter();
  Collect sink;
  drain(&driver, &sink);
  ASSERT_EQ(sink.heading.size(), 1u);
  EXPECT_TRUE(sink.heading[0].is_true);
  EXPECT_NEAR(sink.heading[0].heading_rad, 1.0, 1e-12);
}

TEST_F(CanSocketpair, MappedImuFrames) {
  config.imu_mapping =
      "0x0CF02A80:0:i16le:0.001:gyro_x;0x0CF02A80:2:i16le:0.001:gyro_y;0x0CF02A80:4:i16le:0.001:gyro_z;"
      "0x08F02D80:0:i16le:0.01:accel_x;0x08F02D80:2:i16le:0.01:accel_y;0x08F02D80:4:i16le:0.01:accel_z";
  ASSERT_NO_FATAL_FAILURE(start());
  for (int i = 0; i < 10; ++i) {
    CanFrame g;
    g.extended = true, g.id = 0x0CF02A80, g.dlc = 8;
    g.data = {uint8_t(i), 0, 0, 0, 0, 0, 0, 0};
    CanFrame a = g;
    a.id = 0x08F02D80;
    a.data = {0, 0, 0, 0, 0xD4, 0x03, 0, 0};  // z = 980 -> 9.8
    pair.send(g);
    pair.send(a);
  }
  pair.closeWriter();
  Collect sink;
  drain(&driver, &sink);
  ASSERT_EQ(sink.imu.size(), 10u);
  EXPECT_NEAR(sink.imu[9].w_imu_radps.x(), 0.009, 1e-12);
  EXPECT_NEAR(sink.imu[9].f_imu_mps2.z(), 9.8, 1e-12);
}

TEST_F(CanSocketpair, ErrorFramesDriveTheBusState) {
  config.bus_off_recovery_s = 0.05;
  ASSERT_NO_FATAL_FAILURE(start());
  Collect sink;
  pair.sendError(CAN_ERR_CRTL | CAN_ERR_CNT, CAN_ERR_CRTL_TX_WARNING, 97, 3);
  ASSERT_TRUE(driver.poll(100, &sink));
  EXPECT_EQ(driver.bus().state(), CanBusMonitor::State::kWarning);
  EXPECT_EQ(driver.bus().txErrors(), 97);
  EXPECT_EQ(driver.bus().rxErrors(), 3);
  pair.sendError(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_PASSIVE);
  ASSERT_TRUE(driver.poll(100, &sink));
  EXPECT_EQ(driver.bus().state(), CanBusMonitor::State::kPassive);
  pair.sendError(CAN_ERR_BUSOFF);
  ASSERT_TRUE(driver.poll(100, &sink));
  EXPECT_TRUE(driver.bus().busOff());
  EXPECT_EQ(driver.bus().busOffCount(), 1u);
  pair.sendError(CAN_ERR_RESTARTED);
  ASSERT_TRUE(driver.poll(100, &sink));
  EXPECT_EQ(driver.bus().state(), CanBusMonitor::State::kActive);
  EXPECT_EQ(driver.bus().restarts(), 1u);
  EXPECT_EQ(driver.bus().errorFrames(), 4u);
}

TEST(CanBusMonitor, RecoveryIsDueAfterTheConfiguredTimeInBusOff) {
  CanBusMonitor m(0.5);
  CanFrame f;
  m.onErrorFrame(CAN_ERR_BUSOFF, f, 1'000'000);
  EXPECT_FALSE(m.recoveryDue(1'400'000));
  EXPECT_TRUE(m.recoveryDue(1'500'000));
  m.markRecoveryAttempt(1'500'000);
  EXPECT_FALSE(m.recoveryDue(1'900'000));  // next attempt only after another recovery time
  EXPECT_TRUE(m.recoveryDue(2'000'000));
  m.onDataFrame();  // a frame arrived: the controller is back on the bus
  EXPECT_FALSE(m.busOff());
  EXPECT_FALSE(m.recoveryDue(3'000'000));
  EXPECT_EQ(m.recoveryAttempts(), 1u);
}

}  // namespace
}  // namespace deepnav
