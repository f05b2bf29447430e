#pragma once
#include <array>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace deepnav::sim {

// The first error met while reading one file; later reads become no-ops once it is set.
struct YamlReadErrors {
  std::string source_name;  // the file, named in every message
  std::string first_error;
  bool failed() const { return !first_error.empty(); }
  void fail(const std::string& message);
};

// One YAML map being read against its schema. Each reader call declares a key (with its range and unit)
// and reads it if present; finish() then rejects any key nobody declared, listing the allowed ones.
// Paths in messages are dotted from the root: "dvl.max_altitude_m", "faults[0].params.std_ms".
class YamlSection {
 public:
  YamlSection(const YAML::Node& node, std::string path, YamlReadErrors* errors);

  void number(const char* key, double* out, double min, double max, const char* unit);
  void integer(const char* key, int* out, int min, int max, const char* unit);
  void boolean(const char* key, bool* out);
  void text(const char* key, std::string* out);
  // One of `allowed`; returns the index chosen, or -1 when absent or wrong.
  int choice(const char* key, const std::vector<std::string>& allowed);
  template <std::size_t N>
  void numbers(const char* key, std::array<double, N>* out, double min, double max, const char* unit);
  // A nested map (an absent key gives an empty section).
  YamlSection section(const char* key);
  // A sequence (an absent key gives a null node).
  YAML::Node sequence(const char* key);
  bool has(const char* key) const;

  void finish();
  const std::string& path() const { return path_; }
  std::string keyPath(const char* key) const;

 private:
  YAML::Node find(const char* key);
  void rangeError(const char* key, const std::string& value, double min, double max, const char* unit);

  YAML::Node node_;
  std::string path_;
  YamlReadErrors* errors_;
  std::vector<std::string> declared_;
};

}  // namespace deepnav::sim
