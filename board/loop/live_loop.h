#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <thread>

#include "board/config/board_config.h"
#include "board/loop/nav_core.h"
#include "board/loop/scheduler.h"
#include "drivers/buffers/live_inputs.h"
#include "drivers/clock/loop_clock.h"
#include "drivers/recording/queued_recorder.h"
#include "vision/pipeline/vision_pipeline.h"

namespace deepnav {

// Sees every tick's solution on the loop thread, right after the tick (outputs hang here). It must not
// block, allocate or throw: copy what it needs and return.
class TickObserver {
 public:
  virtual ~TickObserver() = default;
  virtual void onTick(const NavSolution& solution, const InputCounters& counters) = 0;
};

// The vehicle's runtime: a fixed-rate nav loop thread, a vision worker thread and the recorder thread,
// around one NavCore. Drivers (live or replay) push into inputs(); the loop merges the rings in time
// order every tick. Everything is allocated in init(); the steady state neither allocates, blocks on
// I/O nor throws.
class LiveLoop {
 public:
  LiveLoop() = default;
  ~LiveLoop() { stop(nullptr); }
  LiveLoop(const LiveLoop&) = delete;
  LiveLoop& operator=(const LiveLoop&) = delete;

  // Before init(): one more metadata record for the recording (e.g. deepnav.workspace: the run started from
  // a saved workspace, which its stage machine knows and a reproduction must too).
  void addRecordingMetadata(const std::string& name, const std::map<std::string, std::string>& values) {
    extra_metadata_.push_back({name, values});
  }
  // Before init(), bench and tests only: VisionPipelineConfig::stage_probe_for_test of the vision worker.
  void setVisionStageProbeForTest(void (*probe)(VisionStage stage)) { vision_probe_ = probe; }
  // recording_path empty: no recording.
  bool init(const VehicleSetup& setup, const std::string& recording_path, std::string* error);
  LiveInputs& inputs() { return inputs_; }

  // Both are set before start(). The observer sees every tick (nullptr: none). The thread hook runs once
  // at the start of the loop thread ("nav") and of the vision worker ("vision"), on that thread, e.g. to
  // set its scheduling policy and CPU affinity.
  void setTickObserver(TickObserver* observer) { observer_ = observer; }
  void setThreadStartHook(std::function<void(const char* thread_name)> hook) { thread_hook_ = std::move(hook); }
  // Set before start(): runs on the vision worker after each pair (its result already handed to the
  // loop) with the workspace map and the pair's navigation context, e.g. to save the stage-1 map once
  // stage 2 is entered (board/service/workspace_state.h). It may do a little file I/O: never on the loop.
  void setVisionPairHook(std::function<void(const WorkspaceModel&, const VisionContext&)> hook) {
    vision_hook_ = std::move(hook);
  }
  // Between init() and start(): the vision pipeline's workspace map (to restore a saved one into), and
  // telling the stage machine a saved workspace was restored (stage 2 once the panel is fixed again).
  WorkspaceModel& workspace() { return vision_.workspace(); }
  void setWorkspaceRestored() { core_.setWorkspaceRestored(true); }

  // Starts the threads. The loop's clock is t_us = monotonicUs() + clock_offset_us (0 on the vehicle; a
  // replay maps the recording's clock onto now).
  bool start(TimeUs clock_offset_us, std::string* error) { return start(LoopClock{clock_offset_us}, error); }
  // The same on any mapping of the monotonic clock, e.g. a replay faster than real time (tools/soak).
  bool start(const LoopClock& clock, std::string* error);
  // Stops the threads after the current tick, drains the recorder and closes the recording.
  bool stop(std::string* error);

  // The body of one loop tick at t_us: merge the input rings in time order, fuse the vision results, tick
  // the core, publish. The loop thread calls it; tests and benchmarks drive it directly when start() was
  // not called.
  void runTick(TimeUs t_us);

  LoopStats stats() const { return scheduler_.stats(); }
  NavSolution latest() const;
  InputCounters counters() const;
  std::uint64_t recorderDrops() const { return recorder_.dropped(); }
  std::uint64_t recorderWriteFailures() const { return recording_ ? recorder_.writeFailures() : 0; }
  // Samples and frames refused by full input rings or an exhausted frame pool (a driver outran the loop).
  std::uint64_t inputsRefused() const;
  // Stereo pairs the vision worker gave up because a stage threw (VisionPipeline::failedPairs()); each
  // was handed to the loop as frame_ok = false. Readable from any thread.
  std::uint64_t visionFailures() const { return vision_failures_.load(std::memory_order_relaxed); }

 private:
  void loopThread();
  void visionThread();
  bool consumeOldest(TimeUs t_us);
  void publish(const NavSolution& s);

  LiveInputs inputs_;
  SpscRing<VisionResult> vision_results_;
  SpscRing<NavFeedback> feedback_;          // loop thread -> vision worker, one per tick
  VisionContextSource vision_context_;      // vision worker only
  QueuedRecorder recorder_;
  RecordSink* sink_ = nullptr;
  NavCore core_;
  VisionPipeline vision_;
  Scheduler scheduler_;
  int nav_task_ = -1, stats_task_ = -1, vision_task_ = -1;
  LoopClock clock_;
  std::atomic<bool> running_{false};
  std::atomic<std::uint64_t> vision_failures_{0};
  std::thread loop_thread_, vision_thread_;
  mutable std::mutex latest_mutex_;  // guards latest_ and counters_ copies for readers off the loop
  NavSolution latest_;
  InputCounters counters_;
  bool recording_ = false;
  TickObserver* observer_ = nullptr;
  std::function<void(const char*)> thread_hook_;
  std::function<void(const WorkspaceModel&, const VisionContext&)> vision_hook_;
  QueuedRecorder::MetadataList extra_metadata_;
  void (*vision_probe_)(VisionStage stage) = nullptr;
};

}  // namespace deepnav
