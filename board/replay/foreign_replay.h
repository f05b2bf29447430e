#pragma once
#include <string>

#include "board/replay/bench_replay.h"

namespace deepnav {

// `deepnav replay --topics map.yaml --board board.yaml foreign.mcap|foreign.bag --out dir`: a ROS 2 MCAP or
// ROS 1 bag converted on the fly through the topic map (board/config/topic_map_file.h) and run through the
// loop and vision as a sensor log. The map's mountings become board overrides (before the command line's
// --set). The output recording is deepnav's own, inputs included, with the topic map and source file in
// its metadata "deepnav.foreign", so it replays bit for bit with a plain `deepnav replay`.
bool runForeignBenchReplay(const ReplayOptions& options, ReplaySummary* summary, std::string* error);

}  // namespace deepnav
