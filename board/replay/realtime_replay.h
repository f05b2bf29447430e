#pragma once
#include <string>

#include "board/replay/bench_replay.h"

namespace deepnav {

// Replays a recording at its recorded speed through the vehicle's threaded runtime (LiveLoop: nav loop
// thread, vision worker thread, recorder thread) fed by a ReplaySource driver thread, exactly as on a
// dive. The run is recorded to out_dir/live.mcap; that recording is then replayed on the bench, which
// checks that the threaded run is reproduced bit for bit and computes the metrics. The summary carries
// the live loop's timing statistics (late ticks, overruns).
bool runRealtimeReplay(const ReplayOptions& options, ReplaySummary* summary, std::string* error);

}  // namespace deepnav
