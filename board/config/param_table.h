#pragma once
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace YAML {
class Node;
}

namespace deepnav {

// A parameter is declared exactly once, in a table: key, type, unit, default, range, meaning.
// Loading a YAML file walks the table, so defaults, validation and documentation cannot drift apart.
// kVec3 lands in an Eigen::Vector3d; kRotation is written [roll, pitch, yaw] in degrees (ZYX, as a
// mounting rotation is measured) and lands in an Eigen::Quaterniond; kDurationS is written in seconds
// and lands in a TimeUs (int64 microseconds).
enum class ParamType { kBool, kInt, kDouble, kString, kChoice, kVec3, kRotation, kDurationS };

template <typename Config>
struct ParamSpec {
  const char* key;          // dotted path in the YAML file, e.g. "loop.rate_hz"
  ParamType type;
  const char* unit;         // "Hz", "m", "-" ...
  double min;               // inclusive range for kInt/kDouble/kVec3 (each element)
  double max;
  const char* default_text; // default as YAML text ("100", "zstd", "[0, 0, 0]")
  const char* choices;      // kChoice: allowed values separated by '|'
  const char* doc;          // what it means
  void* (*field)(Config&);  // where the value lands (see ParamType)
};

// Type-erased walkers, implemented once in param_table.cpp.
struct ParamSpecView {
  const char* key;
  ParamType type;
  const char* unit;
  double min;
  double max;
  const char* default_text;
  const char* choices;
  const char* doc;
  void* target;
};

// Applies a YAML document (already parsed) to the targets. On the first problem returns false and sets
// *error to one message naming the file, the key and what is allowed. Unknown keys are rejected.
bool applyParams(const std::vector<ParamSpecView>& params, const YAML::Node& root, const std::string& file,
                 std::string* error);

// Sets every target to its declared default.
bool applyDefaults(const std::vector<ParamSpecView>& params, std::string* error);

// A Markdown table of every parameter (for `deepnav config --list` and docs/configuration.md).
std::string describeParams(const std::vector<ParamSpecView>& params);

template <typename Config, std::size_t N>
std::vector<ParamSpecView> bindParams(const std::array<ParamSpec<Config>, N>& table, Config& config) {
  std::vector<ParamSpecView> views;
  views.reserve(N);
  for (const auto& p : table) {
    views.push_back({p.key, p.type, p.unit, p.min, p.max, p.default_text, p.choices, p.doc, p.field(config)});
  }
  return views;
}

}  // namespace deepnav
