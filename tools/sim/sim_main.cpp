#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>

#include "tools/sim/dive_recorder.h"

int main(int argc, char** argv) {
  CLI::App app{"deepnav-sim: simulated ROV dive around an oil & gas panel, written as a deepnav recording"};
  deepnav::sim::DiveRecordOptions o;
  app.add_option("--scenario", o.scenario_path, "scenario file (tools/sim/scenarios/*.yaml)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--out", o.out_path, "output recording (.mcap)")->required();
  app.add_option("--seed", o.seed, "random seed (same seed, same recording)");
  app.add_option("--board", o.board_path, "board of the simulated vehicle, stored in the recording")
      ->default_val(std::string(DEEPNAV_SOURCE_DIR) + "/board/sim/board.yaml")
      ->check(CLI::ExistingFile);
  CLI11_PARSE(app, argc, argv);
  deepnav::sim::DiveRecordSummary summary;
  std::string error;
  if (!deepnav::sim::recordDive(o, &summary, &error)) {
    std::fprintf(stderr, "deepnav-sim: %s\n", error.c_str());
    return 1;
  }
  std::printf("wrote %s: %.1f s, %llu messages\n", o.out_path.c_str(), summary.duration_s,
              static_cast<unsigned long long>(summary.messages));
  return 0;
}
