#pragma once
#include <cstdint>
#include <string>

#include "tools/sim/scenario.h"

namespace deepnav::sim {

struct DiveRecordOptions {
  std::string scenario_path;
  std::string out_path;
  std::string board_path;   // stored in the recording so that replays use the vehicle's board
  std::uint64_t seed = 1;
  bool progress = true;
  bool render = true;       // render the stereo pairs (false: navigation sensors only, much faster)
  bool truth_maps = true;   // record each pair's true depth and disparity maps (false: poses and marker ids
                            // only; a 7-minute dive then takes about half the disk)
};

struct DiveRecordSummary {
  std::uint64_t messages = 0;
  std::uint64_t camera_ticks = 0;
  std::uint64_t frames = 0;   // stereo pairs rendered and recorded
  double duration_s = 0.0;
};

// Runs the simulator over a scenario and writes every stream (sensors and ground truth) to a deepnav
// recording. False with a message naming the file or key on error.
bool recordDive(const DiveRecordOptions& options, DiveRecordSummary* summary, std::string* error);

// Writes the panel description (knowledge base) of a scenario's rendered panel.
bool writeScenarioPanel(const std::string& scenario_path, const std::string& out_path, std::string* error);

}  // namespace deepnav::sim
