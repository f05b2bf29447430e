#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "drivers/mcap/reader.h"
#include "drivers/replay/recorded_topics.h"
#include "drivers/replay/replay_event_source.h"
#include "drivers/recording/frame_truth.h"
#include "drivers/recording/topics.h"
#include "nav/types/input_sample.h"
#include "nav/types/nav_solution.h"
#include "nav/types/truth_sample.h"
#include "vision/types/stereo_frame.h"

namespace deepnav {

// Reads a deepnav recording back into the loop's sample types: the replay driver. Bad messages are
// counted and skipped, never fatal; a recording cut off by a crash replays up to its last complete
// chunk, with a warning.
class RecordingReader : public ReplayEventSource {
 public:
  bool open(const std::string& path, std::string* error);

  // True when the recording holds the loop's own outputs (a recording of a run, not a raw sensor log).
  bool hasSolutions() const override { return count(Topic::kNavSolution) > 0; }
  bool hasTruth() const { return count(Topic::kTruth) > 0; }
  std::uint64_t count(Topic topic) const { return recording_.count(topic); }

  // File order = the order the loop consumed and produced; log-time order = sensor time order.
  bool forEach(bool log_time_order, const Callback& callback, std::string* error) override;

  // Also deliver the simulator's per-pair truth (/truth/frame) as kFrameTruth events (off by default:
  // the loop never sees it; evaluation, e.g. the replay's VO consistency, asks for it).
  void setDeliverFrameTruth(bool deliver) { deliver_frame_truth_ = deliver; }

  const std::map<std::string, std::string>* metadata(const std::string& name) const override {
    return recording_.metadata(name);
  }
  bool truncated() const override { return recording_.reader().truncated(); }
  const std::vector<std::string>& warnings() const override {
    return recording_.reader().warnings();
  }
  const ReplayReadStats& stats() const override { return stats_; }

 private:
  bool handle(const mcap::MessageView& m, const Callback& callback);
  bool handleImage(Topic topic, const mcap::MessageView& m, const Callback& callback);

  RecordedTopics recording_;
  ReplayReadStats stats_;
  StereoFrame frame_;
  bool frame_has_info_ = false;
  bool frame_has_left_ = false;
  bool deliver_frame_truth_ = false;
  FrameTruth frame_truth_;
};

}  // namespace deepnav
