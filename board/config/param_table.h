#pragma once
#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "base/param_decl.h"

namespace YAML {
class Node;
}

namespace deepnav {

// A parameter is declared exactly once, in a table: key, type, unit, default, range, meaning.
// Loading a YAML file walks the table, so defaults, validation and documentation cannot drift apart.
// ParamType (base/param_decl.h) says how a value is written and where it lands. A module's own keys are
// declared next to its config struct (ParamDecl, e.g. nav/ekf/ekf_config.cpp) and joined to a file's
// table with appendModuleParams.
template <typename Config>
struct ParamSpec {
  const char* key;          // dotted path in the YAML file, e.g. "loop.rate_hz"
  ParamType type;
  const char* unit;         // "Hz", "m", "-" ...
  double min;               // inclusive range for kInt/kDouble/kVec3 (each element)
  double max;
  const char* default_text; // default as YAML text ("100", "zstd", "[0, 0, 0]"); nullptr: the field's initialiser
  const char* choices;      // kChoice: allowed values separated by '|'
  const char* doc;          // what it means
  void* (*field)(Config&);  // where the value lands (see ParamType)
};

// Type-erased walkers, implemented once in param_table.cpp.
struct ParamSpecView {
  std::string key;
  ParamType type;
  const char* unit;
  double min;
  double max;
  const char* default_text;  // nullptr: the value the target holds before loading (a module's initialiser)
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

// Joins a module's declared keys (ParamDecl) to a table, below `section` ("ekf" for "ekf.gravity_mps2"),
// bound to the module's config inside the file's config. Their defaults are the config's initialisers.
template <typename Module>
void appendModuleParams(std::span<const ParamDecl<Module>> decls, const char* section, Module& module,
                        std::vector<ParamSpecView>* views) {
  for (const auto& d : decls) {
    views->push_back({std::string(section) + "." + d.key, d.type, d.unit, d.min, d.max, nullptr, d.choices, d.doc,
                      d.field(module)});
  }
}

}  // namespace deepnav
