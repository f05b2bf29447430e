#pragma once
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/temp_path.h"
#include "tools/sim/dive_recorder.h"
#include "tests/support/source_paths.h"

namespace deepnav::testing {

// Writes a simulated dive of the default scenario shortened to duration_s, and returns its path.
// edits: {"key: default value" as written in default.yaml, "key: new value"} applied to its text.
inline std::string makeTestDive(const std::string& name, double duration_s, std::uint64_t seed = 7,
                                bool render = true,
                                const std::vector<std::pair<std::string, std::string>>& edits = {}) {
  std::ifstream in(deepnav::testing::sourceDir() + "/tools/sim/scenarios/default.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const std::string key = "duration_s: 120.0";
  const auto at = yaml.find(key);
  if (at != std::string::npos) yaml.replace(at, key.size(), "duration_s: " + std::to_string(duration_s));
  for (const auto& [from, to] : edits) {
    const auto where = yaml.find(from);
    EXPECT_NE(where, std::string::npos) << "default.yaml has no '" << from << "'";
    if (where != std::string::npos) yaml.replace(where, from.size(), to);
  }
  const std::string scenario = tempPath(name) + ".yaml";
  std::ofstream(scenario) << yaml;
  sim::DiveRecordOptions o;
  o.scenario_path = scenario;
  o.out_path = tempPath(name) + ".mcap";
  o.board_path = deepnav::testing::sourceDir() + "/board/sim/board.yaml";
  o.seed = seed;
  o.progress = false;
  o.render = render;
  sim::DiveRecordSummary summary;
  std::string error;
  EXPECT_TRUE(sim::recordDive(o, &summary, &error)) << error;
  return o.out_path;
}

}  // namespace deepnav::testing
