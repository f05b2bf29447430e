#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "nav/types/input_sample.h"
#include "nav/types/nav_solution.h"
#include "nav/types/truth_sample.h"
#include "drivers/recording/frame_truth.h"
#include "vision/types/stereo_frame.h"

namespace deepnav {

// One item of a recording as the replay sees it.
struct ReplayEvent {
  enum class Kind { kInput, kSolution, kFrame, kTruth, kFrameTruth };
  Kind kind = Kind::kInput;
  TimeUs t_us = 0;  // when the loop meets it: an input's arrival (its stamp unless recorded otherwise)
  InputSample input;
  NavSolution solution;
  TruthSample truth;
  const StereoFrame* frame = nullptr;  // valid during the callback only
  const FrameTruth* frame_truth = nullptr;  // kFrameTruth: poses only (no maps), during the callback only
};

struct ReplayReadStats {
  std::uint64_t messages = 0;
  std::uint64_t bad_messages = 0;   // undecodable: counted and skipped
  std::uint64_t unknown_topic = 0;  // channels deepnav does not know (e.g. from another tool)
  std::uint64_t incomplete_frames = 0;
};

// What the bench replay reads events from: a deepnav recording (RecordingReader) or a foreign
// recording converted through a topic map (foreign::ForeignReplayReader).
class ReplayEventSource {
 public:
  using Callback = std::function<bool(const ReplayEvent&)>;  // return false to stop
  virtual ~ReplayEventSource() = default;

  // True when the recording holds the loop's own outputs (a recording of a run, not a raw sensor log).
  virtual bool hasSolutions() const = 0;
  // File order = the order the loop consumed and produced; log-time order = sensor time order.
  virtual bool forEach(bool log_time_order, const Callback& callback, std::string* error) = 0;
  // A deepnav metadata record (deepnav.board, ...); nullptr when absent.
  virtual const std::map<std::string, std::string>* metadata(const std::string& name) const = 0;
  virtual bool truncated() const = 0;
  virtual const std::vector<std::string>& warnings() const = 0;
  virtual const ReplayReadStats& stats() const = 0;
};

}  // namespace deepnav
