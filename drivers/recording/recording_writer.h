#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "drivers/mcap/writer.h"
#include "drivers/recording/frame_truth.h"
#include "drivers/recording/record_sink.h"
#include "drivers/recording/topics.h"
#include "nav/types/loop_stats.h"
#include "nav/types/truth_sample.h"

namespace deepnav {

struct RecordingOptions {
  std::string compression = "zstd";  // zstd | lz4 | none
  double chunk_max_duration_s = 1.0;
  int chunk_size_kib = 4096;
  int image_width_px = 688;           // sizes the encode buffer: one image must fit without growing
  int image_height_px = 516;
  int image_channels = 1;
  bool record_images = true;
  bool truth_maps = false;            // simulator: room for the float depth map of recordFrameTruth()
};

// Writes a deepnav recording: one MCAP channel per topic (topics.h), ROS 2 schemas, CDR messages.
// Synchronous: the bench replay and the simulator use it directly; live, QueuedRecorder runs it in a
// thread of its own. Message log time = sample time (t_us), publish time = log time, except for an input
// recorded with its arrival time (log time = arrival, publish time = its stamp); file order is the order
// of the calls, which for the loop is consumption order.
class RecordingWriter : public RecordSink {
 public:
  bool open(const std::string& path, const RecordingOptions& options, std::string* error);
  bool close(std::string* error);
  bool isOpen() const { return writer_.isOpen(); }

  void recordInput(const InputSample& sample) override;
  // An input that reached the vehicle at arrival_us, whatever its stamp says (the simulator's clock
  // jumps): a replay delivers it at its arrival, and the loop judges its stamp.
  void recordInputArrived(const InputSample& sample, TimeUs arrival_us);
  void recordSolution(const NavSolution& solution) override;
  void recordFusion(const FusionDiagnostic& diagnostic) override;
  void recordEstimatorStates(const EstimatorStates& states) override;
  void recordFrame(const StereoFrame& frame, int pool_index) override;
  void recordTruth(const TruthSample& truth);
  // Simulator ground truth of one stereo pair: /truth/frame, then /truth/depth and /truth/disparity
  // when the truth holds maps (truth_codec.h). Maps need RecordingOptions::truth_maps.
  void recordFrameTruth(const FrameTruth& truth);
  void recordLoopStats(TimeUs t_us, const LoopStats& stats);
  // Key/value metadata (scenario, seed, board...) stored as an MCAP Metadata record.
  bool recordMetadata(const std::string& name, const std::map<std::string, std::string>& values);

  // Messages that could not be encoded or written (the file stays readable up to them).
  std::uint64_t failures() const { return failures_; }
  std::uint64_t messages() const { return writer_.messageCount(); }

 private:
  void put(Topic topic, TimeUs t_us, std::size_t size) { put(topic, t_us, t_us, size); }
  void put(Topic topic, TimeUs log_us, TimeUs publish_us, std::size_t size);

  mcap::Writer writer_;
  std::array<std::uint16_t, kTopicCount> channel_{};
  std::array<std::uint32_t, kTopicCount> sequence_{};
  std::vector<std::uint8_t> buffer_;
  bool record_images_ = true;
  std::uint64_t failures_ = 0;
};

// Parses a compression name into the MCAP enum; false for an unknown name.
bool parseCompression(const std::string& name, mcap::Compression* out);

}  // namespace deepnav
