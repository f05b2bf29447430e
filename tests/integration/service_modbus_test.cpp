// The Modbus TCP output, read by a real libmodbus client on loopback while `deepnav run` replays a dive:
// the register map of drivers/outputs/register_map.h (magic, version, fresh sequence and time, pose,
// velocity, covariance diagonal, stage, status, health, counters), also as input registers; writes refused.
#include <modbus/modbus.h>

#include <cerrno>
#include <cmath>
#include <thread>

#include <gtest/gtest.h>

#include "drivers/outputs/register_map.h"
#include "tests/support/service_fixture.h"
#include "tests/support/test_dive.h"

namespace deepnav {
namespace {

class ModbusClient {
 public:
  explicit ModbusClient(int port) : ctx_(modbus_new_tcp("127.0.0.1", port)) {}
  ~ModbusClient() {
    modbus_close(ctx_);
    modbus_free(ctx_);
  }
  bool connect() { return modbus_connect(ctx_) == 0; }
  modbus_t* get() { return ctx_; }

 private:
  modbus_t* ctx_;
};

TEST(ServiceModbus, RegisterMapIsServedAtLoopRateAndReadOnly) {
  // GIVEN deepnav running on a 6 s dive with the Modbus server on a free loopback port
  const std::string dive = testing::makeTestDive("modbus_dive", 6.0, 7, false);
  const int port = testing::freePort(SOCK_STREAM);
  const std::string board = testing::makeServiceBoard(
      "modbus_board", dive,
      {{"outputs.modbus_enabled", "true"}, {"outputs.modbus_address", "127.0.0.1"},
       {"outputs.modbus_port", std::to_string(port)}});
  testing::NotifyReceiver systemd;
  testing::DeepnavProcess run({"run", "--board", board, "--no-record", "--duration", "4"},
                              {{"NOTIFY_SOCKET", systemd.path()}});
  ASSERT_FALSE(systemd.receive(10.0, "READY=1").empty()) << run.stderrText();
  ModbusClient client(port);
  ASSERT_TRUE(client.connect()) << modbus_strerror(errno);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // past IMU alignment
  // WHEN a PLC reads the whole map twice, 0.2 s apart (function 3), and once as input registers (function 4)
  std::uint16_t a[reg::kCount], b[reg::kCount], in[reg::kCount];
  ASSERT_EQ(modbus_read_registers(client.get(), 0, reg::kCount, a), reg::kCount) << modbus_strerror(errno);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  ASSERT_EQ(modbus_read_registers(client.get(), 0, reg::kCount, b), reg::kCount) << modbus_strerror(errno);
  ASSERT_EQ(modbus_read_input_registers(client.get(), 0, reg::kCount, in), reg::kCount) << modbus_strerror(errno);
  // THEN the map is deepnav's, version 1, and fresh: the sequence advanced by about 20 ticks (100 Hz) and
  // the time by 10 ms per tick (more when a loaded machine made the loop skip ticks)
  EXPECT_EQ(a[reg::kMagic], 0x444E);
  EXPECT_EQ(a[reg::kVersion], 1);
  EXPECT_EQ(in[reg::kMagic], 0x444E);
  const std::uint32_t dseq = registerU32(b, reg::kSequence) - registerU32(a, reg::kSequence);
  EXPECT_GE(dseq, 5u);
  EXPECT_LE(dseq, 40u);
  const std::uint64_t dt_us = registerU64(b, reg::kTimeUs) - registerU64(a, reg::kTimeUs);
  EXPECT_GE(dt_us, 10'000u * dseq);
  EXPECT_EQ(dt_us % 10'000u, 0u);
  // AND the pose is a pose: unit quaternion, depth = -up, heading = 90 - yaw in [0, 360), finite variances
  const float qx = registerFloat(b, reg::kQx), qy = registerFloat(b, reg::kQy), qz = registerFloat(b, reg::kQz),
              qw = registerFloat(b, reg::kQw);
  EXPECT_NEAR(qx * qx + qy * qy + qz * qz + qw * qw, 1.0, 1e-5);
  EXPECT_FLOAT_EQ(registerFloat(b, reg::kDepth), -registerFloat(b, reg::kUp));
  EXPECT_GT(registerFloat(b, reg::kDepth), 1.0);  // the default dive is well below the surface
  const float heading = registerFloat(b, reg::kHeading);
  EXPECT_GE(heading, 0.0f);
  EXPECT_LT(heading, 360.0f);
  EXPECT_NEAR(std::remainder(heading - (90.0f - registerFloat(b, reg::kYaw)), 360.0f), 0.0, 1e-3);
  EXPECT_EQ(b[reg::kStage], 1);  // stage 1 once aligned
  EXPECT_TRUE(b[reg::kStatus] & 0x1) << "attitude valid";
  for (std::uint16_t r = reg::kVarEast; r <= reg::kVarVelUp; r += 2) {
    EXPECT_TRUE(std::isfinite(registerFloat(b, r)) && registerFloat(b, r) > 0.0f) << "register " << r;
  }
  // AND the counters count: ticks and samples consumed
  EXPECT_GT(registerU32(b, reg::kTicks), 100u);
  EXPECT_GT(registerU32(b, reg::kImuCount), 100u);
  EXPECT_GT(registerU32(b, reg::kDvlCount), 5u);
  EXPECT_GT(registerU32(b, reg::kDepthCount), 5u);
  // AND writes are refused with exception 1 (illegal function)
  errno = 0;
  EXPECT_EQ(modbus_write_register(client.get(), reg::kStage, 2), -1);
  EXPECT_EQ(errno, EMBXILFUN);
  EXPECT_EQ(run.wait(8.0), 0) << run.stderrText();
}

}  // namespace
}  // namespace deepnav
