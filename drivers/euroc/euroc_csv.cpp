#include "drivers/euroc/euroc_csv.h"

#include <charconv>
#include <cmath>
#include <fstream>

#include "drivers/euroc/euroc_text.h"

namespace deepnav {
namespace {

std::string trim(const std::string& s) { return trimEurocBlanks(s); }

std::vector<std::string> splitCommas(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    out.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

bool parseTimestampNs(const std::string& text, std::int64_t* t_ns) {
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, *t_ns);
  return r.ec == std::errc() && r.ptr == end && *t_ns >= 0;
}

}  // namespace

bool readEurocCsv(const std::string& path, int columns, std::vector<EurocCsvRow>* rows, std::string* error) {
  rows->clear();
  std::ifstream in(path);
  if (!in) {
    if (error) *error = path + ": cannot open (missing data.csv?)";
    return false;
  }
  std::string text;
  int line = 0;
  while (std::getline(in, text)) {
    ++line;
    const std::string t = trim(text);
    if (t.empty() || t[0] == '#') continue;
    std::vector<std::string> fields = splitCommas(t);
    if (static_cast<int>(fields.size()) != columns) {
      return failAtLine(path, line, std::to_string(fields.size()) + " columns, expected " + std::to_string(columns), error);
    }
    EurocCsvRow row;
    row.line = line;
    if (!parseTimestampNs(fields[0], &row.t_ns)) {
      return failAtLine(path, line, "timestamp '" + fields[0] + "' is not a non-negative integer (ns)", error);
    }
    if (!rows->empty() && row.t_ns <= rows->back().t_ns) {
      return failAtLine(path, line, "timestamp " + fields[0] + " ns is not after the previous row's (line " +
                                  std::to_string(rows->back().line) + "): timestamps must increase",
                  error);
    }
    row.fields.assign(fields.begin() + 1, fields.end());
    rows->push_back(std::move(row));
  }
  return true;
}

bool eurocCsvNumbers(const std::string& path, const EurocCsvRow& row, std::vector<double>* out, std::string* error) {
  out->resize(row.fields.size());
  for (std::size_t i = 0; i < row.fields.size(); ++i) {
    const std::string& f = row.fields[i];
    char* end = nullptr;
    const double v = std::strtod(f.c_str(), &end);
    if (f.empty() || end != f.c_str() + f.size() || !std::isfinite(v)) {
      return failAtLine(path, row.line, "column " + std::to_string(i + 2) + " '" + f + "' is not a finite number", error);
    }
    (*out)[i] = v;
  }
  return true;
}

}  // namespace deepnav
