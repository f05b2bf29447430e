#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>

#include "drivers/mcap/reader.h"
#include "drivers/replay/recorded_topics.h"
#include "drivers/recording/frame_truth.h"
#include "drivers/recording/topics.h"
#include "vision/types/stereo_frame.h"

namespace deepnav {

struct TruthFrameReadStats {
  std::uint64_t pairs = 0;          // stereo pairs delivered with their truth
  std::uint64_t bad_messages = 0;   // undecodable truth or image messages: counted and skipped
  std::uint64_t unmatched = 0;      // a pair without truth, or truth without its pair (images recorded)
};

// Reads a simulated recording's stereo pairs together with their per-frame ground truth (/truth/frame,
// /truth/depth, /truth/disparity; truth_codec.h), for evaluation tools. The replay (RecordingReader)
// ignores these topics, so a recording with them replays exactly as one without.
//
//   TruthFrameReader reader;
//   if (!reader.open("dive.mcap", &error)) die(error);
//   reader.forEach([&](const StereoFrame* pair, const FrameTruth& truth) { ...; return true; }, &error);
class TruthFrameReader {
 public:
  // pair is null when the recording holds no images; both are valid during the callback only.
  using Callback = std::function<bool(const StereoFrame* pair, const FrameTruth& truth)>;  // false: stop

  bool open(const std::string& path, std::string* error);
  std::uint64_t count(Topic topic) const { return recording_.count(topic); }
  bool hasMaps() const { return count(Topic::kTruthDepth) > 0 && count(Topic::kTruthDisparity) > 0; }
  bool hasImages() const { return count(Topic::kLeftImage) > 0 && count(Topic::kRightImage) > 0; }
  const std::map<std::string, std::string>* metadata(const std::string& name) const {
    return recording_.metadata(name);
  }

  // In file order (the simulator writes each pair, then its truth, all stamped with the capture time).
  bool forEach(const Callback& callback, std::string* error);
  const TruthFrameReadStats& stats() const { return stats_; }

 private:
  void handle(const mcap::MessageView& m);
  void handleImage(bool left, const mcap::MessageView& m);
  void deliverIfMatched();

  RecordedTopics recording_;
  TruthFrameReadStats stats_;
  const Callback* callback_ = nullptr;
  bool stopped_ = false;
  StereoFrame pair_;
  FrameTruth truth_;
  bool has_info_ = false, has_left_ = false, pair_done_ = false;
  bool truth_has_frame_ = false, truth_has_depth_ = false, truth_has_disparity_ = false;
};

}  // namespace deepnav
