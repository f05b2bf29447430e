#pragma once
#include <atomic>
#include <cstdint>
#include <string>
#include <thread>
#include <utility>
#include <variant>
#include <vector>

#include "drivers/buffers/frame_pool.h"
#include "drivers/buffers/spsc_ring.h"
#include "drivers/recording/recording_writer.h"
#include "nav/types/loop_stats.h"

namespace deepnav {

// The live recorder: the loop (and the vision worker) hand records to lock-free queues, and a thread of
// its own writes them with a RecordingWriter, so the loop never waits for the disk. Frames stay in the
// FramePool (one reference held) until written. A full queue drops the record and counts it.
// Producers: one thread may call recordInput/recordSolution/recordLoopStats (the loop), another
// recordFrame (the camera side); each has its own queue.
class QueuedRecorder : public RecordSink {
 public:
  struct FrameRef {
    int pool_index = -1;
  };
  struct StatsRecord {
    TimeUs t_us = 0;
    LoopStats stats;
  };
  using Item = std::variant<InputSample, NavSolution, StatsRecord, FusionDiagnostic, EstimatorStates>;

  QueuedRecorder() = default;
  ~QueuedRecorder() { stop(nullptr); }
  QueuedRecorder(const QueuedRecorder&) = delete;
  QueuedRecorder& operator=(const QueuedRecorder&) = delete;

  using MetadataList = std::vector<std::pair<std::string, std::map<std::string, std::string>>>;

  // Opens the file, writes the metadata records, and starts the writer thread. pool may be null when
  // no frames are recorded.
  bool start(const std::string& path, const RecordingOptions& options, const MetadataList& metadata,
             std::size_t queue_capacity, std::size_t frame_queue_capacity, FramePool* pool, std::string* error);
  // Drains both queues, closes the file (summary and footer) and joins the thread.
  bool stop(std::string* error);

  void recordInput(const InputSample& sample) override;
  void recordSolution(const NavSolution& solution) override;
  void recordFusion(const FusionDiagnostic& diagnostic) override;
  void recordEstimatorStates(const EstimatorStates& states) override;
  void recordFrame(const StereoFrame& frame, int pool_index) override;
  void recordLoopStats(TimeUs t_us, const LoopStats& stats);

  std::uint64_t dropped() const { return queue_.dropped() + frames_.dropped(); }
  std::uint64_t writeFailures() const { return writer_.failures(); }

 private:
  void run();
  bool drainOnce();

  RecordingWriter writer_;
  SpscRing<Item> queue_;
  SpscRing<FrameRef> frames_;
  FramePool* pool_ = nullptr;
  std::thread thread_;
  std::atomic<bool> running_{false};
};

}  // namespace deepnav
