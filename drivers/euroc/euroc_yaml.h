#pragma once
#include <map>
#include <string>
#include <vector>

namespace deepnav {

// The subset of YAML that EuRoC/ASL sensor.yaml files use (OpenCV's "%YAML:1.0" dialect, which yaml-cpp
// refuses): `key: scalar`, `key: [a, b, ...]` (the list may span lines) and one level of nesting
// (`T_BS:` then indented `rows:`, `cols:`, `data:`, read as "T_BS.data"). Comments (#) and directives (%)
// are skipped. Every value keeps its line so that messages name "<path>:<line>: key '<key>' ...".
class EurocYaml {
 public:
  bool parse(const std::string& text, const std::string& path, std::string* error);
  bool load(const std::string& path, std::string* error);

  bool has(const std::string& key) const { return values_.count(key) != 0; }
  bool text(const std::string& key, std::string* out, std::string* error) const;
  bool number(const std::string& key, double* out, std::string* error) const;
  // A [..] list of exactly `count` finite numbers.
  bool numbers(const std::string& key, std::size_t count, std::vector<double>* out, std::string* error) const;

 private:
  struct Entry {
    std::string value;
    int line = 0;
  };
  const Entry* find(const std::string& key, std::string* error) const;
  bool failAt(const Entry& e, const std::string& key, const std::string& what, std::string* error) const;

  std::string path_;
  std::map<std::string, Entry> values_;
};

}  // namespace deepnav
