#pragma once
#include <cstdint>
#include <string>
#include <string_view>

#include "nav/types/depth_sample.h"

namespace deepnav {

// Where a Modbus pressure/depth sensor keeps its reading, and how to turn it into pressure and depth.
// From board.yaml (`modbus.*`): register address and kind, value type and word order, scale and offset
// to pascals, and the water column model depth = (p - p_atm) / (rho * g).
struct DepthRegisterMap {
  enum class Kind { kHolding, kInput };
  enum class Type { kU16, kI16, kU32, kI32, kF32 };
  Kind kind = Kind::kInput;
  int address = 0;              // first register (0-based protocol address)
  Type type = Type::kF32;
  bool high_word_first = true;  // 32-bit values: the first register holds the high 16 bits
  double scale_pa = 1.0;        // pascals per count (e.g. 100 for a value in mbar, 1e5 for bar)
  double offset_pa = 0.0;
  double atmospheric_pa = 101325.0;
  double density_kgpm3 = 1025.0;
  double gravity_mps2 = 9.80665;
  double sigma_m = 0.0;         // 1-sigma carried by each sample (0: the EKF's default)

  int registerCount() const { return type == Type::kU16 || type == Type::kI16 ? 1 : 2; }
  // Pressure and depth from the registers read; false when the value is not finite.
  bool decode(const uint16_t* registers, TimeUs t_us, DepthSample* sample) const;
};

bool parseDepthRegisterType(std::string_view name, DepthRegisterMap::Type* type);
bool parseDepthRegisterKind(std::string_view name, DepthRegisterMap::Kind* kind);

}  // namespace deepnav
