#pragma once
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "drivers/buffers/live_inputs.h"
#include "drivers/can/can_sensor_driver.h"
#include "drivers/modbus/modbus_depth_sensor.h"
#include "drivers/sensor_io/live_inputs_sink.h"
#include "drivers/serial/serial_sensor_driver.h"

namespace deepnav {

struct SensorThreadsConfig {
  std::optional<SerialSensorConfig> dvl;    // PD0, PD6 or Water Linked: DVL samples
  std::optional<SerialSensorConfig> ahrs;   // Xsens: IMU + attitude; NMEA 0183: heading
  std::optional<CanSensorConfig> can;       // heading, attitude, IMU (mapped) not already given above
  int can_socket_fd = -1;                   // tests: a connected socket carrying struct can_frame
  std::optional<ModbusDepthConfig> depth;   // depth samples
  double depth_rate_hz = 10.0;
  int poll_timeout_ms = 50;                 // how soon a thread notices stop()
};

// One thread per configured sensor, each feeding its sample kinds into the nav loop's rings. Every
// ring gets one producer: the DVL line gives DVL samples, the AHRS line IMU and attitude (Xsens) or
// heading (NMEA 0183), the Modbus sensor depth, and the CAN bus whatever kinds are left (heading and
// attitude from NMEA 2000, IMU from a mapping). start() opens every device first, so a missing device
// fails start-up with its name, before any thread runs.
class SensorThreads {
 public:
  struct Status {
    bool dvl_on = false, ahrs_on = false, can_on = false, depth_on = false;  // which drivers ran
    SensorStreamDecoder::Counters dvl, ahrs;
    uint64_t dvl_reopens = 0, ahrs_reopens = 0;  // serial ports opened again after vanishing
    CanSensorDriver::Counters can;
    const char* can_bus_state = "";
    int can_tx_errors = 0, can_rx_errors = 0;  // the controller's error counters
    uint64_t depth_reads = 0, depth_failures = 0;
  };

  SensorThreads() = default;
  SensorThreads(const SensorThreads&) = delete;
  SensorThreads& operator=(const SensorThreads&) = delete;
  ~SensorThreads() { stop(); }

  bool start(const SensorThreadsConfig& config, LiveInputs* inputs, std::string* error);
  void stop();
  // The drivers' counters. Call after stop(): the driver threads write them without synchronisation.
  Status status() const;
  // Which kinds the CAN driver forwards, given the serial AHRS protocol.
  static uint8_t canKinds(const SensorThreadsConfig& config);

 private:
  void runSerial(SerialSensorDriver* driver, LiveInputsSink sink);
  void runCan(LiveInputsSink sink);
  void runDepth(LiveInputs* inputs);

  SensorThreadsConfig config_;
  std::unique_ptr<SerialSensorDriver> dvl_, ahrs_;
  std::unique_ptr<CanSensorDriver> can_;
  std::unique_ptr<ModbusDepthSensor> depth_;
  std::atomic<uint64_t> depth_reads_{0}, depth_failures_{0};
  std::vector<std::thread> threads_;
  std::atomic<bool> stop_{false};
};

}  // namespace deepnav
