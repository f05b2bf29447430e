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

namespace deepnav {
namespace {

// A pressure sensor: libmodbus RTU slave on the pty master, answering until stopped.
class FakeSensor {
 public:
  explicit FakeSensor(int slave_id) {
    char name[128];
    if (openpty(&master_, &slave_, name, nullptr, nullptr) != 0) return;
    path_ = name;
    ctx_ = modbus_new_rtu(name, 115200, 'N', 8, 1);  // the device name is not opened: the socket is set below
    modbus_set_slave(ctx_, slave_id);
    modbus_set_socket(ctx_, master_);
    map_ = modbus_mapping_new(0, 0, 100, 100);
    thread_ = std::thread([this] { serve(); });
  }
  ~FakeSensor() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    if (map_) modbus_mapping_free(map_);
    if (ctx_) modbus_free(ctx_);
    if (master_ >= 0) ::close(master_);
    if (slave_ >= 0) ::close(slave_);
  }
  const std::string& path() const { return path_; }
  // Float32 pressure in pascals at input registers 10-11, high word first.
  void setPressure(float pa) {
    uint32_t bits;
    std::memcpy(&bits, &pa, 4);
    map_->tab_input_registers[10] = uint16_t(bits >> 16);
    map_->tab_input_registers[11] = uint16_t(bits & 0xFFFF);
  }
  void setHolding(int address, uint16_t value) { map_->tab_registers[address] = value; }

 private:
  void serve() {
    uint8_t query[MODBUS_RTU_MAX_ADU_LENGTH];
    while (!stop_) {
      fd_set set;
      FD_ZERO(&set);
      FD_SET(master_, &set);
      timeval tv{0, 20000};
      if (::select(master_ + 1, &set, nullptr, nullptr, &tv) <= 0) continue;
      const int n = modbus_receive(ctx_, query);
      if (n > 0) modbus_reply(ctx_, query, n, map_);
    }
  }

  int master_ = -1, slave_ = -1;
  std::string path_;
  modbus_t* ctx_ = nullptr;
  modbus_mapping_t* map_ = nullptr;
  std::thread thread_;
  std::atomic<bool> stop_{false};
};

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
