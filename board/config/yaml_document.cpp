#include "board/config/yaml_document.h"

#include <map>
#include <sstream>
#include <vector>

#include <yaml-cpp/eventhandler.h>

#include "base/fail.h"
#include "board/config/text_file.h"

namespace deepnav {
namespace {

std::string lineText(const YAML::Mark& mark) { return "line " + std::to_string(mark.line + 1); }

// Walks the parser's events keeping, for every open mapping, the scalar keys met so far: yaml-cpp's node
// tree has no duplicate check (a map lookup returns the first match).
class DuplicateKeyFinder final : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { value(mark, "~", false); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { value(mark, "", false); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t, const std::string& v) override {
    value(mark, v, true);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    open(mark, false);
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    open(mark, true);
  }
  void OnMapEnd() override { close(); }

  const std::string& problem() const { return problem_; }

 private:
  struct Level {
    bool is_map = false;
    bool expect_key = true;        // maps alternate key, value
    std::string path;              // dotted path of this node from the root
    std::string key;               // the key whose value is being read (maps)
    std::size_t index = 0;         // next element (sequences)
    std::map<std::string, int> lines;  // key -> 1-based line of its first occurrence
  };

  // The dotted path of the node that starts now (a value in the enclosing map or sequence).
  std::string childPath() const {
    if (stack_.empty()) return "";
    const Level& up = stack_.back();
    if (!up.is_map) return up.path + "[" + std::to_string(up.index) + "]";
    return up.path.empty() ? up.key : up.path + "." + up.key;
  }

  // A scalar (or null, alias) either is a map key, or completes a value.
  void value(const YAML::Mark& mark, const std::string& v, bool scalar) {
    if (stack_.empty()) return;
    Level& up = stack_.back();
    if (!up.is_map) {
      ++up.index;
      return;
    }
    if (!up.expect_key) {
      up.expect_key = true;
      return;
    }
    up.expect_key = false;
    up.key = scalar ? v : "";
    if (!scalar || !problem_.empty()) return;
    const auto [it, inserted] = up.lines.emplace(v, mark.line + 1);
    if (!inserted) {
      const std::string path = up.path.empty() ? v : up.path + "." + v;
      problem_ = lineText(mark) + ": key '" + path + "' repeats the one of line " + std::to_string(it->second) +
                 " (YAML keeps only one of them): remove one";
    }
  }

  void open(const YAML::Mark&, bool is_map) {
    Level next;
    next.is_map = is_map;
    next.path = childPath();
    if (!stack_.empty()) {
      Level& up = stack_.back();
      // A collection used as a key is skipped as a key (never declared by any of our schemas).
      if (up.is_map && up.expect_key) {
        up.expect_key = false;
        up.key = "";
      } else if (up.is_map) {
        up.expect_key = true;
      } else {
        ++up.index;
      }
    }
    stack_.push_back(std::move(next));
  }

  void close() {
    if (!stack_.empty()) stack_.pop_back();
  }

  std::vector<Level> stack_;
  std::string problem_;
};

}  // namespace

bool parseYamlDocument(const std::string& text, const std::string& name, YAML::Node* root, std::string* error) {
  try {
    std::istringstream in(text);
    YAML::Parser parser(in);
    DuplicateKeyFinder finder;
    parser.HandleNextDocument(finder);
    if (!finder.problem().empty()) return fail(error, name + ": " + finder.problem());
    DuplicateKeyFinder second;
    if (parser.HandleNextDocument(second)) {
      return fail(error, name + ": holds more than one YAML document (a second one after '---' or '...'); "
                               "one is expected: remove the separator or split the file");
    }
    *root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    return fail(error, name + ": not valid YAML (" + lineText(e.mark) + "): " + e.msg);
  }
  return true;
}

bool checkYamlKeysUnique(const std::string& text, const std::string& name, std::string* error) {
  DuplicateKeyFinder finder;
  try {
    std::istringstream in(text);
    YAML::Parser parser(in);
    while (finder.problem().empty() && parser.HandleNextDocument(finder)) {
    }
  } catch (const YAML::Exception&) {
    // what was scanned before the syntax error still counts
  }
  return finder.problem().empty() || fail(error, name + ": " + finder.problem());
}

bool loadYamlFile(const std::string& path, const std::string& what, std::string* text, YAML::Node* root,
                  std::string* error) {
  return readTextFile(path, what, text, error) && parseYamlDocument(*text, path, root, error);
}

}  // namespace deepnav
