#pragma once
#include <string>

#include "board/config/board_config.h"
#include "drivers/can/can_sensor_driver.h"
#include "drivers/modbus/modbus_depth_sensor.h"
#include "drivers/sensor_io/sensor_threads.h"
#include "drivers/serial/serial_sensor_driver.h"

namespace deepnav {

// The serial, CAN and Modbus driver configurations of a board: device paths from `sources.*`,
// protocols and settings from `serial.*`, `can.*` and `modbus_depth.*`. False (with *error naming the
// key) when a value the table cannot check is wrong (e.g. the CAN mapping spec).
bool dvlSerialConfig(const BoardConfig& board, SerialSensorConfig* config, std::string* error);
bool ahrsSerialConfig(const BoardConfig& board, SerialSensorConfig* config, std::string* error);
bool canSensorConfig(const BoardConfig& board, CanSensorConfig* config, std::string* error);
bool modbusDepthConfig(const BoardConfig& board, ModbusDepthConfig* config, std::string* error);

// Every sensor the board lists: a driver for each non-empty sources.dvl_serial, ahrs_serial,
// can_interface, depth_serial (what `deepnav run` starts with SensorThreads).
bool sensorThreadsConfig(const BoardConfig& board, SensorThreadsConfig* config, std::string* error);

}  // namespace deepnav
