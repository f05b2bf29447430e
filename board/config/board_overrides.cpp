#include "board/config/board_overrides.h"

#include <yaml-cpp/yaml.h>

#include "board/config/text_file.h"

namespace deepnav {
namespace {

bool setPath(YAML::Node root, const std::string& key, const std::string& value_text, std::string* error) {
  YAML::Node value;
  try {
    value = YAML::Load(value_text);
  } catch (const YAML::Exception& e) {
    if (error) *error = "override " + key + ": value is not valid YAML: " + e.msg;
    return false;
  }
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const std::size_t dot = key.find('.', start);
    parts.push_back(key.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  std::vector<YAML::Node> chain{root};
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    YAML::Node next = chain.back()[parts[i]];
    if (!next.IsDefined() || next.IsNull()) next = YAML::Node(YAML::NodeType::Map);
    if (!next.IsMap()) {
      if (error) *error = "override " + key + ": " + parts[i] + " is not a section";
      return false;
    }
    chain.back()[parts[i]] = next;
    chain.push_back(next);
  }
  chain.back()[parts.back()] = value;
  return true;
}

}  // namespace

bool applyBoardOverrides(const std::vector<std::string>& overrides, VehicleSetup* setup, std::string* error) {
  if (overrides.empty()) return true;
  YAML::Node root;
  try {
    root = setup->board_text.empty() ? YAML::Node(YAML::NodeType::Map) : YAML::Load(setup->board_text);
  } catch (const YAML::Exception& e) {
    if (error) *error = "board text: " + e.msg;
    return false;
  }
  if (root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  for (const std::string& o : overrides) {
    const std::size_t eq = o.find('=');
    if (eq == std::string::npos || eq == 0) {
      if (error) *error = "override '" + o + "': expected key=value";
      return false;
    }
    if (!setPath(root, o.substr(0, eq), o.substr(eq + 1), error)) return false;
  }
  YAML::Emitter out;
  out << root;
  BoardConfig config;
  if (!loadBoardConfigText(out.c_str(), "board with overrides", &config, error)) return false;
  // A calibration named on the command line is read from there (relative to the working directory): the
  // setup's text belongs to the old name.
  const std::string& calibration = config.camera.calibration_file;
  if (calibration.empty()) {
    setup->calibration_text.clear();
  } else if (calibration != setup->config.camera.calibration_file &&
             !readTextFile(calibration, "the stereo calibration (camera.calibration_file override)",
                           &setup->calibration_text, error)) {
    return false;
  }
  setup->config = config;
  setup->board_text = out.c_str();
  return buildSetupRectification("board with overrides", setup, error);
}

}  // namespace deepnav
