#pragma once
#include <cstdint>
#include <string>

#include "drivers/modbus/depth_register_map.h"

typedef struct _modbus modbus_t;

namespace deepnav {

struct ModbusDepthConfig {
  std::string device;     // e.g. /dev/ttyUSB0
  int baud = 9600;
  char parity = 'N';      // N, E or O
  int stop_bits = 1;
  int slave_id = 1;
  int response_timeout_ms = 100;
  DepthRegisterMap map;
};

// A depth/pressure sensor polled over Modbus RTU with libmodbus. One read() per poll: a failed request
// (timeout, CRC error, exception) is counted and returns false; after `reconnect_after` failures in a
// row the serial line is closed and reopened.
class ModbusDepthSensor {
 public:
  ModbusDepthSensor() = default;
  ModbusDepthSensor(const ModbusDepthSensor&) = delete;
  ModbusDepthSensor& operator=(const ModbusDepthSensor&) = delete;
  ~ModbusDepthSensor();

  bool open(const ModbusDepthConfig& config, std::string* error);
  void close();
  // Reads the registers and converts them; t_us stamps the sample (the request's mid-time).
  bool read(DepthSample* sample, std::string* error);

  uint64_t reads() const { return reads_; }
  uint64_t failures() const { return failures_; }
  uint64_t reconnects() const { return reconnects_; }
  static constexpr int kReconnectAfter = 5;

 private:
  bool connect(std::string* error);

  ModbusDepthConfig config_;
  modbus_t* ctx_ = nullptr;
  uint64_t reads_ = 0, failures_ = 0, reconnects_ = 0;
  int failures_in_row_ = 0;
};

}  // namespace deepnav
