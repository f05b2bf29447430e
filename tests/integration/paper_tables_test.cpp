// tools/eval/paper_tables.py: several runs per name (one per seed, listed or globbed) are aggregated as
// mean ± sample standard deviation; absent figures print as n/a, not 0; the dead-reckoning run is a row.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

// A replay's summary.json with the figures the tables read (the replay writes the same keys).
std::string summaryJson(double odom_pos_m, const std::string& panel_error, double nees_in_band, int markers_fused) {
  std::ostringstream o;
  o << "{\"position_error_m\": {\"mean\": " << odom_pos_m << "}, \"orientation_error_deg\": {\"mean\": "
    << 10 * odom_pos_m << "},\n \"odom_error\": {\"whole\": {}, \"stage2\": null},\n \"panel_error\": " << panel_error
    << ",\n \"ate\": {\"position_rmse_m\": " << odom_pos_m / 2 << ", \"rotation_rmse_deg\": 0.5},\n"
    << " \"rpe\": {\"pairs\": 12, \"translation_percent\": {\"mean\": 1.5}, "
    << "\"rotation_deg_per_m\": {\"mean\": 0.25}},\n"
    << " \"nees\": {\"position\": {\"in_band_fraction\": " << nees_in_band
    << ", \"mean\": 3.0}, \"heading\": {\"in_band_fraction\": 0.9, \"mean\": 1.0}},\n"
    << " \"smoothness_m_a\": 0.99, \"stage2_at_s\": -1, \"vo\": {\"accepted\": 0, \"accepted_orb\": 0, "
    << "\"accepted_planes\": 0},\n \"markers\": {\"poses_accepted\": " << markers_fused << "},\n"
    << " \"dive_s\": 100.0, \"loop\": {\"tasks\": [{\"name\": \"nav\", \"runs\": 10000, \"mean_us\": 5.0}, "
    << "{\"name\": \"vision\", \"runs\": 1000, \"mean_us\": " << 200.0 * markers_fused << "}]},\n"
    << " \"modalities\": {\"dvl\": {\"offered\": 100, \"fused\": 90, \"rejected_gate\": 6, \"rejected_other\": 4}}}\n";
  return o.str();
}

void writeRun(const std::string& dir, const std::string& json) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/summary.json") << json;
}

struct Result {
  int status = -1;
  std::string out;
};
Result runTables(const std::string& args) {
  const std::string cmd = "/usr/bin/python3 " + deepnav::testing::sourceDir() + "/tools/eval/paper_tables.py " +
                          args + " 2>&1";
  Result r;
  std::FILE* pipe = ::popen(cmd.c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  while (std::fgets(buf, sizeof buf, pipe)) r.out += buf;
  r.status = ::pclose(pipe);
  return r;
}

std::string lineWith(const std::string& text, const std::string& a, const std::string& b) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.find(a) != std::string::npos && line.find(b) != std::string::npos) return line;
  }
  return "";
}

TEST(PaperTables, AggregatesSeedsAsMeanAndSampleStd) {
  // GIVEN two seeds of the dead-reckoning run (odom error 1 and 3 m, no panel estimate) and of T_L2
  // (0.1 and 0.3 m, panel-relative 0.02 and 0.04 m)
  const std::string root = ::testing::TempDir() + "paper_tables/";
  std::filesystem::remove_all(root);
  const std::string panel2 = "{\"whole\": {\"position_m\": {\"mean\": 0.02}, \"orientation_deg\": {\"mean\": 0.5}}, "
                             "\"stage2\": null}";
  const std::string panel4 = "{\"whole\": {\"position_m\": {\"mean\": 0.04}, \"orientation_deg\": {\"mean\": 0.7}}, "
                             "\"stage2\": null}";
  writeRun(root + "seed1/dr", summaryJson(1.0, "null", 0.5, 0));
  writeRun(root + "seed2/dr", summaryJson(3.0, "null", 0.7, 0));
  writeRun(root + "seed1/tl2", summaryJson(0.1, panel2, 0.8, 100));
  writeRun(root + "seed2/tl2", summaryJson(0.3, panel4, 0.9, 120));
  // WHEN tabled, the dr seeds by a glob and the tl2 seeds one by one
  const Result r = runTables("--run 'dr=" + root + "seed*/dr' --run tl2=" + root + "seed1/tl2 --run tl2=" + root +
                             "seed2/tl2 --json " + root + "tables.json");
  ASSERT_EQ(r.status, 0) << r.out;
  // THEN Table V has both rows over 2 seeds: mean ± sample std (sqrt(2) for 1 and 3), n/a for the
  // absent panel-relative error, the counts as means
  const std::string dr = lineWith(r.out, "dead reckoning", "| 2 | 2.000 ± 1.414 | 20.00 ± 14.14 | n/a | n/a |");
  EXPECT_FALSE(dr.empty()) << r.out;
  const std::string tl2 =
      lineWith(r.out, "T_L2", "| 2 | 0.200 ± 0.141 | 2.00 ± 1.41 | 0.030 ± 0.014 | 0.60 ± 0.14 |");
  EXPECT_FALSE(tl2.empty()) << r.out;
  EXPECT_NE(tl2.find("| 110 |"), std::string::npos) << tl2;
  // AND the vision worker's CPU over the dive (1000 runs of 20 and 24 ms in 100 s: 20 and 24 % of a core)
  EXPECT_NE(tl2.find("| 22 ± 3 |"), std::string::npos) << tl2;
  // AND the drift and consistency table: ATE half the odom error, NEES in-band share 0.60 ± 0.14
  EXPECT_FALSE(lineWith(r.out, "dead reckoning", "| 1.000 ± 0.707 | 0.50 ± 0.00 | 1.50 ± 0.00 | 0.250 ± 0.000 | "
                                                 "0.60 ± 0.14 |").empty())
      << r.out;
  // AND the per-modality counts (offered / fused / gate / other); absent modalities n/a
  EXPECT_FALSE(lineWith(r.out, "T_L2", "| 100 / 90 / 6 / 4 | n/a / n/a / n/a / n/a |").empty()) << r.out;
  // AND the JSON holds the same aggregates
  std::ifstream json_file(root + "tables.json");
  std::stringstream json;
  json << json_file.rdbuf();
  EXPECT_NE(json.str().find("\"std\": 1.4142135623730951"), std::string::npos);
  EXPECT_EQ(json.str().find("NaN"), std::string::npos);
}

TEST(PaperTables, AMissingRunDirectoryIsAnError) {
  const Result r = runTables("--run tl2=/nonexistent/run");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("--run tl2=/nonexistent/run"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace deepnav
