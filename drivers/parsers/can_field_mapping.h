#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "drivers/parsers/can_frame.h"
#include "nav/types/attitude_sample.h"
#include "nav/types/heading_sample.h"
#include "nav/types/imu_sample.h"

namespace deepnav {

// Where the fields of a CAN IMU or compass that does not speak NMEA 2000 sit in its frames. Written
// in board.yaml (`can.imu_mapping`) as entries separated by ';':
//     ID:BYTE:TYPE:SCALE:TARGET
//   ID      frame identifier in hex ("0x18FF0180"; more than 3 digits = 29-bit)
//   BYTE    offset of the field in the payload (0-7)
//   TYPE    i8 u8 i16le u16le i16be u16be i32le u32le i32be u32be f32le f32be
//   SCALE   SI units per count (e.g. 0.0001 for 1e-4 rad)
//   TARGET  gyro_x gyro_y gyro_z (rad/s) accel_x accel_y accel_z (m/s^2) heading roll pitch (rad),
//           in the sensor's FLU frame (heading clockwise from north)
// An ImuSample is emitted when all six gyro/accel targets have been refreshed since the last one (the
// fields may come in different frames), a HeadingSample on every heading, an AttitudeSample when roll
// and pitch have both been refreshed.
class CanFieldMapping {
 public:
  static constexpr int kMaxFields = 16;
  enum Target { kGyroX, kGyroY, kGyroZ, kAccelX, kAccelY, kAccelZ, kHeading, kRoll, kPitch, kNumTargets };

  // Parses the spec; an empty spec maps nothing. On error *error names the entry and what is wrong.
  bool parse(std::string_view spec, std::string* error);
  int numFields() const { return num_fields_; }
  bool empty() const { return num_fields_ == 0; }
  // Identifier of field i (for the socket's acceptance filters).
  uint32_t fieldId(int i, bool* extended) const { return *extended = fields_[i].extended, fields_[i].id; }
  // True when the frame's identifier is mapped.
  bool matches(const CanFrame& frame) const;

  struct Output {
    bool has_imu = false, has_heading = false, has_attitude = false;
    ImuSample imu;
    HeadingSample heading;
    AttitudeSample attitude;
  };
  // Applies one frame; false when a mapped field runs past the frame's length (the frame is dropped).
  bool apply(const CanFrame& frame, TimeUs t_us, Output* out);

 private:
  enum class Type { kI8, kU8, kI16Le, kU16Le, kI16Be, kU16Be, kI32Le, kU32Le, kI32Be, kU32Be, kF32Le, kF32Be };
  struct Field {
    uint32_t id = 0;
    bool extended = false;
    int byte = 0;
    Type type = Type::kU8;
    double scale = 1.0;
    Target target = kGyroX;
  };
  static int typeSize(Type t);
  static double read(const uint8_t* p, Type t);

  std::array<Field, kMaxFields> fields_{};
  int num_fields_ = 0;
  std::array<double, kNumTargets> value_{};
  uint32_t fresh_ = 0;    // bit per target refreshed since its last emission
  uint32_t mapped_ = 0;   // bit per target present in the mapping
};

}  // namespace deepnav
