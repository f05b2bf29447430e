#include "drivers/parsers/json_scan.h"

#include <cctype>
#include <charconv>
#include <cmath>

namespace deepnav {
namespace {

size_t skipWs(std::string_view s, size_t i) {
  while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r')) ++i;
  return i;
}

// Index just past the value starting at i, or npos when the text is not a valid value.
size_t skipValue(std::string_view s, size_t i, int depth);

size_t skipString(std::string_view s, size_t i) {
  if (i >= s.size() || s[i] != '"') return std::string_view::npos;
  for (++i; i < s.size(); ++i) {
    if (s[i] == '\\') {
      ++i;
    } else if (s[i] == '"') {
      return i + 1;
    } else if (static_cast<unsigned char>(s[i]) < 0x20) {
      return std::string_view::npos;
    }
  }
  return std::string_view::npos;
}

size_t skipContainer(std::string_view s, size_t i, int depth, bool object) {
  const char close = object ? '}' : ']';
  if (depth >= JsonScan::kMaxDepth) return std::string_view::npos;
  i = skipWs(s, i + 1);
  if (i < s.size() && s[i] == close) return i + 1;
  while (i < s.size()) {
    if (object) {
      i = skipString(s, i);
      if (i == std::string_view::npos) return i;
      i = skipWs(s, i);
      if (i >= s.size() || s[i] != ':') return std::string_view::npos;
      i = skipWs(s, i + 1);
    }
    i = skipValue(s, i, depth + 1);
    if (i == std::string_view::npos) return i;
    i = skipWs(s, i);
    if (i >= s.size()) return std::string_view::npos;
    if (s[i] == close) return i + 1;
    if (s[i] != ',') return std::string_view::npos;
    i = skipWs(s, i + 1);
  }
  return std::string_view::npos;
}

size_t skipValue(std::string_view s, size_t i, int depth) {
  if (i >= s.size()) return std::string_view::npos;
  const char c = s[i];
  if (c == '{' || c == '[') return skipContainer(s, i, depth, c == '{');
  if (c == '"') return skipString(s, i);
  for (std::string_view lit : {"true", "false", "null"}) {
    if (s.substr(i, lit.size()) == lit) return i + lit.size();
  }
  const size_t start = i;
  while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '-' || s[i] == '+' || s[i] == '.' ||
                          s[i] == 'e' || s[i] == 'E')) {
    ++i;
  }
  return i > start ? i : std::string_view::npos;
}

}  // namespace

bool JsonScan::isObject(std::string_view text) {
  const size_t i = skipWs(text, 0);
  if (i >= text.size() || text[i] != '{') return false;
  const size_t end = skipValue(text, i, 0);
  return end != std::string_view::npos && skipWs(text, end) == text.size();
}

bool JsonScan::member(std::string_view o, std::string_view key, std::string_view* value) {
  size_t i = skipWs(o, 0);
  if (i >= o.size() || o[i] != '{') return false;
  i = skipWs(o, i + 1);
  while (i < o.size() && o[i] != '}') {
    const size_t key_end = skipString(o, i);
    if (key_end == std::string_view::npos) return false;
    const std::string_view k = o.substr(i + 1, key_end - i - 2);
    i = skipWs(o, key_end);
    if (i >= o.size() || o[i] != ':') return false;
    i = skipWs(o, i + 1);
    const size_t v_end = skipValue(o, i, 1);
    if (v_end == std::string_view::npos) return false;
    if (k == key) {
      *value = o.substr(i, v_end - i);
      return true;
    }
    i = skipWs(o, v_end);
    if (i < o.size() && o[i] == ',') i = skipWs(o, i + 1);
  }
  return false;
}

bool JsonScan::arrayBegin(std::string_view array, std::string_view* rest) {
  const size_t i = skipWs(array, 0);
  if (i >= array.size() || array[i] != '[') return false;
  *rest = array.substr(i + 1);
  return true;
}

bool JsonScan::arrayNext(std::string_view* rest, std::string_view* element) {
  size_t i = skipWs(*rest, 0);
  if (i < rest->size() && (*rest)[i] == ',') i = skipWs(*rest, i + 1);
  if (i >= rest->size() || (*rest)[i] == ']') return false;
  const size_t end = skipValue(*rest, i, 1);
  if (end == std::string_view::npos) return false;
  *element = rest->substr(i, end - i);
  *rest = rest->substr(end);
  return true;
}

bool JsonScan::number(std::string_view v, double* out) {
  double x = 0;
  const auto r = std::from_chars(v.data(), v.data() + v.size(), x);
  if (r.ec != std::errc() || r.ptr != v.data() + v.size() || !std::isfinite(x)) return false;
  *out = x;
  return true;
}

bool JsonScan::boolean(std::string_view v, bool* out) {
  if (v == "true" || v == "false") {
    *out = v == "true";
    return true;
  }
  return false;
}

bool JsonScan::string(std::string_view v, std::string_view* out) {
  if (v.size() < 2 || v.front() != '"' || v.back() != '"') return false;
  *out = v.substr(1, v.size() - 2);
  return true;
}

}  // namespace deepnav
