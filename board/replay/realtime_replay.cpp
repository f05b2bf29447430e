#include "board/replay/realtime_replay.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "board/config/board_overrides.h"
#include "board/loop/live_loop.h"
#include "board/replay/output_file.h"
#include "drivers/clock/monotonic_clock.h"
#include "drivers/replay/replay_source.h"

namespace deepnav {
namespace {

constexpr TimeUs kStartDelayUs = 200'000;  // time for the threads to start before the first sample
constexpr TimeUs kDrainUs = 500'000;       // let the loop consume the last samples and vision results

}  // namespace

bool runRealtimeReplay(const ReplayOptions& o, ReplaySummary* summary, std::string* error) {
  RecordingReader reader;
  if (!reader.open(o.input_path, error)) return false;
  VehicleSetup setup;
  if (!loadReplaySetup(o.board_path, reader, o.input_path, &setup, error) ||
      !applyBoardOverrides(o.overrides, &setup, error)) {
    return false;
  }
  if (!prepareOutputDir(o.out_dir, error)) return false;
  const std::string live_path = o.out_dir + "/live.mcap";
  auto loop = std::make_unique<LiveLoop>();
  loop->setVisionStageProbeForTest(o.vision_stage_probe);
  if (!loop->init(setup, live_path, error)) return false;
  ReplaySource source;
  if (!source.open(o.input_path, error)) {
    if (error && reader.truncated() && !reader.warnings().empty()) *error += " (" + reader.warnings().front() + ")";
    return false;
  }
  const TimeUs offset = source.firstTimeUs() - (monotonicUs() + kStartDelayUs);
  if (!loop->start(offset, error)) return false;
  source.start(&loop->inputs(), offset);
  TimeUs next_report = source.firstTimeUs();
  while (!source.finished() || monotonicUs() + offset < source.lastTimeUs() + kDrainUs) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    const TimeUs t = monotonicUs() + offset;
    if (o.progress && t >= next_report) {
      std::fprintf(stderr, "replay (real time): %.0f / %.0f s\n", usToS(t - source.firstTimeUs()),
                   usToS(source.lastTimeUs() - source.firstTimeUs()));
      next_report += 10 * kUsPerS;
    }
  }
  source.stop();
  if (!loop->stop(error)) return false;
  if (source.pushed() == 0) {
    if (error) *error = replayNoDataError(o.input_path, reader);
    return false;
  }
  const LoopStats live_stats = loop->stats();
  const std::uint64_t drops = loop->recorderDrops() + source.refused();
  const std::uint64_t vision_failures = loop->visionFailures();
  ReplayOptions bench = o;
  bench.input_path = live_path;
  bench.board_path.clear();
  bench.rerun = false;
  bench.realtime = false;
  if (!runBenchReplay(bench, summary, error)) return false;
  summary->loop = live_stats;
  summary->vision_failures = vision_failures;  // the bench pass re-runs no vision: the live count
  if (vision_failures > 0) {
    summary->warnings.push_back(std::to_string(vision_failures) + " stereo pairs skipped: a vision stage threw");
  }
  if (!source.error().empty()) summary->warnings.push_back(source.error());
  if (drops > 0) summary->warnings.push_back(std::to_string(drops) + " samples or records refused by full queues");
  // Ground truth is not a loop input, so the live recording has none: take it from the original.
  summary->truth.clear();
  reader.forEach(
      true,
      [&](const ReplayEvent& e) {
        if (e.kind == ReplayEvent::Kind::kTruth) {
          summary->truth.push_back({usToS(e.t_us), e.truth.p_robot_in_odom_m, e.truth.q_odom_robot});
        }
        return true;
      },
      error);
  if (!summary->truth_T_odom_panel) {
    summary->truth_T_odom_panel = truthPanelFromMetadata(reader.metadata(kTruthPanelMetadata), nullptr);
  }
  computeReplayMetrics(summary);
  return writeReplayOutputs(o.out_dir, *summary, error);
}

}  // namespace deepnav
