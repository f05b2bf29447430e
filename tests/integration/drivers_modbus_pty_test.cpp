// The Modbus RTU depth sensor driver against a libmodbus RTU server on the other end of a pty pair:
// register map, scaling, the pressure -> depth model, exceptions and a silent slave.
#include <modbus.h>
#include <pty.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "drivers/modbus/modbus_depth_sensor.h"
#include "tests/support/fake_modbus_sensor.h"

namespace deepnav {
namespace {

using test::FakeSensor;

ModbusDepthConfig configFor(const std::string& path, int slave_id) {
  ModbusDepthConfig c;
  c.device = path;
  c.baud = 115200;
  c.slave_id = slave_id;
  c.response_timeout_ms = 200;
  c.map.kind = DepthRegisterMap::Kind::kInput;
  c.map.address = 10;
  c.map.type = DepthRegisterMap::Type::kF32;
  return c;
}

TEST(ModbusPty, Float32PressureGivesDepth) {
  FakeSensor sensor(7);
  ASSERT_FALSE(sensor.path().empty());
  sensor.setPressure(101325.0f + 1025.0f * 9.80665f * 120.0f);  // 120 m of sea water
  ModbusDepthSensor driver;
  std::string error;
  ASSERT_TRUE(driver.open(configFor(sensor.path(), 7), &error)) << error;
  DepthSample s;
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(driver.read(&s, &error)) << error;
  EXPECT_NEAR(s.depth_m, 120.0, 1e-3);
  EXPECT_NEAR(s.pressure_pa, 101325.0 + 1025.0 * 9.80665 * 120.0, 1.0);
  EXPECT_GT(s.t_us, 0);
  EXPECT_EQ(driver.failures(), 0u);
}

TEST(ModbusPty, ScaledHoldingRegister) {
  FakeSensor sensor(1);
  ASSERT_FALSE(sensor.path().empty());
  sensor.setHolding(3, 23456);  // 2345.6 mbar
  ModbusDepthConfig c = configFor(sensor.path(), 1);
  c.map.kind = DepthRegisterMap::Kind::kHolding;
  c.map.address = 3;
  c.map.type = DepthRegisterMap::Type::kU16;
  c.map.scale_pa = 10.0;  // 0.1 mbar per count
  ModbusDepthSensor driver;
  std::string error;
  ASSERT_TRUE(driver.open(c, &error)) << error;
  DepthSample s;
  ASSERT_TRUE(driver.read(&s, &error)) << error;
  EXPECT_NEAR(s.pressure_pa, 234560.0, 1e-9);
  EXPECT_NEAR(s.depth_m, (234560.0 - 101325.0) / (1025.0 * 9.80665), 1e-9);
}

TEST(ModbusPty, ExceptionAndSilentSlaveAreCountedFailures) {
  FakeSensor sensor(2);
  ASSERT_FALSE(sensor.path().empty());
  ModbusDepthConfig c = configFor(sensor.path(), 2);
  c.map.address = 99;  // the server holds registers 0-99: a 2-register read at 99 is an illegal address
  ModbusDepthSensor driver;
  std::string error;
  ASSERT_TRUE(driver.open(c, &error)) << error;
  DepthSample s;
  EXPECT_FALSE(driver.read(&s, &error));
  EXPECT_NE(error.find("register 99"), std::string::npos) << error;
  ModbusDepthSensor wrong_id;
  ASSERT_TRUE(wrong_id.open(configFor(sensor.path(), 9), &error)) << error;  // nobody answers to 9
  for (int i = 0; i < ModbusDepthSensor::kReconnectAfter; ++i) EXPECT_FALSE(wrong_id.read(&s, &error));
  EXPECT_EQ(wrong_id.failures(), uint64_t(ModbusDepthSensor::kReconnectAfter));
  EXPECT_EQ(wrong_id.reconnects(), 1u);
  EXPECT_FALSE(wrong_id.open({}, &error));  // no device
}

}  // namespace
}  // namespace deepnav
