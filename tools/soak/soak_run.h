#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace deepnav::soak {

struct SoakOptions {
  std::vector<std::string> dives;       // recordings replayed in turn, back to back
  std::string board_path;               // empty: the board stored in each recording
  std::vector<std::string> overrides;   // board keys for every dive ("key=value")
  double minutes = 60.0;                // run whole dives until this much wall time has passed
  double speed = 4.0;                   // recording seconds per wall second
  int warmup_dives = 2;                 // RSS of these dives is the baseline
  double max_growth_kib = 1024.0;       // the limit on the growth after warm-up
  double sample_period_s = 0.2;         // RSS sampling period
  std::string scratch_dir;              // where each dive's recording goes (deleted after the dive)
  bool progress = true;
};

// One dive of the soak, through the threaded runtime.
struct SoakDive {
  int index = 0;
  std::string path;
  double dive_s = 0.0;    // recording time replayed
  double wall_s = 0.0;
  std::uint64_t ticks = 0, late_ticks = 0, nav_overruns = 0, vision_runs = 0, vision_overruns = 0;
  std::int64_t max_lateness_us = 0, nav_max_us = 0, vision_max_us = 0;
  std::uint64_t refused = 0;         // samples and frames refused by full rings or the frame pool
  std::uint64_t recorder_drops = 0;
  int final_stage = 0;
  double peak_rss_kib = 0.0;         // highest RSS sampled while the dive ran
  double end_rss_kib = 0.0;          // RSS after the dive's runtime was torn down
};

struct SoakResult {
  std::vector<SoakDive> dives;
  double wall_s = 0.0;
  double baseline_rss_kib = 0.0;     // highest RSS during the warm-up dives
  double after_rss_kib = 0.0;        // highest RSS after them
  double growth_kib = 0.0;           // rise of the dive peak RSS from the first to the second half after
                                     // warm-up: the lesser of the lowest peaks' and the highest peaks' rise
  double end_rss_slope_kib_per_h = 0.0;  // least-squares trend of end RSS over the post-warm-up dives
  bool growth_ok = false;
  std::string error;
};

// Replays the dives back to back through LiveLoop + ReplaySource (the vehicle's threaded runtime, the
// path of `deepnav replay --realtime` and `deepnav run`) on a loop clock `speed` times faster than real
// time, sampling the process's resident memory (/proc/self/status VmRSS). False on a dive that cannot run.
bool runSoak(const SoakOptions& options, SoakResult* result);

// The table printed at the end, and the same as JSON.
std::string formatSoakTable(const SoakOptions& options, const SoakResult& result);
std::string soakJson(const SoakOptions& options, const SoakResult& result);

// VmRSS of this process in KiB (0 when /proc is unavailable).
double residentKib();

}  // namespace deepnav::soak
