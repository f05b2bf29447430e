// The soak's short version (tools/soak/README.md): deepnav-soak replays a short rendered dive back to back
// for one minute through the threaded runtime at 4x real time; after three warm-up dives the resident
// memory must stay flat (growth < 1 MiB), and every dive must run the loop and the vision worker.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "tests/support/test_dive.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

// Pairs the vision worker must get through per 15 s dive at 4x. A sanitized build's worker takes 10-20 times
// longer per pair (ASan at -O1 measured 340-470 ms), so there the check is only that it ran.
#if defined(DEEPNAV_SANITIZED)
constexpr std::uint64_t kMinVisionRuns = 1;
#else
constexpr std::uint64_t kMinVisionRuns = 20;
#endif

TEST(Soak, OneMinuteOfDivesBackToBackKeepsResidentMemoryFlat) {
  // GIVEN a rendered 15 s dive
  const std::string dive = testing::makeTestDive("soak", 15.0, 5, true);
  const std::string dir = testing::tempPath("soak");
  const std::string json = dir + ".json";
  // WHEN deepnav-soak replays it back to back for a minute
  const std::string cmd = deepnav::testing::binDir() + "/deepnav-soak " + dive +
                          " --minutes 1 --speed 4 --warmup-dives 3 --quiet --scratch " + dir + " --json " + json;
  const int status = std::system(cmd.c_str());
  // THEN it passes its own memory check, and the figures say why
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  const YAML::Node r = YAML::LoadFile(json);  // JSON is YAML
  EXPECT_TRUE(r["growth_ok"].as<bool>());
  EXPECT_LT(r["growth_kib"].as<double>(), 1024.0);
  EXPECT_GT(r["baseline_rss_kib"].as<double>(), 10000.0);  // it measured something
  const YAML::Node dives = r["dives"];
  ASSERT_GE(dives.size(), 6u);
  for (const YAML::Node& d : dives) {
    EXPECT_GT(d["ticks"].as<std::uint64_t>(), 100u);  // the loop ran (ticks already past are skipped under load)
    EXPECT_GE(d["vision_runs"].as<std::uint64_t>(), kMinVisionRuns);
    EXPECT_EQ(d["recorder_drops"].as<std::uint64_t>(), 0u);
  }
}

}  // namespace
}  // namespace deepnav
