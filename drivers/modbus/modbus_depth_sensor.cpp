#include "drivers/modbus/modbus_depth_sensor.h"

#include <cerrno>

#include <modbus.h>

#include "drivers/clock/monotonic_clock.h"

namespace deepnav {

ModbusDepthSensor::~ModbusDepthSensor() { close(); }

void ModbusDepthSensor::close() {
  if (ctx_ != nullptr) {
    modbus_close(ctx_);
    modbus_free(ctx_);
  }
  ctx_ = nullptr;
}

bool ModbusDepthSensor::open(const ModbusDepthConfig& config, std::string* error) {
  config_ = config;
  if (config.parity != 'N' && config.parity != 'E' && config.parity != 'O') {
    return *error = config.device + ": Modbus parity must be N, E or O", false;
  }
  if (config.slave_id < 1 || config.slave_id > 247) return *error = config.device + ": Modbus slave id must be 1..247", false;
  if (config.map.address < 0 || config.map.address + config.map.registerCount() > 65536) {
    return *error = config.device + ": Modbus register address out of range", false;
  }
  return connect(error);
}

bool ModbusDepthSensor::connect(std::string* error) {
  close();
  ctx_ = modbus_new_rtu(config_.device.c_str(), config_.baud, config_.parity, 8, config_.stop_bits);
  if (ctx_ == nullptr) return *error = config_.device + ": cannot create the Modbus RTU context: " + modbus_strerror(errno), false;
  modbus_set_slave(ctx_, config_.slave_id);
  modbus_set_response_timeout(ctx_, uint32_t(config_.response_timeout_ms / 1000), uint32_t(config_.response_timeout_ms % 1000) * 1000);
  if (modbus_connect(ctx_) != 0) {
    *error = config_.device + ": cannot open the Modbus line: " + modbus_strerror(errno);
    close();
    return false;
  }
  return true;
}

bool ModbusDepthSensor::read(DepthSample* sample, std::string* error) {
  if (ctx_ == nullptr && !connect(error)) return ++failures_, false;
  uint16_t regs[2] = {0, 0};
  const int n = config_.map.registerCount();
  const TimeUs t0 = monotonicUs();
  const int got = config_.map.kind == DepthRegisterMap::Kind::kInput ? modbus_read_input_registers(ctx_, config_.map.address, n, regs)
                                                                     : modbus_read_registers(ctx_, config_.map.address, n, regs);
  const TimeUs t1 = monotonicUs();
  ++reads_;
  if (got != n) {
    *error = config_.device + ": Modbus read of register " + std::to_string(config_.map.address) + " failed: " + modbus_strerror(errno);
    ++failures_;
    if (++failures_in_row_ >= kReconnectAfter) {
      failures_in_row_ = 0;
      ++reconnects_;
      std::string ignored;
      connect(&ignored);
    }
    return false;
  }
  failures_in_row_ = 0;
  if (!config_.map.decode(regs, t0 + (t1 - t0) / 2, sample)) {
    *error = config_.device + ": Modbus pressure value is not finite";
    ++failures_;
    return false;
  }
  return true;
}

}  // namespace deepnav
