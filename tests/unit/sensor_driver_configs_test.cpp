// Board keys of the serial, CAN and Modbus sensor drivers: defaults, a board that sets them, and the
// messages for a bad CAN mapping.
#include <string>

#include <gtest/gtest.h>

#include "board/config/sensor_driver_configs.h"

namespace deepnav {
namespace {

TEST(SensorDriverConfigs, DefaultsAreUsable) {
  const BoardConfig b = defaultBoardConfig();
  std::string error;
  SerialSensorConfig s;
  ASSERT_TRUE(dvlSerialConfig(b, &s, &error)) << error;
  EXPECT_EQ(s.protocol, SensorProtocol::kPd0);
  ASSERT_TRUE(ahrsSerialConfig(b, &s, &error)) << error;
  EXPECT_EQ(s.protocol, SensorProtocol::kXsens);
  CanSensorConfig c;
  ASSERT_TRUE(canSensorConfig(b, &c, &error)) << error;
  EXPECT_EQ(c.heading_source, -1);
  ModbusDepthConfig m;
  ASSERT_TRUE(modbusDepthConfig(b, &m, &error)) << error;
  EXPECT_EQ(m.map.type, DepthRegisterMap::Type::kF32);
  EXPECT_EQ(m.parity, 'N');
  SensorThreadsConfig t;
  ASSERT_TRUE(sensorThreadsConfig(b, &t, &error)) << error;
  EXPECT_FALSE(t.dvl || t.ahrs || t.can || t.depth);  // the simulated board lists no devices
}

TEST(SensorDriverConfigs, BoardFileSetsTheDrivers) {
  BoardConfig b;
  std::string error;
  ASSERT_TRUE(loadBoardConfigText(R"(
sources: {dvl_serial: /dev/ttyS1, depth_serial: /dev/ttyUSB0, can_interface: can0}
serial: {dvl_protocol: wl-a50, dvl_baud: 115200, ahrs_protocol: nmea0183, ahrs_baud: 4800}
can: {heading_source: 128, imu_mapping: "0x100:0:i16le:0.001:gyro_x"}
modbus_depth: {baud: 19200, parity: E, slave_id: 3, register_kind: holding, register_address: 40, value_type: u16, scale_pa: 100}
)",
                                  "test.yaml", &b, &error))
      << error;
  SerialSensorConfig s;
  ASSERT_TRUE(dvlSerialConfig(b, &s, &error));
  EXPECT_EQ(s.device, "/dev/ttyS1");
  EXPECT_EQ(s.protocol, SensorProtocol::kWlA50);
  ASSERT_TRUE(ahrsSerialConfig(b, &s, &error));
  EXPECT_EQ(s.protocol, SensorProtocol::kNmea0183);
  EXPECT_EQ(s.baud, 4800);
  CanSensorConfig c;
  ASSERT_TRUE(canSensorConfig(b, &c, &error)) << error;
  EXPECT_EQ(c.interface, "can0");
  EXPECT_EQ(c.heading_source, 128);
  ModbusDepthConfig m;
  ASSERT_TRUE(modbusDepthConfig(b, &m, &error)) << error;
  EXPECT_EQ(m.parity, 'E');
  EXPECT_EQ(m.slave_id, 3);
  EXPECT_EQ(m.map.kind, DepthRegisterMap::Kind::kHolding);
  EXPECT_EQ(m.map.address, 40);
  EXPECT_DOUBLE_EQ(m.map.scale_pa, 100.0);
  SensorThreadsConfig t;
  ASSERT_TRUE(sensorThreadsConfig(b, &t, &error)) << error;
  EXPECT_TRUE(t.dvl && t.can && t.depth);
  EXPECT_FALSE(t.ahrs);  // sources.ahrs_serial not set
  EXPECT_EQ(t.depth->device, "/dev/ttyUSB0");
  EXPECT_FALSE(loadBoardConfigText("serial: {dvl_protocol: pd5}\n", "bad.yaml", &b, &error));
  EXPECT_NE(error.find("serial.dvl_protocol"), std::string::npos) << error;
  ASSERT_TRUE(loadBoardConfigText("can: {imu_mapping: '0x100:9:i16le:1:gyro_x'}\n", "bad.yaml", &b, &error)) << error;
  EXPECT_FALSE(canSensorConfig(b, &c, &error));
  EXPECT_NE(error.find("can.imu_mapping entry 1"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav
