#include "tools/sim/yaml_section.h"

#include <algorithm>
#include <sstream>

namespace deepnav::sim {

namespace {

std::string lineOf(const YAML::Node& node) {
  const YAML::Mark mark = node.Mark();
  return mark.line >= 0 ? " (line " + std::to_string(mark.line + 1) + ")" : "";
}

std::string formatNumber(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

void YamlReadErrors::fail(const std::string& message) {
  if (first_error.empty()) first_error = source_name + ": " + message;
}

YamlSection::YamlSection(const YAML::Node& node, std::string path, YamlReadErrors* errors)
    : node_(node.IsDefined() ? node : YAML::Node()), path_(std::move(path)), errors_(errors) {
  // An absent key comes back from yaml-cpp as an invalid node that throws on use: keep a null one instead.
  if (!node_.IsNull() && !node_.IsMap())
    errors_->fail("key '" + (path_.empty() ? std::string("<root>") : path_) + "' must be a map" + lineOf(node_));
}

std::string YamlSection::keyPath(const char* key) const { return path_.empty() ? key : path_ + "." + key; }

bool YamlSection::has(const char* key) const {
  const YAML::Node& map = node_;
  return map.IsMap() && map[key].IsDefined();
}

YAML::Node YamlSection::find(const char* key) {
  declared_.emplace_back(key);
  if (errors_->failed() || !node_.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
  const YAML::Node& map = node_;  // const operator[]: never inserts the key
  return map[key];
}

void YamlSection::rangeError(const char* key, const std::string& value, double min, double max, const char* unit) {
  errors_->fail("key '" + keyPath(key) + "' = " + value + " is out of range [" + formatNumber(min) + ", " +
                formatNumber(max) + "] " + unit);
}

void YamlSection::number(const char* key, double* out, double min, double max, const char* unit) {
  const YAML::Node value = find(key);
  if (!value.IsDefined()) return;
  double v = 0.0;
  if (!value.IsScalar() || !YAML::convert<double>::decode(value, v)) {
    errors_->fail("key '" + keyPath(key) + "' must be a number in " + unit + lineOf(value));
    return;
  }
  if (!(v >= min && v <= max)) return rangeError(key, value.Scalar(), min, max, unit);
  *out = v;
}

void YamlSection::integer(const char* key, int* out, int min, int max, const char* unit) {
  const YAML::Node value = find(key);
  if (!value.IsDefined()) return;
  int v = 0;
  if (!value.IsScalar() || !YAML::convert<int>::decode(value, v)) {
    errors_->fail("key '" + keyPath(key) + "' must be an integer in " + unit + lineOf(value));
    return;
  }
  if (v < min || v > max) return rangeError(key, value.Scalar(), min, max, unit);
  *out = v;
}

void YamlSection::boolean(const char* key, bool* out) {
  const YAML::Node value = find(key);
  if (!value.IsDefined()) return;
  bool v = false;
  if (!value.IsScalar() || !YAML::convert<bool>::decode(value, v)) {
    errors_->fail("key '" + keyPath(key) + "' must be true or false" + lineOf(value));
    return;
  }
  *out = v;
}

void YamlSection::text(const char* key, std::string* out) {
  const YAML::Node value = find(key);
  if (!value.IsDefined()) return;
  if (!value.IsScalar()) {
    errors_->fail("key '" + keyPath(key) + "' must be a string" + lineOf(value));
    return;
  }
  *out = value.Scalar();
}

int YamlSection::choice(const char* key, const std::vector<std::string>& allowed) {
  const YAML::Node value = find(key);
  if (!value.IsDefined()) return -1;
  const auto it = value.IsScalar() ? std::find(allowed.begin(), allowed.end(), value.Scalar()) : allowed.end();
  if (it != allowed.end()) return static_cast<int>(it - allowed.begin());
  std::string list;
  for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
  errors_->fail("key '" + keyPath(key) + "' = " + (value.IsScalar() ? value.Scalar() : "<not a string>") +
                " is not one of: " + list + lineOf(value));
  return -1;
}

template <std::size_t N>
void YamlSection::numbers(const char* key, std::array<double, N>* out, double min, double max, const char* unit) {
  const YAML::Node value = find(key);
  if (!value.IsDefined()) return;
  if (!value.IsSequence() || value.size() != N) {
    errors_->fail("key '" + keyPath(key) + "' must be a list of " + std::to_string(N) + " numbers in " + unit +
                  lineOf(value));
    return;
  }
  std::array<double, N> v{};
  for (std::size_t i = 0; i < N; ++i) {
    const std::string element = keyPath(key) + "[" + std::to_string(i) + "]";
    if (!value[i].IsScalar() || !YAML::convert<double>::decode(value[i], v[i])) {
      errors_->fail("key '" + element + "' must be a number in " + unit + lineOf(value));
      return;
    }
    if (!(v[i] >= min && v[i] <= max)) {
      errors_->fail("key '" + element + "' = " + value[i].Scalar() + " is out of range [" + formatNumber(min) +
                    ", " + formatNumber(max) + "] " + unit);
      return;
    }
  }
  *out = v;
}

template void YamlSection::numbers<2>(const char*, std::array<double, 2>*, double, double, const char*);
template void YamlSection::numbers<3>(const char*, std::array<double, 3>*, double, double, const char*);

YamlSection YamlSection::section(const char* key) {
  const YAML::Node value = find(key);
  return YamlSection(value, keyPath(key), errors_);
}

YAML::Node YamlSection::sequence(const char* key) { return find(key); }

void YamlSection::finish() {
  if (errors_->failed() || !node_.IsMap()) return;
  for (const auto& entry : node_) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "<non-scalar key>";
    if (std::find(declared_.begin(), declared_.end(), key) != declared_.end()) continue;
    std::string list;
    for (const std::string& d : declared_) list += (list.empty() ? "" : ", ") + d;
    errors_->fail("unknown key '" + keyPath(key.c_str()) + "'" + lineOf(entry.first) + "; allowed keys: " + list);
    return;
  }
}

}  // namespace deepnav::sim
