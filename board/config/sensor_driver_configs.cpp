#include "board/config/sensor_driver_configs.h"

#include "drivers/parsers/can_field_mapping.h"

namespace deepnav {

bool dvlSerialConfig(const BoardConfig& b, SerialSensorConfig* c, std::string* error) {
  *c = SerialSensorConfig{};
  c->device = b.sources.dvl_serial;
  c->baud = b.serial.dvl_baud;
  c->reopen_interval_s = b.serial.reopen_interval_s;
  if (!parseSensorProtocol(b.serial.dvl_protocol, &c->protocol)) return *error = "serial.dvl_protocol: unknown protocol", false;
  return true;
}

bool ahrsSerialConfig(const BoardConfig& b, SerialSensorConfig* c, std::string* error) {
  *c = SerialSensorConfig{};
  c->device = b.sources.ahrs_serial;
  c->baud = b.serial.ahrs_baud;
  c->reopen_interval_s = b.serial.reopen_interval_s;
  if (!parseSensorProtocol(b.serial.ahrs_protocol, &c->protocol)) return *error = "serial.ahrs_protocol: unknown protocol", false;
  return true;
}

bool canSensorConfig(const BoardConfig& b, CanSensorConfig* c, std::string* error) {
  *c = CanSensorConfig{};
  c->interface = b.sources.can_interface;
  c->heading_source = b.can.heading_source;
  c->attitude_source = b.can.attitude_source;
  c->imu_mapping = b.can.imu_mapping;
  c->bus_off_recovery_s = b.can.bus_off_recovery_s;
  CanFieldMapping check;
  return check.parse(c->imu_mapping, error);  // the message names can.imu_mapping and the entry
}

bool modbusDepthConfig(const BoardConfig& b, ModbusDepthConfig* c, std::string* error) {
  const BoardConfig::ModbusDepth& m = b.modbus_depth;
  *c = ModbusDepthConfig{};
  c->device = b.sources.depth_serial;
  c->baud = m.baud;
  c->parity = m.parity.empty() ? 'N' : m.parity[0];
  c->stop_bits = m.stop_bits;
  c->slave_id = m.slave_id;
  c->response_timeout_ms = m.timeout_ms;
  if (!parseDepthRegisterKind(m.register_kind, &c->map.kind)) return *error = "modbus_depth.register_kind: unknown kind", false;
  if (!parseDepthRegisterType(m.value_type, &c->map.type)) return *error = "modbus_depth.value_type: unknown type", false;
  c->map.address = m.register_address;
  c->map.high_word_first = m.high_word_first;
  c->map.scale_pa = m.scale_pa;
  c->map.offset_pa = m.offset_pa;
  c->map.atmospheric_pa = m.atmospheric_pa;
  c->map.density_kgpm3 = m.water_density_kgpm3;
  if (c->map.address + c->map.registerCount() > 65536) return *error = "modbus_depth.register_address: value runs past register 65535", false;
  return true;
}

bool sensorThreadsConfig(const BoardConfig& b, SensorThreadsConfig* c, std::string* error) {
  *c = SensorThreadsConfig{};
  if (!b.sources.dvl_serial.empty() && !dvlSerialConfig(b, &c->dvl.emplace(), error)) return false;
  if (!b.sources.ahrs_serial.empty() && !ahrsSerialConfig(b, &c->ahrs.emplace(), error)) return false;
  if (!b.sources.can_interface.empty() && !canSensorConfig(b, &c->can.emplace(), error)) return false;
  if (!b.sources.depth_serial.empty() && !modbusDepthConfig(b, &c->depth.emplace(), error)) return false;
  c->depth_rate_hz = b.modbus_depth.rate_hz;
  return true;
}

}  // namespace deepnav
