#pragma once
#include <string>

#include <yaml-cpp/yaml.h>

namespace deepnav {

// Parses the text of one YAML input (board, panel, calibration target, simulator scenario) into *root,
// refusing what yaml-cpp accepts silently: a key repeated in one mapping (yaml-cpp keeps the first, so a
// later correction was ignored), and a second document (everything after `---` was ignored). False with
// one message "<name>: ..." naming the line and, for a repeat, the key's dotted path and both lines.
bool parseYamlDocument(const std::string& text, const std::string& name, YAML::Node* root, std::string* error);

// The repeated-key check of parseYamlDocument alone, for a text another parser reads (OpenCV's
// FileStorage keeps the first of two equal keys). Syntax errors are left to that parser.
bool checkYamlKeysUnique(const std::string& text, const std::string& name, std::string* error);

// readTextFile() (size-limited) then parseYamlDocument(); *text keeps what was read (e.g. for a recording).
bool loadYamlFile(const std::string& path, const std::string& what, std::string* text, YAML::Node* root,
                  std::string* error);

}  // namespace deepnav
