#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <sstream>
#include <string>
#include <type_traits>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace deepnav {

// How a parameter is written and where it lands. kVec3 lands in an Eigen::Vector3d; kRotation is written
// [roll, pitch, yaw] in degrees (ZYX, as a mounting rotation is measured) and lands in an
// Eigen::Quaterniond; kDurationS is written in seconds and lands in an int64 microseconds (TimeUs).
// kChoice lands in a std::string; kEnum is written as kChoice is and lands in an enum of underlying type
// int whose value is the written choice's position in `choices` (declared with DEEPNAV_PARAM_ENUM_FIELD).
// kSize is written and listed as kInt is and lands in a std::size_t (a capacity, a count).
enum class ParamType { kBool, kInt, kDouble, kString, kChoice, kVec3, kRotation, kDurationS, kEnum, kSize };

// One parameter of a module's config, declared once, next to the struct it lands in: the key a board file
// writes in the module's section, its type, unit, inclusive range (kInt, kDouble, kVec3 each element,
// kDurationS in seconds, kRotation each written angle, kSize) and meaning. Its default is the field's initialiser
// in the struct. The module validates its config against these ranges (checkParamRanges) and the board
// reads its files through the same table (board/config/param_table.h), so the two cannot disagree.
template <typename Config>
struct ParamDecl {
  const char* key;          // below the module's section, e.g. "gravity_mps2" of "ekf.gravity_mps2"
  ParamType type;
  const char* unit;
  double min;
  double max;
  const char* choices;      // kChoice: allowed values separated by '|'
  const char* doc;
  const char* member;       // the field's name in Config, for messages
  void* (*field)(Config&);  // where the value lands
};

// Declares a table row's member name and field accessor together: DEEPNAV_PARAM_FIELD(Config, gravity_mps2).
#define DEEPNAV_PARAM_FIELD(Config, member) #member, [](Config& c) -> void* { return &c.member; }
// The same for a kEnum field: the enum must be int-sized (its value is read and written as an int).
#define DEEPNAV_PARAM_ENUM_FIELD(Config, member)                                                  \
  #member, [](Config& c) -> void* {                                                                \
    static_assert(std::is_enum_v<std::remove_reference_t<decltype(c.member)>> &&                   \
                  sizeof(c.member) == sizeof(int), "a kEnum field is an int-sized enum");            \
    return &c.member;                                                                              \
  }

// The position of `value` in the '|'-separated `choices` (-1: not one of them), and the choice at a position
// ("" outside).
inline int paramChoiceIndex(const char* choices, const std::string& value) {
  if (value.empty()) return -1;
  const std::string all = choices;
  std::size_t begin = 0;
  for (int index = 0;; ++index) {
    const std::size_t end = all.find('|', begin);
    if (all.substr(begin, end == std::string::npos ? std::string::npos : end - begin) == value) return index;
    if (end == std::string::npos) return -1;
    begin = end + 1;
  }
}

inline std::string paramChoiceAt(const char* choices, int index) {
  if (index < 0) return "";
  const std::string all = choices;
  std::size_t begin = 0;
  for (int i = 0; i < index; ++i) {
    begin = all.find('|', begin);
    if (begin == std::string::npos) return "";
    ++begin;
  }
  return all.substr(begin, all.find('|', begin) - begin);
}

// A kEnum target read and written as the int it is (no aliasing of the enum type through int*).
inline int paramEnumValue(const void* target) {
  int v = 0;
  std::memcpy(&v, target, sizeof v);
  return v;
}

inline void setParamEnumValue(void* target, int v) { std::memcpy(target, &v, sizeof v); }

// "[min, max]" (or what is allowed) as messages and the board's documentation write it.
inline std::string paramRangeText(ParamType type, double min, double max, const char* choices) {
  std::ostringstream s;
  switch (type) {
    case ParamType::kBool: return "true or false";
    case ParamType::kString: return "a string";
    case ParamType::kChoice:
    case ParamType::kEnum: s << "one of " << choices; return s.str();
    case ParamType::kInt:
    case ParamType::kSize: s << "an integer in [" << min << ", " << max << "]"; return s.str();
    case ParamType::kDouble: s << "a number in [" << min << ", " << max << "]"; return s.str();
    case ParamType::kVec3: s << "a list of 3 numbers, each in [" << min << ", " << max << "]"; return s.str();
    case ParamType::kRotation: s << "[roll, pitch, yaw], each in [" << min << ", " << max << "]"; return s.str();
    case ParamType::kDurationS: s << "a duration in [" << min << ", " << max << "]"; return s.str();
  }
  return "?";
}

// True when the value at `target` (of `type`) lies in the declared range. A rotation is checked as the unit
// quaternion it lands in (its range bounds the written angles); a duration in microseconds against the
// range in seconds.
inline bool paramInRange(ParamType type, double min, double max, const char* choices, const void* target) {
  const auto in = [&](double v) { return v >= min && v <= max; };  // false for NaN
  switch (type) {
    case ParamType::kBool:
    case ParamType::kString: return true;
    case ParamType::kChoice: {
      const std::string v = *static_cast<const std::string*>(target);
      return !v.empty() && (std::string("|") + choices + "|").find("|" + v + "|") != std::string::npos;
    }
    case ParamType::kEnum: return !paramChoiceAt(choices, paramEnumValue(target)).empty();
    case ParamType::kInt: return in(*static_cast<const int*>(target));
    case ParamType::kSize: return in(static_cast<double>(*static_cast<const std::size_t*>(target)));
    case ParamType::kDouble: return in(*static_cast<const double*>(target));
    case ParamType::kVec3: {
      const auto& v = *static_cast<const Eigen::Vector3d*>(target);
      return in(v.x()) && in(v.y()) && in(v.z());
    }
    case ParamType::kRotation: {
      const auto& q = *static_cast<const Eigen::Quaterniond*>(target);
      return q.coeffs().allFinite() && std::abs(q.norm() - 1.0) < 1e-6;
    }
    case ParamType::kDurationS: {
      const std::int64_t us = *static_cast<const std::int64_t*>(target);
      return in(static_cast<double>(us) / 1e6);
    }
  }
  return false;
}

// Checks every declared field of `config` against its range; on the first one outside writes
// "<type_name>.<member> (<section>.<key>): must be <range> (<unit>)" and returns false.
template <typename Config>
bool checkParamRanges(std::span<const ParamDecl<Config>> table, Config config, const char* type_name,
                      const char* section, std::string* error) {
  for (const auto& p : table) {
    if (paramInRange(p.type, p.min, p.max, p.choices, p.field(config))) continue;
    if (error != nullptr) {
      *error = std::string(type_name) + "." + p.member + " (" + section + "." + p.key + "): must be " +
               paramRangeText(p.type, p.min, p.max, p.choices) + " (" + p.unit + ")";
    }
    return false;
  }
  return true;
}

}  // namespace deepnav
