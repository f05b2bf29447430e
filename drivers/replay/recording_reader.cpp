#include "drivers/replay/recording_reader.h"

#include "drivers/recording/sample_codec.h"
#include "drivers/recording/truth_codec.h"

namespace deepnav {

bool RecordingReader::open(const std::string& path, std::string* error) {
  if (!recording_.open(path, error)) return false;
  stats_ = ReplayReadStats{};
  return true;
}

bool RecordingReader::forEach(bool log_time_order, const Callback& callback, std::string* error) {
  bool stopped = false;
  auto visit = [&](const mcap::MessageView& m) {
    if (!stopped && !handle(m, callback)) stopped = true;
  };
  mcap::Reader& reader = recording_.reader();
  const bool ok = log_time_order ? reader.readAllInLogTimeOrder(visit) : reader.readAll(visit);
  if (!ok && error) *error = reader.error();
  return ok;
}

bool RecordingReader::handle(const mcap::MessageView& m, const Callback& callback) {
  ++stats_.messages;
  const Topic topic = recording_.topicOf(m.channel_id);
  ReplayEvent e;
  switch (topic) {
    case Topic::kImu:
    case Topic::kDvlBottomTrack:
    case Topic::kDepth:
    case Topic::kHeading:
    case Topic::kAttitude:
    case Topic::kVisionResult:
      e.kind = ReplayEvent::Kind::kInput;
      if (!decodeInput(topic, m.data, m.size, &e.input)) break;
      // Delivered at its arrival: the log time where it differs from the stamp (publish time), as the
      // simulator records a sensor whose clock jumped (RecordingWriter::recordInputArrived).
      e.t_us = m.log_time_ns == m.publish_time_ns ? sampleTimeUs(e.input) : static_cast<TimeUs>(m.log_time_ns / 1000);
      return callback(e);
    case Topic::kNavSolution:
      e.kind = ReplayEvent::Kind::kSolution;
      if (!decodeSolution(m.data, m.size, &e.solution)) break;
      e.t_us = e.solution.t_us;
      return callback(e);
    case Topic::kTruth:
      e.kind = ReplayEvent::Kind::kTruth;
      if (!decodeTruth(m.data, m.size, &e.truth)) break;
      e.t_us = e.truth.t_us;
      return callback(e);
    case Topic::kFrameTruth:
      if (!deliver_frame_truth_) return true;
      e.kind = ReplayEvent::Kind::kFrameTruth;
      if (!decodeFrameTruth(m.data, m.size, &frame_truth_)) break;
      e.t_us = frame_truth_.t_us;
      e.frame_truth = &frame_truth_;
      return callback(e);
    case Topic::kStereoInfo:
      if (frame_has_info_) ++stats_.incomplete_frames;
      frame_has_info_ = decodeStereoInfo(m.data, m.size, &frame_);
      frame_has_left_ = false;
      if (!frame_has_info_) break;
      return true;
    case Topic::kLeftImage:
    case Topic::kRightImage:
      return handleImage(topic, m, callback);
    case Topic::kCount:
      ++stats_.unknown_topic;
      return true;
    default:
      return true;  // viewer-only companions (/dvl, /pressure, /nav/odometry, /nav/loop_stats)
  }
  ++stats_.bad_messages;
  return true;
}

bool RecordingReader::handleImage(Topic topic, const mcap::MessageView& m, const Callback& callback) {
  const bool left = topic == Topic::kLeftImage;
  int rows = 0, cols = 0, channels = 0;
  if (!frame_has_info_ || (!left && !frame_has_left_) || !peekImageSize(m.data, m.size, &rows, &cols, &channels)) {
    ++stats_.incomplete_frames;
    return true;
  }
  // The frame buffer is sized by the first image and reused; a replay only reallocates if the size changes.
  cv::Mat& img = left ? frame_.left : frame_.right;
  img.create(rows, cols, channels == 3 ? CV_8UC3 : CV_8UC1);
  if (!decodeImageInto(m.data, m.size, left, &frame_)) {
    ++stats_.bad_messages;
    frame_has_info_ = false;
    return true;
  }
  if (left) {
    frame_has_left_ = true;
    return true;
  }
  frame_has_info_ = frame_has_left_ = false;
  ReplayEvent e;
  e.kind = ReplayEvent::Kind::kFrame;
  e.t_us = frame_.t_us;
  e.frame = &frame_;
  return callback(e);
}

}  // namespace deepnav
