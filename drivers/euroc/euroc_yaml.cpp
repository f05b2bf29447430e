#include "drivers/euroc/euroc_yaml.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "drivers/euroc/euroc_text.h"

namespace deepnav {
namespace {

std::string trim(const std::string& s) { return trimEurocBlanks(s); }

std::string withoutComment(const std::string& line) {
  const auto hash = line.find('#');
  return hash == std::string::npos ? line : line.substr(0, hash);
}

std::size_t indentOf(const std::string& line) {
  const auto b = line.find_first_not_of(" \t");
  return b == std::string::npos ? line.size() : b;
}

bool parseNumber(const std::string& s, double* v) {
  const std::string t = trim(s);
  char* end = nullptr;
  *v = std::strtod(t.c_str(), &end);
  return !t.empty() && end == t.c_str() + t.size() && std::isfinite(*v);
}

}  // namespace

bool EurocYaml::load(const std::string& path, std::string* error) {
  std::ifstream in(path);
  if (!in) {
    if (error) *error = path + ": cannot open (missing sensor.yaml?)";
    return false;
  }
  std::stringstream text;
  text << in.rdbuf();
  return parse(text.str(), path, error);
}

bool EurocYaml::parse(const std::string& text, const std::string& path, std::string* error) {
  path_ = path;
  values_.clear();
  std::istringstream in(text);
  std::string raw;
  std::string parent;  // the top-level key whose value is the indented block below it
  int line = 0;
  while (std::getline(in, raw)) {
    ++line;
    const std::string content = withoutComment(raw);
    const std::string t = trim(content);
    if (t.empty() || t[0] == '%' || t == "---") continue;
    const auto colon = t.find(':');
    if (colon == std::string::npos || colon == 0) {
      if (error) *error = path + ":" + std::to_string(line) + ": expected 'key: value', got '" + t + "'";
      return false;
    }
    const std::string key = trim(t.substr(0, colon));
    std::string value = trim(t.substr(colon + 1));
    const bool nested = indentOf(content) > 0;
    if (nested && parent.empty()) {
      if (error) *error = path + ":" + std::to_string(line) + ": key '" + key + "' is indented under no mapping";
      return false;
    }
    const int first_line = line;
    // A flow list continues until its closing bracket.
    if (!value.empty() && value[0] == '[') {
      while (value.find(']') == std::string::npos) {
        if (!std::getline(in, raw)) {
          if (error) *error = path + ":" + std::to_string(first_line) + ": key '" + key + "': list '[' never closed";
          return false;
        }
        ++line;
        value.push_back(' ');
        value.append(trim(withoutComment(raw)));
      }
    }
    const std::string full = nested ? parent + "." + key : key;
    if (values_.count(full)) {
      if (error)
        *error = path + ":" + std::to_string(first_line) + ": key '" + full + "' repeated (first on line " +
                 std::to_string(values_.at(full).line) + ")";
      return false;
    }
    values_[full] = Entry{value, first_line};
    if (!nested) parent = value.empty() ? key : std::string();
  }
  return true;
}

const EurocYaml::Entry* EurocYaml::find(const std::string& key, std::string* error) const {
  const auto it = values_.find(key);
  if (it != values_.end()) return &it->second;
  if (error) *error = path_ + ": key '" + key + "' missing";
  return nullptr;
}

bool EurocYaml::failAt(const Entry& e, const std::string& key, const std::string& what, std::string* error) const {
  if (error) *error = path_ + ":" + std::to_string(e.line) + ": key '" + key + "' " + what;
  return false;
}

bool EurocYaml::text(const std::string& key, std::string* out, std::string* error) const {
  const Entry* e = find(key, error);
  if (e == nullptr) return false;
  if (e->value.empty()) return failAt(*e, key, "is empty", error);
  *out = e->value;
  return true;
}

bool EurocYaml::number(const std::string& key, double* out, std::string* error) const {
  const Entry* e = find(key, error);
  if (e == nullptr) return false;
  if (!parseNumber(e->value, out)) return failAt(*e, key, "is '" + e->value + "', not a finite number", error);
  return true;
}

bool EurocYaml::numbers(const std::string& key, std::size_t count, std::vector<double>* out,
                        std::string* error) const {
  const Entry* e = find(key, error);
  if (e == nullptr) return false;
  const std::string& v = e->value;
  if (v.size() < 2 || v.front() != '[' || v.back() != ']') return failAt(*e, key, "is not a [..] list", error);
  out->clear();
  std::stringstream items(v.substr(1, v.size() - 2));
  std::string item;
  while (std::getline(items, item, ',')) {
    double x = 0.0;
    if (!parseNumber(item, &x)) {
      return failAt(*e, key, "element " + std::to_string(out->size()) + " '" + trim(item) + "' is not a finite number",
                    error);
    }
    out->push_back(x);
  }
  if (out->size() != count) {
    return failAt(*e, key, "has " + std::to_string(out->size()) + " numbers, expected " + std::to_string(count), error);
  }
  return true;
}

}  // namespace deepnav
