// Every relative link of README.md and docs/*.md lands: the file exists, and an anchor (#...) names a
// heading of the target page, by GitHub's rule (lower case, punctuation dropped, spaces to hyphens,
// repeats suffixed -1, -2, ...). Links inside code (fenced blocks, `spans`) are not links.
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include "tests/support/source_paths.h"
#include "tests/support/temp_path.h"

namespace {

namespace fs = std::filesystem;

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

bool isFence(const std::string& line) {
  const auto first = line.find_first_not_of(' ');
  return first != std::string::npos && line.compare(first, 3, "```") == 0;
}

// The line with code spans blanked, so a `[a](b)` shown as code is not taken for a link.
std::string withoutCodeSpans(const std::string& line) {
  std::string out = line;
  bool in_code = false;
  for (char& c : out) {
    if (c == '`') {
      in_code = !in_code;
      c = ' ';
    } else if (in_code) {
      c = ' ';
    }
  }
  return out;
}

// GitHub's heading anchor: lower case; letters, digits, '-' and '_' kept, spaces to '-', rest dropped.
std::string slugOf(const std::string& heading) {
  std::string slug;
  for (unsigned char c : heading) {
    if (std::isalnum(c) || c == '-' || c == '_' || c >= 0x80) {
      slug += static_cast<char>(std::tolower(c));
    } else if (c == ' ') {
      slug += '-';
    }
  }
  return slug;
}

std::set<std::string> anchorsOf(const std::string& markdown) {
  std::set<std::string> anchors;
  std::map<std::string, int> seen;
  bool in_fence = false;
  for (const std::string& line : splitLines(markdown)) {
    if (isFence(line)) in_fence = !in_fence;
    if (in_fence || line.rfind('#', 0) != 0) continue;
    const auto text_start = line.find_first_not_of('#');
    if (text_start == std::string::npos || line[text_start] != ' ') continue;
    const std::string base = slugOf(line.substr(text_start + 1));
    const int n = seen[base]++;
    anchors.insert(n == 0 ? base : base + "-" + std::to_string(n));
  }
  return anchors;
}

// Targets of inline links and images, [text](target) and ![alt](target), outside code.
std::vector<std::string> linkTargets(const std::string& markdown) {
  std::vector<std::string> targets;
  bool in_fence = false;
  for (const std::string& raw : splitLines(markdown)) {
    if (isFence(raw)) in_fence = !in_fence;
    if (in_fence || raw.rfind("    ", 0) == 0) continue;  // fenced or indented code
    const std::string line = withoutCodeSpans(raw);
    for (auto at = line.find("]("); at != std::string::npos; at = line.find("](", at + 2)) {
      const auto end = line.find(')', at + 2);
      if (end == std::string::npos) break;
      std::string target = line.substr(at + 2, end - at - 2);
      target = target.substr(0, target.find(' '));  // drop a "title"
      targets.push_back(target);
    }
  }
  return targets;
}

bool isExternal(const std::string& target) {
  return target.find("://") != std::string::npos || target.rfind("mailto:", 0) == 0;
}

// One line per broken relative link of `page`: missing file, or anchor with no such heading.
std::vector<std::string> brokenLinks(const fs::path& page) {
  std::vector<std::string> broken;
  const std::string text = readFile(page);
  for (const std::string& target : linkTargets(text)) {
    if (target.empty() || isExternal(target)) continue;
    const auto hash = target.find('#');
    const std::string file_part = target.substr(0, hash);
    const fs::path file = file_part.empty() ? page : page.parent_path() / file_part;
    if (!fs::exists(file)) {
      broken.push_back(page.string() + ": " + target + ": no such file");
      continue;
    }
    if (hash == std::string::npos) continue;
    const std::string anchor = target.substr(hash + 1);
    if (!anchorsOf(readFile(file)).count(anchor)) {
      broken.push_back(page.string() + ": " + target + ": no heading with anchor #" + anchor);
    }
  }
  return broken;
}

std::vector<fs::path> documentationPages(const fs::path& root) {
  std::vector<fs::path> pages{root / "README.md"};
  for (const auto& entry : fs::directory_iterator(root / "docs")) {
    if (entry.path().extension() == ".md") pages.push_back(entry.path());
  }
  std::sort(pages.begin(), pages.end());
  return pages;
}

fs::path scratchDir() {
  const fs::path dir = fs::path(deepnav::testing::tempPath("docs_links"));
  fs::create_directories(dir / "docs");
  return dir;
}

void writeFile(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

}  // namespace

TEST(DocsLinks, EveryRelativeLinkOfTheReadmeAndDocsResolves) {
  const fs::path root = deepnav::testing::sourceDir();
  const auto pages = documentationPages(root);
  ASSERT_GE(pages.size(), 2u) << "README.md and docs/*.md expected under " << root;
  std::vector<std::string> broken;
  for (const auto& page : pages) {
    const auto b = brokenLinks(page);
    broken.insert(broken.end(), b.begin(), b.end());
  }
  std::string report;
  for (const auto& line : broken) report += line + "\n";
  EXPECT_TRUE(broken.empty()) << report;
}

TEST(DocsLinks, TheReadmeStaysShort) {
  // Issue 22: a README a newcomer reads in five minutes, at most about 15 KB; the rest lives in docs/.
  const auto size = fs::file_size(fs::path(deepnav::testing::sourceDir()) / "README.md");
  EXPECT_LE(size, 15u * 1024u) << "README.md is " << size << " bytes: move the detail into docs/";
}

TEST(DocsLinks, CheckerReportsAMissingFileAndAMissingAnchor) {
  const fs::path dir = scratchDir();
  writeFile(dir / "docs" / "b.md", "# B page\n\n## Main job: `tools/dive.sh`\n\n## Repeat\n\n## Repeat\n");
  writeFile(dir / "README.md",
            "# A\n\n[ok](docs/b.md) [ok](docs/b.md#main-job-toolsdivesh) [ok](docs/b.md#repeat-1)\n"
            "[self](#a) `[code](missing.md)` [ext](https://example.org/x.md)\n"
            "```\n[fenced](missing.md)\n```\n"
            "    [indented](missing.md)\n"
            "[gone](docs/missing.md) [bad anchor](docs/b.md#no-such) [bad self](#nope)\n");
  const auto broken = brokenLinks(dir / "README.md");
  ASSERT_EQ(broken.size(), 3u);
  EXPECT_NE(broken[0].find("docs/missing.md: no such file"), std::string::npos) << broken[0];
  EXPECT_NE(broken[1].find("docs/b.md#no-such: no heading"), std::string::npos) << broken[1];
  EXPECT_NE(broken[2].find("#nope: no heading"), std::string::npos) << broken[2];
  fs::remove_all(dir);
}
