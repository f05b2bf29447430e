#include "drivers/recording/recording_writer.h"

#include <algorithm>

#include "drivers/cdr/ros2msg_definitions.h"
#include "drivers/recording/estimator_states_codec.h"
#include "drivers/recording/fusion_codec.h"
#include "drivers/recording/sample_codec.h"
#include "drivers/recording/truth_codec.h"

namespace deepnav {
namespace {

constexpr std::size_t kHeaderRoom = 512;  // CDR header, image fields and alignment around the pixels

std::uint64_t toNs(TimeUs t_us) { return t_us > 0 ? static_cast<std::uint64_t>(t_us) * 1000u : 0u; }

}  // namespace

bool parseCompression(const std::string& name, mcap::Compression* out) {
  if (name == "zstd") *out = mcap::Compression::kZstd;
  else if (name == "lz4") *out = mcap::Compression::kLz4;
  else if (name == "none") *out = mcap::Compression::kNone;
  else return false;
  return true;
}

bool RecordingWriter::open(const std::string& path, const RecordingOptions& options, std::string* error) {
  mcap::WriterOptions w;
  if (!parseCompression(options.compression, &w.compression)) {
    if (error) *error = "recording: unknown compression '" + options.compression + "' (zstd, lz4 or none)";
    return false;
  }
  w.chunk_max_duration_ns = static_cast<std::uint64_t>(options.chunk_max_duration_s * 1e9);
  w.chunk_size_bytes = static_cast<std::size_t>(options.chunk_size_kib) * 1024u;
  const std::size_t image_bytes = static_cast<std::size_t>(options.image_width_px) *
                                  static_cast<std::size_t>(options.image_height_px) *
                                  static_cast<std::size_t>(options.image_channels);
  const std::size_t depth_bytes = options.truth_maps ? static_cast<std::size_t>(options.image_width_px) *
                                                          static_cast<std::size_t>(options.image_height_px) * 4u
                                                    : 0u;
  w.max_message_bytes = std::max(image_bytes, depth_bytes) + kHeaderRoom;
  buffer_.assign(w.max_message_bytes, 0);
  record_images_ = options.record_images;
  if (!writer_.open(path, w, error)) return false;
  for (std::size_t i = 0; i < kTopicCount; ++i) {
    const TopicInfo& info = topicInfo(static_cast<Topic>(i));
    const std::uint16_t schema =
        writer_.addSchema(info.type, ros::kRos2MsgEncoding, topicSchema(static_cast<Topic>(i)));
    channel_[i] = writer_.addChannel(schema, info.name, ros::kCdrEncoding);
    sequence_[i] = 0;
    if (schema == 0 || channel_[i] == 0) {
      if (error) *error = path + ": cannot register topic " + std::string(info.name) + ": " + writer_.lastError();
      return false;
    }
  }
  failures_ = 0;
  return true;
}

bool RecordingWriter::close(std::string* error) { return writer_.close(error); }

void RecordingWriter::put(Topic topic, TimeUs log_us, TimeUs publish_us, std::size_t size) {
  const auto i = static_cast<std::size_t>(topic);
  if (size == 0 || !writer_.isOpen() ||
      !writer_.write(channel_[i], sequence_[i]++, toNs(log_us), toNs(publish_us), buffer_.data(), size)) {
    ++failures_;
  }
}

void RecordingWriter::recordInput(const InputSample& sample) { recordInputArrived(sample, sampleTimeUs(sample)); }

void RecordingWriter::recordInputArrived(const InputSample& sample, TimeUs arrival_us) {
  const TimeUs t_us = sampleTimeUs(sample);
  put(inputTopic(sample), arrival_us, t_us, encodeInput(sample, buffer_.data(), buffer_.size()));
  const std::size_t n = encodeInputCompanion(sample, buffer_.data(), buffer_.size());
  if (n > 0) put(inputCompanionTopic(sample), arrival_us, t_us, n);
}

void RecordingWriter::recordSolution(const NavSolution& s) {
  put(Topic::kOdometry, s.t_us, encodeOdometry(s, buffer_.data(), buffer_.size()));
  put(Topic::kNavSolution, s.t_us, encodeSolution(s, buffer_.data(), buffer_.size()));
}

void RecordingWriter::recordFusion(const FusionDiagnostic& d) {
  put(Topic::kFusion, d.t_us, encodeFusion(d, buffer_.data(), buffer_.size()));
}

void RecordingWriter::recordEstimatorStates(const EstimatorStates& e) {
  put(Topic::kEstimatorStates, e.t_us, encodeEstimatorStates(e, buffer_.data(), buffer_.size()));
}

void RecordingWriter::recordFrame(const StereoFrame& frame, int /*pool_index*/) {
  put(Topic::kStereoInfo, frame.t_us, encodeStereoInfo(frame, buffer_.data(), buffer_.size()));
  if (!record_images_) return;
  put(Topic::kLeftImage, frame.t_us, encodeImage(frame, true, buffer_.data(), buffer_.size()));
  put(Topic::kRightImage, frame.t_us, encodeImage(frame, false, buffer_.data(), buffer_.size()));
}

void RecordingWriter::recordTruth(const TruthSample& truth) {
  put(Topic::kTruth, truth.t_us, encodeTruth(truth, buffer_.data(), buffer_.size()));
}

void RecordingWriter::recordFrameTruth(const FrameTruth& truth) {
  put(Topic::kFrameTruth, truth.t_us, encodeFrameTruth(truth, buffer_.data(), buffer_.size()));
  if (!truth.depth_m.empty()) put(Topic::kTruthDepth, truth.t_us, encodeTruthDepth(truth, buffer_.data(), buffer_.size()));
  if (!truth.disparity_px.empty())
    put(Topic::kTruthDisparity, truth.t_us, encodeTruthDisparity(truth, buffer_.data(), buffer_.size()));
}

void RecordingWriter::recordLoopStats(TimeUs t_us, const LoopStats& stats) {
  put(Topic::kLoopStats, t_us, encodeLoopStats(t_us, stats, buffer_.data(), buffer_.size()));
}

bool RecordingWriter::recordMetadata(const std::string& name, const std::map<std::string, std::string>& values) {
  return writer_.writeMetadata(name, values);
}

}  // namespace deepnav
