#include "board/loop/live_loop.h"

#include "board/config/recording_options.h"

#include <chrono>

#include "drivers/clock/monotonic_clock.h"

namespace deepnav {

bool LiveLoop::init(const VehicleSetup& setup, const std::string& recording_path, std::string* error) {
  const BoardConfig& c = setup.config;
  LiveInputCapacities caps = c.buffers.inputs;
  caps.width_px = c.camera.width_px;
  caps.height_px = c.camera.height_px;
  caps.channels = c.camera.channels;
  if (!validateLiveInputCapacities(caps, error)) return false;
  if (!inputs_.allocate(caps) || !vision_results_.allocate(static_cast<std::size_t>(c.buffers.vision_results))) {
    if (error) *error = "loop: cannot allocate the input buffers (see buffers.* in the board file)";
    return false;
  }
  const TaskSpec table[] = {
      {"nav", c.loop.rate_hz, c.loop.budget_us, false},
      {"stats", 1, c.loop.budget_us, false},
      {"vision", static_cast<int>(c.camera.rate_hz + 0.5), c.loop.vision_budget_us, true},
  };
  if (!scheduler_.init(table, 3, c.loop.late_tick_tolerance, error)) return false;
  nav_task_ = scheduler_.findTask("nav");
  stats_task_ = scheduler_.findTask("stats");
  vision_task_ = scheduler_.findTask("vision");
  VisionPipelineConfig vision = visionConfig(setup);
  vision.stage_probe_for_test = vision_probe_;
  if (!vision_.init(vision, error)) return false;
  if (!feedback_.allocate(PoseHistory::kCapacity)) {
    if (error) *error = "loop: cannot allocate the nav-to-vision feedback ring";
    return false;
  }
  vision_context_.init(robotFromCamera(setup));
  recording_ = !recording_path.empty() && c.recording.enabled;
  sink_ = nullptr;
  if (recording_) {
    QueuedRecorder::MetadataList metadata = recordingMetadata(setup);
    metadata.insert(metadata.end(), extra_metadata_.begin(), extra_metadata_.end());
    if (!recorder_.start(recording_path, recordingOptions(c), metadata,
                         static_cast<std::size_t>(c.buffers.record), c.buffers.inputs.frames,
                         &inputs_.pool, error)) {
      return false;
    }
    sink_ = &recorder_;
  }
  return core_.init(setup, sink_, error);
}

bool LiveLoop::start(const LoopClock& clock, std::string* error) {
  if (running_.load()) {
    if (error) *error = "loop: already running";
    return false;
  }
  clock_ = clock;
  running_.store(true, std::memory_order_release);
  vision_thread_ = std::thread([this] { visionThread(); });
  loop_thread_ = std::thread([this] { loopThread(); });
  return true;
}

bool LiveLoop::stop(std::string* error) {
  running_.store(false, std::memory_order_release);
  if (loop_thread_.joinable()) loop_thread_.join();
  if (vision_thread_.joinable()) vision_thread_.join();
  return recording_ ? recorder_.stop(error) : true;
}

NavSolution LiveLoop::latest() const {
  std::lock_guard<std::mutex> lock(latest_mutex_);
  return latest_;
}

InputCounters LiveLoop::counters() const {
  std::lock_guard<std::mutex> lock(latest_mutex_);
  return counters_;
}

// Never blocks the loop: if a reader holds the lock, this tick's copy is skipped.
void LiveLoop::publish(const NavSolution& s) {
  std::unique_lock<std::mutex> lock(latest_mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  latest_ = s;
  counters_ = core_.counters();
}

// Consumes the oldest queued sample not newer than t_us (rings are each in time order, so a k-way merge
// of their fronts keeps the inputs in time order; a tie goes to the earlier ring of forEachSensorRing).
// False when nothing is due.
bool LiveLoop::consumeOldest(TimeUs t_us) {
  TimeUs best = t_us + 1;
  int which = -1, position = 0;
  inputs_.forEachSensorRing([&](const auto& ring) {
    if (const auto* f = ring.front(); f && f->t_us < best) {
      best = f->t_us;
      which = position;
    }
    ++position;
  });
  if (which < 0) return false;
  position = 0;
  inputs_.forEachSensorRing([&](auto& ring) {
    if (position++ != which) return;
    core_.consume(*ring.front());
    ring.pop();
  });
  return true;
}

void LiveLoop::runTick(TimeUs t_us) {
  while (consumeOldest(t_us)) {
  }
  // Vision results are late by nature: they carry their capture time and are fused at it.
  VisionResult v;
  while (vision_results_.tryPop(v)) core_.consume(v);
  const NavSolution& solution = core_.tick(t_us);
  feedback_.push(core_.feedback());  // full ring (vision stalled > 2.5 s): the oldest poses are lost
  publish(solution);
  if (observer_) observer_->onTick(solution, core_.counters());
}

std::uint64_t LiveLoop::inputsRefused() const {
  std::uint64_t refused = inputs_.frames.dropped();
  inputs_.forEachSensorRing([&refused](const auto& ring) { refused += ring.dropped(); });
  return refused;
}

void LiveLoop::loopThread() {
  if (thread_hook_) thread_hook_("nav");
  const TimeUs period = scheduler_.periodUs();
  TimeUs next_us = (clock_.toLoop(monotonicUs()) / period + 1) * period;
  for (std::uint64_t tick = 0; running_.load(std::memory_order_acquire); ++tick) {
    sleepUntilUs(clock_.toMono(next_us));
    const TimeUs start = monotonicUs();
    scheduler_.recordTickStart(next_us, clock_.toLoop(start));
    runTick(next_us);
    scheduler_.recordRun(nav_task_, monotonicUs() - start);
    if (scheduler_.due(stats_task_, tick) && recording_) recorder_.recordLoopStats(next_us, scheduler_.stats());
    next_us += period;
    // After an overrun, skip the ticks that are already past instead of bursting to catch up.
    const TimeUs now = clock_.toLoop(monotonicUs());
    if (next_us < now) next_us += ((now - next_us) / period + 1) * period;
  }
}

void LiveLoop::visionThread() {
  if (thread_hook_) thread_hook_("vision");
  while (running_.load(std::memory_order_acquire)) {
    int index = -1;
    if (!inputs_.frames.tryPop(index)) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      continue;
    }
    const StereoFrame& frame = inputs_.pool.frame(index);
    if (recording_) recorder_.recordFrame(frame, index);
    NavFeedback f;
    while (feedback_.tryPop(f)) vision_context_.push(f);
    VisionResult result;
    const TimeUs start = monotonicUs();
    const VisionContext context = vision_context_.contextAt(frame.t_us);
    vision_.process(frame, context, &result);  // never throws: a failing stage fails the pair
    vision_failures_.store(vision_.failedPairs(), std::memory_order_relaxed);
    const TimeUs elapsed = monotonicUs() - start;
    result.processing_us = static_cast<std::uint32_t>(elapsed);
    scheduler_.recordRun(vision_task_, elapsed);
    inputs_.pool.release(index);
    vision_results_.push(result);
    if (vision_hook_) vision_hook_(vision_.workspace(), context);
  }
}

}  // namespace deepnav
