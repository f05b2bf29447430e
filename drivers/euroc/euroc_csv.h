#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace deepnav {

// One data row of an EuRoC/ASL data.csv: the timestamp (first column, ns) and the other columns as text.
struct EurocCsvRow {
  std::int64_t t_ns = 0;
  std::vector<std::string> fields;  // columns 2..n
  int line = 0;                     // 1-based line in the file, for messages
};

// Reads an EuRoC data.csv: '#' header lines, then rows of exactly `columns` comma-separated fields whose
// first is an integer timestamp in ns, strictly increasing. False with "<path>:<line>: ..." naming the
// first bad row (missing file, wrong column count, bad timestamp, timestamps out of order).
bool readEurocCsv(const std::string& path, int columns, std::vector<EurocCsvRow>* rows, std::string* error);

// The fields of a row as numbers; false with "<path>:<line>: column <n> ..." when one is not a finite number.
bool eurocCsvNumbers(const std::string& path, const EurocCsvRow& row, std::vector<double>* out, std::string* error);

}  // namespace deepnav
