#pragma once
#include <string_view>

namespace deepnav {

// A small allocation-free JSON reader for flat sensor reports: it validates the syntax of a value
// while skipping it and hands out views of member values. Nesting is limited to kMaxDepth levels; string
// escapes are skipped, not decoded (sensor reports use plain keys and values).
struct JsonScan {
  static constexpr int kMaxDepth = 8;
  // True when `text` is exactly one JSON object (surrounding whitespace allowed).
  static bool isObject(std::string_view text);
  // The raw text of member `key` of object `object` (the first match).
  static bool member(std::string_view object, std::string_view key, std::string_view* value);
  // Array iteration: `*rest` starts as the array text; each call yields the next element.
  static bool arrayBegin(std::string_view array, std::string_view* rest);
  static bool arrayNext(std::string_view* rest, std::string_view* element);
  static bool number(std::string_view value, double* out);
  static bool boolean(std::string_view value, bool* out);
  static bool string(std::string_view value, std::string_view* out);  // contents without quotes
};

}  // namespace deepnav
