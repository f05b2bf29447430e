#include "drivers/parsers/can_field_mapping.h"

#include <charconv>
#include <cmath>
#include <cstring>

#include "drivers/parsers/byte_order.h"

namespace deepnav {
namespace {

struct Named {
  const char* name;
  int value;
};

constexpr Named kTypes[] = {{"i8", 0},     {"u8", 1},     {"i16le", 2}, {"u16le", 3}, {"i16be", 4},  {"u16be", 5},
                            {"i32le", 6},  {"u32le", 7},  {"i32be", 8}, {"u32be", 9}, {"f32le", 10}, {"f32be", 11}};
constexpr Named kTargets[] = {{"gyro_x", 0},  {"gyro_y", 1},  {"gyro_z", 2}, {"accel_x", 3}, {"accel_y", 4},
                              {"accel_z", 5}, {"heading", 6}, {"roll", 7},   {"pitch", 8}};

template <size_t N>
bool lookup(const Named (&table)[N], std::string_view name, int* value) {
  for (const Named& n : table) {
    if (name == n.name) return *value = n.value, true;
  }
  return false;
}

std::string_view cut(std::string_view* s, char sep) {
  const size_t i = s->find(sep);
  const std::string_view head = s->substr(0, i);
  *s = i == std::string_view::npos ? std::string_view() : s->substr(i + 1);
  return head;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return s;
}

}  // namespace

int CanFieldMapping::typeSize(Type t) {
  switch (t) {
    case Type::kI8:
    case Type::kU8: return 1;
    case Type::kI16Le:
    case Type::kU16Le:
    case Type::kI16Be:
    case Type::kU16Be: return 2;
    default: return 4;
  }
}

double CanFieldMapping::read(const uint8_t* p, Type t) {
  float f = 0;
  uint32_t bits = 0;
  switch (t) {
    case Type::kI8: return int8_t(p[0]);
    case Type::kU8: return p[0];
    case Type::kI16Le: return readLeI16(p);
    case Type::kU16Le: return readLe16(p);
    case Type::kI16Be: return int16_t(readBe16(p));
    case Type::kU16Be: return readBe16(p);
    case Type::kI32Le: return readLeI32(p);
    case Type::kU32Le: return readLe32(p);
    case Type::kI32Be: return int32_t(readBe32(p));
    case Type::kU32Be: return readBe32(p);
    case Type::kF32Le: bits = readLe32(p); break;
    case Type::kF32Be: bits = readBe32(p); break;
  }
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

bool CanFieldMapping::parse(std::string_view spec, std::string* error) {
  num_fields_ = 0;
  mapped_ = fresh_ = 0;
  int index = 0;
  while (!trim(spec).empty()) {
    const std::string_view entry = trim(cut(&spec, ';'));
    ++index;
    const auto fail = [&](const char* why) {
      *error = "can.imu_mapping entry " + std::to_string(index) + " '" + std::string(entry) + "': " + why;
      return false;
    };
    if (entry.empty()) continue;
    if (num_fields_ == kMaxFields) return fail("too many entries (at most 16)");
    std::string_view rest = entry;
    std::string_view id = trim(cut(&rest, ':'));
    const std::string_view byte = trim(cut(&rest, ':')), type = trim(cut(&rest, ':')), scale = trim(cut(&rest, ':'));
    const std::string_view target = trim(rest);
    Field f;
    if (id.substr(0, 2) == "0x" || id.substr(0, 2) == "0X") id.remove_prefix(2);
    if (id.empty() || id.size() > 8 || std::from_chars(id.data(), id.data() + id.size(), f.id, 16).ptr != id.data() + id.size()) {
      return fail("identifier is not hex");
    }
    f.extended = id.size() > 3;
    if (f.id > (f.extended ? 0x1FFFFFFFu : 0x7FFu)) return fail("identifier out of range");
    if (byte.empty() || std::from_chars(byte.data(), byte.data() + byte.size(), f.byte).ptr != byte.data() + byte.size()) {
      return fail("byte offset is not an integer");
    }
    int v = 0;
    if (!lookup(kTypes, type, &v)) return fail("unknown type (i8 u8 i16le u16le i16be u16be i32le u32le i32be u32be f32le f32be)");
    f.type = Type(v);
    if (f.byte < 0 || f.byte + typeSize(f.type) > 8) return fail("field runs past byte 7");
    if (scale.empty() || std::from_chars(scale.data(), scale.data() + scale.size(), f.scale).ptr != scale.data() + scale.size() ||
        !std::isfinite(f.scale) || f.scale == 0) {
      return fail("scale is not a non-zero number");
    }
    if (!lookup(kTargets, target, &v)) return fail("unknown target (gyro_x..z accel_x..z heading roll pitch)");
    f.target = Target(v);
    mapped_ |= 1u << f.target;
    fields_[num_fields_++] = f;
  }
  return true;
}

bool CanFieldMapping::matches(const CanFrame& frame) const {
  for (int i = 0; i < num_fields_; ++i) {
    if (fields_[i].id == frame.id && fields_[i].extended == frame.extended) return true;
  }
  return false;
}

bool CanFieldMapping::apply(const CanFrame& frame, TimeUs t_us, Output* out) {
  *out = Output{};
  uint32_t updated = 0;
  for (int i = 0; i < num_fields_; ++i) {
    const Field& f = fields_[i];
    if (f.id != frame.id || f.extended != frame.extended) continue;
    if (f.byte + typeSize(f.type) > frame.dlc) return false;
    const double v = read(frame.data.data() + f.byte, f.type) * f.scale;
    if (!std::isfinite(v)) return false;
    value_[f.target] = v;
    updated |= 1u << f.target;
  }
  fresh_ |= updated;
  constexpr uint32_t kImuBits = 0x3F;
  const uint32_t imu_needed = mapped_ & kImuBits;
  if (imu_needed != 0 && (updated & kImuBits) != 0 && (fresh_ & imu_needed) == imu_needed) {
    out->has_imu = true;
    out->imu.t_us = t_us;
    out->imu.w_imu_radps = Eigen::Vector3d(value_[kGyroX], value_[kGyroY], value_[kGyroZ]);
    out->imu.f_imu_mps2 = Eigen::Vector3d(value_[kAccelX], value_[kAccelY], value_[kAccelZ]);
    fresh_ &= ~kImuBits;
  }
  if (updated & (1u << kHeading)) {
    out->has_heading = true;
    double h = std::fmod(value_[kHeading], 2 * M_PI);
    if (h < 0) h += 2 * M_PI;
    out->heading.t_us = t_us;
    out->heading.heading_rad = h;
    fresh_ &= ~(1u << kHeading);
  }
  const uint32_t att_bits = (1u << kRoll) | (1u << kPitch);
  if ((updated & att_bits) != 0 && (fresh_ & att_bits) == att_bits) {
    out->has_attitude = true;
    out->attitude.t_us = t_us;
    out->attitude.roll_rad = value_[kRoll];
    out->attitude.pitch_rad = value_[kPitch];
    fresh_ &= ~att_bits;
  }
  return true;
}

}  // namespace deepnav
