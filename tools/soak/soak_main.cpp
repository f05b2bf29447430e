// deepnav-soak: replays dives back to back through the vehicle's threaded runtime, faster than real time,
// and checks that resident memory stays flat after warm-up (tools/soak/README.md).
#include <cstdio>
#include <fstream>

#include <CLI/CLI.hpp>

#include "drivers/realtime/heap_policy.h"
#include "tools/soak/soak_run.h"

int main(int argc, char** argv) {
  deepnav::fixHeapPolicy();  // the vehicle binary's heap policy (board/main.cpp), so the soak measures it
  deepnav::soak::SoakOptions o;
  std::string json_path;
  CLI::App app{"deepnav-soak: dives back to back through the threaded runtime; resident memory and loop statistics"};
  app.add_option("dives", o.dives, "recordings (sensor logs) replayed in turn")->required()->check(CLI::ExistingFile);
  app.add_option("--minutes", o.minutes, "wall time: whole dives are replayed until it has passed")->check(CLI::Range(0.0, 10000.0));
  app.add_option("--speed", o.speed, "loop clock speed (recording seconds per wall second)")->check(CLI::Range(0.01, 100.0));
  app.add_option("--board", o.board_path, "board file (default: the board stored in each recording)");
  app.add_option("--set", o.overrides, "board key override KEY=VALUE, for every dive");
  app.add_option("--warmup-dives", o.warmup_dives, "dives whose peak RSS is the baseline")->check(CLI::Range(1, 1000));
  app.add_option("--max-growth-kib", o.max_growth_kib, "fail when the peak RSS after warm-up exceeds the baseline by this much");
  app.add_option("--scratch", o.scratch_dir, "directory of each dive's recording (deleted after the dive)");
  app.add_option("--json", json_path, "also write the result as JSON");
  app.add_flag("!--quiet", o.progress, "no per-dive progress lines");
  CLI11_PARSE(app, argc, argv);
  if (o.scratch_dir.empty()) o.scratch_dir = "/tmp/deepnav-soak";
  deepnav::soak::SoakResult r;
  const bool ran = deepnav::soak::runSoak(o, &r);
  std::printf("%s", deepnav::soak::formatSoakTable(o, r).c_str());
  if (!json_path.empty()) std::ofstream(json_path) << deepnav::soak::soakJson(o, r);
  if (!ran) {
    std::fprintf(stderr, "deepnav-soak: %s\n", r.error.c_str());
    return 2;
  }
  return r.growth_ok ? 0 : 1;
}
