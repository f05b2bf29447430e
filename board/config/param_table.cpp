#include "board/config/param_table.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <yaml-cpp/yaml.h>

#include "nav/types/time.h"

namespace deepnav {
namespace {

std::string rangeText(const ParamSpecView& p) { return paramRangeText(p.type, p.min, p.max, p.choices); }

bool fail(std::string* error, const std::string& file, const ParamSpecView& p, const std::string& what) {
  if (error) {
    *error = file + ": key '" + p.key + "' " + what + "; allowed: " + rangeText(p) + " (" + p.unit + ")";
  }
  return false;
}

bool parseNumber(const YAML::Node& n, double* out) {
  if (!n.IsScalar()) return false;
  try {
    *out = n.as<double>();
  } catch (const YAML::Exception&) {
    return false;
  }
  return std::isfinite(*out);
}

bool inRange(const ParamSpecView& p, double v) { return v >= p.min && v <= p.max; }

std::string show(const YAML::Node& n) {
  std::ostringstream s;
  s << n;
  return s.str();
}

bool applyScalar(const ParamSpecView& p, const YAML::Node& n, const std::string& file, std::string* error) {
  switch (p.type) {
    case ParamType::kBool: {
      bool b = false;
      if (!n.IsScalar() || !YAML::convert<bool>::decode(n, b)) return fail(error, file, p, "is '" + show(n) + "'");
      *static_cast<bool*>(p.target) = b;
      return true;
    }
    case ParamType::kString:
      if (!n.IsScalar()) return fail(error, file, p, "is not a string");
      *static_cast<std::string*>(p.target) = n.Scalar();
      return true;
    case ParamType::kChoice: {
      const std::string v = n.IsScalar() ? n.Scalar() : std::string();
      std::string choices = std::string("|") + p.choices + "|";
      if (v.empty() || choices.find("|" + v + "|") == std::string::npos) {
        return fail(error, file, p, "is '" + show(n) + "'");
      }
      *static_cast<std::string*>(p.target) = v;
      return true;
    }
    case ParamType::kEnum: {
      const int index = paramChoiceIndex(p.choices, n.IsScalar() ? n.Scalar() : std::string());
      if (index < 0) return fail(error, file, p, "is '" + show(n) + "'");
      setParamEnumValue(p.target, index);
      return true;
    }
    case ParamType::kInt: {
      double v = 0;
      if (!parseNumber(n, &v) || std::floor(v) != v) return fail(error, file, p, "is '" + show(n) + "'");
      if (!inRange(p, v)) return fail(error, file, p, "is " + show(n) + ", out of range");
      *static_cast<int*>(p.target) = static_cast<int>(v);
      return true;
    }
    case ParamType::kSize: {
      double v = 0;
      if (!parseNumber(n, &v) || std::floor(v) != v) return fail(error, file, p, "is '" + show(n) + "'");
      // The declared range keeps v at or above 0 before the conversion (a size has no negative values).
      if (!inRange(p, v) || v < 0) return fail(error, file, p, "is " + show(n) + ", out of range");
      *static_cast<std::size_t*>(p.target) = static_cast<std::size_t>(v);
      return true;
    }
    case ParamType::kDouble: {
      double v = 0;
      if (!parseNumber(n, &v)) return fail(error, file, p, "is '" + show(n) + "'");
      if (!inRange(p, v)) return fail(error, file, p, "is " + show(n) + ", out of range");
      *static_cast<double*>(p.target) = v;
      return true;
    }
    case ParamType::kVec3:
    case ParamType::kRotation: {
      if (!n.IsSequence() || n.size() != 3) return fail(error, file, p, "is '" + show(n) + "'");
      Eigen::Vector3d v;
      for (std::size_t i = 0; i < 3; ++i) {
        if (!parseNumber(n[i], &v[static_cast<Eigen::Index>(i)]) || !inRange(p, v[static_cast<Eigen::Index>(i)])) {
          return fail(error, file, p, "is " + show(n) + ", element " + std::to_string(i) + " invalid");
        }
      }
      if (p.type == ParamType::kVec3) {
        *static_cast<Eigen::Vector3d*>(p.target) = v;
      } else {
        const Eigen::Vector3d rad = v * (M_PI / 180.0);
        *static_cast<Eigen::Quaterniond*>(p.target) = Eigen::AngleAxisd(rad.z(), Eigen::Vector3d::UnitZ()) *
                                                      Eigen::AngleAxisd(rad.y(), Eigen::Vector3d::UnitY()) *
                                                      Eigen::AngleAxisd(rad.x(), Eigen::Vector3d::UnitX());
      }
      return true;
    }
    case ParamType::kDurationS: {
      double v = 0;
      if (!parseNumber(n, &v)) return fail(error, file, p, "is '" + show(n) + "'");
      if (!inRange(p, v)) return fail(error, file, p, "is " + show(n) + ", out of range");
      *static_cast<TimeUs*>(p.target) = sToUs(v);
      return true;
    }
  }
  return false;
}

// Walks every map in the document and reports the first key no parameter declares.
bool findUnknownKey(const YAML::Node& node, const std::string& prefix, const std::set<std::string>& keys,
                    const std::set<std::string>& sections, const std::string& file, std::string* error) {
  for (const auto& kv : node) {
    const std::string key = prefix.empty() ? kv.first.Scalar() : prefix + "." + kv.first.Scalar();
    // `loop.rate_hz: 5` names a declared key but lookup() only walks nested maps: it would never apply.
    if (kv.first.Scalar().find('.') != std::string::npos) {
      if (error) {
        const std::string& written = kv.first.Scalar();
        const std::size_t dot = written.find('.');
        *error = file + ": key '" + written + "' (line " + std::to_string(kv.first.Mark().line + 1) +
                 ") is written with a dot; nest it instead: '" + written.substr(0, dot) + ":' then '  " +
                 written.substr(dot + 1) + ": ...'";
      }
      return false;
    }
    if (keys.count(key)) continue;
    if (sections.count(key) && kv.second.IsMap()) {
      if (!findUnknownKey(kv.second, key, keys, sections, file, error)) return false;
      continue;
    }
    if (error) {
      *error = file + ": unknown key '" + key + "'" +
               (sections.count(key) ? " (a section: expected a map)" : "") +
               "; run `deepnav config --list` for the declared parameters";
    }
    return false;
  }
  return true;
}

// Recursive so that no yaml-cpp Node is ever reassigned (Node::operator= rewrites the tree it refers to).
YAML::Node lookup(const YAML::Node& node, const std::string& dotted) {
  if (!node.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
  const std::size_t dot = dotted.find('.');
  if (dot == std::string::npos) return node[dotted];
  const YAML::Node child = node[dotted.substr(0, dot)];
  if (!child.IsDefined()) return YAML::Node(YAML::NodeType::Undefined);
  return lookup(child, dotted.substr(dot + 1));
}

}  // namespace

bool applyDefaults(const std::vector<ParamSpecView>& params, std::string* error) {
  for (const auto& p : params) {
    if (p.default_text == nullptr) continue;  // the module's initialiser, already in the target
    if (!applyScalar(p, YAML::Load(p.default_text), "<built-in defaults>", error)) return false;
  }
  return true;
}

bool applyParams(const std::vector<ParamSpecView>& params, const YAML::Node& root, const std::string& file,
                 std::string* error) {
  if (!root.IsDefined() || root.IsNull()) return true;
  if (!root.IsMap()) {
    if (error) *error = file + ": expected a map of sections at the top level";
    return false;
  }
  std::set<std::string> keys;
  std::set<std::string> sections;
  for (const auto& p : params) {
    const std::string key = p.key;
    keys.insert(key);
    for (std::size_t dot = key.find('.'); dot != std::string::npos; dot = key.find('.', dot + 1)) {
      sections.insert(key.substr(0, dot));
    }
  }
  if (!findUnknownKey(root, "", keys, sections, file, error)) return false;
  for (const auto& p : params) {
    const YAML::Node n = lookup(root, p.key);
    if (n.IsDefined() && !applyScalar(p, n, file, error)) return false;
  }
  return true;
}

namespace {

// The shortest text that reads back as the same double ("0.0001", "9.80665"); -0 written as 0.
std::string numberText(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v + 0.0);
  return std::string(buf, r.ptr);
}

std::string listText(const Eigen::Vector3d& v) {
  std::ostringstream s;
  s << '[' << numberText(v.x()) << ", " << numberText(v.y()) << ", " << numberText(v.z()) << ']';
  return s.str();
}

// A target's value written as its key is written in a file (a module default, for the documentation).
std::string valueText(const ParamSpecView& p) {
  switch (p.type) {
    case ParamType::kBool: return *static_cast<const bool*>(p.target) ? "true" : "false";
    case ParamType::kInt: return std::to_string(*static_cast<const int*>(p.target));
    case ParamType::kSize: return std::to_string(*static_cast<const std::size_t*>(p.target));
    case ParamType::kDouble: return numberText(*static_cast<const double*>(p.target));
    case ParamType::kString:
    case ParamType::kChoice: {
      const auto& v = *static_cast<const std::string*>(p.target);
      return v.empty() ? "''" : v;
    }
    case ParamType::kEnum: return paramChoiceAt(p.choices, paramEnumValue(p.target));
    case ParamType::kVec3: return listText(*static_cast<const Eigen::Vector3d*>(p.target));
    case ParamType::kRotation: {
      // [roll, pitch, yaw] of R = Rz(yaw) Ry(pitch) Rx(roll), as applyScalar composes it.
      const Eigen::Matrix3d R = static_cast<const Eigen::Quaterniond*>(p.target)->toRotationMatrix();
      const Eigen::Vector3d rpy(std::atan2(R(2, 1), R(2, 2)), std::asin(-R(2, 0)), std::atan2(R(1, 0), R(0, 0)));
      return listText(rpy * (180.0 / M_PI));
    }
    case ParamType::kDurationS: return numberText(static_cast<double>(*static_cast<const TimeUs*>(p.target)) / 1e6);
  }
  return "?";
}

// A Markdown table cell: a '|' of the text (the choices "zstd|lz4|none") would end the cell.
std::string markdownCell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::string describeParams(const std::vector<ParamSpecView>& params) {
  std::ostringstream s;
  s << "| key | type | unit | default | allowed | meaning |\n|---|---|---|---|---|---|\n";
  for (const auto& p : params) {
    // A kEnum is written as a choice, a kSize as an int: the file cannot tell them apart.
    static const char* kTypes[] = {"bool", "int", "double", "string", "choice", "vec3", "rotation", "duration",
                                   "choice", "int"};
    const std::string default_text = p.default_text != nullptr ? p.default_text : valueText(p);
    s << "| `" << p.key << "` | " << kTypes[static_cast<int>(p.type)] << " | " << p.unit << " | `"
      << default_text << "` | " << markdownCell(rangeText(p)) << " | " << markdownCell(p.doc) << " |\n";
  }
  return s.str();
}

}  // namespace deepnav
