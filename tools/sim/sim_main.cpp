#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>

#include "tools/sim/dive_recorder.h"

int main(int argc, char** argv) {
  CLI::App app{"deepnav-sim: simulated ROV dive around an oil & gas panel, written as a deepnav recording"};
  deepnav::sim::DiveRecordOptions o;
  std::string panel_out;
  app.add_option("--scenario", o.scenario_path, "scenario file (tools/sim/scenarios/*.yaml)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--out", o.out_path, "output recording (.mcap)");
  app.add_option("--write-panel", panel_out, "write the scenario's panel description (knowledge base) and exit");
  app.add_flag("!--no-images", o.render, "navigation sensors only: no stereo rendering");
  app.add_flag("!--no-truth-maps", o.truth_maps,
               "leave the per-pair true depth and disparity maps out (poses and marker ids stay): smaller files");
  app.add_option("--seed", o.seed, "random seed (same seed, same recording)");
  app.add_option("--board", o.board_path, "board of the simulated vehicle, stored in the recording")
      ->default_val(std::string(DEEPNAV_SOURCE_DIR) + "/board/sim/board.yaml")
      ->check(CLI::ExistingFile);
  CLI11_PARSE(app, argc, argv);
  std::string error;
  if (!panel_out.empty()) {
    if (!deepnav::sim::writeScenarioPanel(o.scenario_path, panel_out, &error)) {
      std::fprintf(stderr, "deepnav-sim: %s\n", error.c_str());
      return 1;
    }
    return 0;
  }
  if (o.out_path.empty()) {
    std::fprintf(stderr, "deepnav-sim: --out is required\n");
    return 2;
  }
  deepnav::sim::DiveRecordSummary summary;
  if (!deepnav::sim::recordDive(o, &summary, &error)) {
    std::fprintf(stderr, "deepnav-sim: %s\n", error.c_str());
    return 1;
  }
  std::printf("wrote %s: %.1f s, %llu messages, %llu stereo pairs\n", o.out_path.c_str(), summary.duration_s,
              static_cast<unsigned long long>(summary.messages), static_cast<unsigned long long>(summary.frames));
  return 0;
}
