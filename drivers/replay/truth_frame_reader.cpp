#include "drivers/replay/truth_frame_reader.h"

#include "drivers/recording/sample_codec.h"
#include "drivers/recording/truth_codec.h"

namespace deepnav {

bool TruthFrameReader::open(const std::string& path, std::string* error) {
  if (!recording_.open(path, error)) return false;
  if (count(Topic::kFrameTruth) == 0) {
    if (error) *error = path + ": no per-frame ground truth (/truth/frame); record it with deepnav-sim";
    return false;
  }
  return true;
}

bool TruthFrameReader::forEach(const Callback& callback, std::string* error) {
  stats_ = TruthFrameReadStats{};
  callback_ = &callback;
  stopped_ = false;
  has_info_ = has_left_ = pair_done_ = false;
  truth_has_frame_ = truth_has_depth_ = truth_has_disparity_ = false;
  const bool ok = recording_.reader().readAll([this](const mcap::MessageView& m) {
    if (!stopped_) handle(m);
  });
  callback_ = nullptr;
  if (!ok && error) *error = recording_.reader().error();
  return ok;
}

void TruthFrameReader::handle(const mcap::MessageView& m) {
  const Topic topic = recording_.topicOf(m.channel_id);
  TimeUs t_us = 0;
  switch (topic) {
    case Topic::kStereoInfo:
      if (pair_done_ || has_info_) ++stats_.unmatched;
      has_info_ = decodeStereoInfo(m.data, m.size, &pair_);
      has_left_ = pair_done_ = false;
      if (!has_info_) ++stats_.bad_messages;
      return;
    case Topic::kLeftImage:
    case Topic::kRightImage:
      handleImage(topic == Topic::kLeftImage, m);
      return;
    case Topic::kFrameTruth:
      if (truth_has_frame_) ++stats_.unmatched;
      truth_has_frame_ = decodeFrameTruth(m.data, m.size, &truth_);
      truth_has_depth_ = truth_has_disparity_ = false;
      if (!truth_has_frame_) ++stats_.bad_messages;
      break;
    case Topic::kTruthDepth:
      truth_has_depth_ = truth_has_frame_ && decodeTruthDepth(m.data, m.size, &t_us, &truth_) && t_us == truth_.t_us;
      if (!truth_has_depth_) ++stats_.bad_messages;
      break;
    case Topic::kTruthDisparity:
      truth_has_disparity_ =
          truth_has_frame_ && decodeTruthDisparity(m.data, m.size, &t_us, &truth_) && t_us == truth_.t_us;
      if (!truth_has_disparity_) ++stats_.bad_messages;
      break;
    default:
      return;
  }
  deliverIfMatched();
}

void TruthFrameReader::handleImage(bool left, const mcap::MessageView& m) {
  int rows = 0, cols = 0, channels = 0;
  if (!has_info_ || (!left && !has_left_) || !peekImageSize(m.data, m.size, &rows, &cols, &channels)) {
    ++stats_.bad_messages;
    return;
  }
  cv::Mat& img = left ? pair_.left : pair_.right;
  img.create(rows, cols, channels == 3 ? CV_8UC3 : CV_8UC1);
  if (!decodeImageInto(m.data, m.size, left, &pair_)) {
    ++stats_.bad_messages;
    has_info_ = has_left_ = false;
    return;
  }
  if (left) {
    has_left_ = true;
    return;
  }
  has_info_ = has_left_ = false;
  pair_done_ = true;
  deliverIfMatched();
}

// A truth is complete with its maps when the recording has maps; it goes out with the pair of the same
// capture time (or alone when the recording has no images).
void TruthFrameReader::deliverIfMatched() {
  const bool maps = hasMaps();
  if (!truth_has_frame_ || (maps && (!truth_has_depth_ || !truth_has_disparity_))) return;
  if (!maps) {
    truth_.depth_m.release();
    truth_.disparity_px.release();
  }
  const bool images = hasImages();
  if (images && !pair_done_) return;  // its pair is still to come (or was lost: counted then)
  if (images && pair_.t_us != truth_.t_us) {
    ++stats_.unmatched;
    pair_done_ = false;
    return;
  }
  truth_has_frame_ = truth_has_depth_ = truth_has_disparity_ = pair_done_ = false;
  ++stats_.pairs;
  if (!(*callback_)(images ? &pair_ : nullptr, truth_)) stopped_ = true;
}

}  // namespace deepnav
