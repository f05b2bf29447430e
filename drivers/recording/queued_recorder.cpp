#include "drivers/recording/queued_recorder.h"

#include <chrono>

namespace deepnav {

bool QueuedRecorder::start(const std::string& path, const RecordingOptions& options, const MetadataList& metadata,
                           std::size_t queue_capacity, std::size_t frame_queue_capacity, FramePool* pool,
                           std::string* error) {
  if (!queue_.allocate(queue_capacity) || !frames_.allocate(frame_queue_capacity)) {
    if (error) *error = "recorder: cannot allocate its queues";
    return false;
  }
  pool_ = pool;
  if (!writer_.open(path, options, error)) return false;
  for (const auto& [name, values] : metadata) writer_.recordMetadata(name, values);
  running_.store(true, std::memory_order_release);
  thread_ = std::thread([this] { run(); });
  return true;
}

bool QueuedRecorder::stop(std::string* error) {
  if (!thread_.joinable()) return true;
  running_.store(false, std::memory_order_release);
  thread_.join();
  while (drainOnce()) {
  }
  return writer_.close(error);
}

void QueuedRecorder::recordInput(const InputSample& sample) { queue_.push(Item(sample)); }

void QueuedRecorder::recordSolution(const NavSolution& solution) { queue_.push(Item(solution)); }

void QueuedRecorder::recordFusion(const FusionDiagnostic& diagnostic) { queue_.push(Item(diagnostic)); }
void QueuedRecorder::recordEstimatorStates(const EstimatorStates& states) { queue_.push(Item(states)); }

void QueuedRecorder::recordLoopStats(TimeUs t_us, const LoopStats& stats) {
  queue_.push(Item(StatsRecord{t_us, stats}));
}

void QueuedRecorder::recordFrame(const StereoFrame& /*frame*/, int pool_index) {
  if (!pool_ || pool_index < 0) return;
  pool_->addRef(pool_index);
  if (!frames_.push(FrameRef{pool_index})) pool_->release(pool_index);
}

// Writes what is queued; frames first when both wait, in the order they were captured.
bool QueuedRecorder::drainOnce() {
  bool any = false;
  FrameRef f;
  while (frames_.tryPop(f)) {
    writer_.recordFrame(pool_->frame(f.pool_index), f.pool_index);
    pool_->release(f.pool_index);
    any = true;
  }
  while (const Item* item = queue_.front()) {
    if (const auto* in = std::get_if<InputSample>(item)) writer_.recordInput(*in);
    else if (const auto* sol = std::get_if<NavSolution>(item)) writer_.recordSolution(*sol);
    else if (const auto* fusion = std::get_if<FusionDiagnostic>(item)) writer_.recordFusion(*fusion);
    else if (const auto* states = std::get_if<EstimatorStates>(item)) writer_.recordEstimatorStates(*states);
    else {
      const auto& st = std::get<StatsRecord>(*item);
      writer_.recordLoopStats(st.t_us, st.stats);
    }
    queue_.pop();
    any = true;
  }
  return any;
}

void QueuedRecorder::run() {
  while (running_.load(std::memory_order_acquire)) {
    if (!drainOnce()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

}  // namespace deepnav
