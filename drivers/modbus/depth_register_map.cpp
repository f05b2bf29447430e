#include "drivers/modbus/depth_register_map.h"

#include <cmath>
#include <cstring>

namespace deepnav {

bool DepthRegisterMap::decode(const uint16_t* r, TimeUs t_us, DepthSample* s) const {
  const uint32_t word32 = high_word_first ? (uint32_t(r[0]) << 16) | r[1] : (uint32_t(r[1]) << 16) | r[0];
  double raw = 0;
  switch (type) {
    case Type::kU16: raw = r[0]; break;
    case Type::kI16: raw = int16_t(r[0]); break;
    case Type::kU32: raw = word32; break;
    case Type::kI32: raw = int32_t(word32); break;
    case Type::kF32: {
      float f;
      std::memcpy(&f, &word32, sizeof f);
      raw = f;
      break;
    }
  }
  const double p = raw * scale_pa + offset_pa;
  if (!std::isfinite(p)) return false;
  *s = DepthSample{};
  s->t_us = t_us;
  s->pressure_pa = p;
  s->depth_m = (p - atmospheric_pa) / (density_kgpm3 * gravity_mps2);
  s->sigma_m = sigma_m;
  return true;
}

bool parseDepthRegisterType(std::string_view name, DepthRegisterMap::Type* type) {
  using T = DepthRegisterMap::Type;
  if (name == "u16") return *type = T::kU16, true;
  if (name == "i16") return *type = T::kI16, true;
  if (name == "u32") return *type = T::kU32, true;
  if (name == "i32") return *type = T::kI32, true;
  if (name == "f32") return *type = T::kF32, true;
  return false;
}

bool parseDepthRegisterKind(std::string_view name, DepthRegisterMap::Kind* kind) {
  if (name == "holding") return *kind = DepthRegisterMap::Kind::kHolding, true;
  if (name == "input") return *kind = DepthRegisterMap::Kind::kInput, true;
  return false;
}

}  // namespace deepnav
