// docs/configuration.md holds the board parameter table exactly as `deepnav config --list` prints it
// (describeBoardParams), between two markers; the page says how to regenerate it.
#include "board/config/board_config.h"
#include "tests/support/source_paths.h"

#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace {

const char* const kBegin = "<!-- BEGIN config-list -->\n";
const char* const kEnd = "<!-- END config-list -->\n";

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(DocsConfiguration, ParameterTableIsWhatConfigListPrints) {
  const std::string path = deepnav::testing::sourceDir() + "/docs/configuration.md";
  const std::string page = readFile(path);
  const auto begin = page.find(kBegin);
  const auto end = page.find(kEnd);
  ASSERT_NE(begin, std::string::npos) << path << " lacks the line " << kBegin;
  ASSERT_NE(end, std::string::npos) << path << " lacks the line " << kEnd;
  ASSERT_LT(begin, end);
  const auto table_start = begin + std::string(kBegin).size();
  const std::string table = page.substr(table_start, end - table_start);
  EXPECT_EQ(table, deepnav::describeBoardParams())
      << path << " differs from `deepnav config --list`: regenerate it as the page says (section "
      << "'Parameter table')";
}
