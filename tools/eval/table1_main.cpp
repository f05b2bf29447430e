// deepnav-table1: the paper's Table I on a simulated recording (tools/eval/README.md).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>

#include "tools/eval/table1.h"

int main(int argc, char** argv) {
  CLI::App app{"DexROV Table I: dense stereo and plane registration scored against the simulator's truth"};
  std::string recording, out_path;
  deepnav::eval::Table1Options o;
  o.progress = true;
  app.add_option("recording", recording, "simulated dive (deepnav-sim, with images and truth maps)")->required();
  app.add_option("--frames", o.max_frames, "stereo pairs to score (0 = all)")->check(CLI::NonNegativeNumber);
  app.add_option("--out", out_path, "write the table as JSON");
  app.add_option("--eval-from-s", o.eval_from_s, "score pairs captured from this time on (s)");
  app.add_option("--map-every", o.map_every, "stage-1 map: every n-th pair, never scored (0 = the board's vision.map_every_n_frames)")->check(CLI::NonNegativeNumber);
  app.add_option("--map-from-s", o.map_from_s, "stage-1 map: first capture time (s)");
  app.add_option("--map-to-s", o.map_to_s, "stage-1 map: end of the capture times (s, exclusive)");
  app.add_option("--max-disp", o.num_disparities, "disparity range at the matching size (0 = the board's vision.dense_disparities)")->check(CLI::Range(0, 256));
  app.add_option("--max-turn-deg", o.max_turn_deg, "registration rotation prior between consecutive pairs (0 = the board's)");
  app.add_option("--dump-dir", o.dump_dir, "write the first scored pair and its disparity maps as PNGs here");
  app.add_option("--set", o.overrides, "board override key=value on the stored board (repeatable)");
  app.add_option("--rows", o.rows, "rows to run, comma separated: gt,elas,sgbm,elas-filter,sgbm-filter (default all)");
  app.add_option("--registrations-csv", o.registrations_csv, "write one line per scored registration (errors, NEES)");
  app.add_flag("!--quiet", o.progress, "no progress on stderr");
  CLI11_PARSE(app, argc, argv);

  deepnav::eval::Table1Result result;
  std::string error;
  if (!deepnav::eval::runTable1(recording, o, &result, &error)) {
    std::fprintf(stderr, "deepnav-table1: %s\n", error.c_str());
    return 1;
  }
  std::fputs(deepnav::eval::table1Markdown(result).c_str(), stdout);
  if (!out_path.empty()) {
    std::ofstream out(out_path);
    out << deepnav::eval::table1Json(result);
    if (!out) {
      std::fprintf(stderr, "deepnav-table1: cannot write %s\n", out_path.c_str());
      return 1;
    }
  }
  return 0;
}
