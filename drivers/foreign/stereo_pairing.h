#pragma once
#include <cstdint>
#include <deque>

#include <opencv2/core.hpp>

#include "nav/types/time.h"
#include "vision/types/stereo_frame.h"

namespace deepnav::foreign {

// Stereo pairs from two image topics, by stamp: an image pairs with the other camera's pending image
// whose stamp is nearest, if within the tolerance. Images waiting for their partner are kept (up to
// kMaxPending per camera); older ones that never paired are dropped and counted. The pair's time is the
// left image's stamp.
class StereoPairing {
 public:
  static constexpr std::size_t kMaxPending = 8;

  explicit StereoPairing(TimeUs tolerance_us = 0) : tolerance_us_(tolerance_us) {}
  void setTolerance(TimeUs tolerance_us) { tolerance_us_ = tolerance_us; }

  // Takes the image (moved from). True when it completed a pair, then in *frame (sequence counts pairs).
  bool add(bool left, TimeUs t_us, cv::Mat* image, StereoFrame* frame);

  std::uint64_t pairs() const { return pairs_; }
  // Images dropped without a partner, and those still waiting.
  std::uint64_t unpaired() const { return dropped_ + left_.size() + right_.size(); }

 private:
  struct Pending {
    TimeUs t_us = 0;
    cv::Mat image;
  };
  TimeUs tolerance_us_;
  std::deque<Pending> left_;
  std::deque<Pending> right_;
  std::uint64_t pairs_ = 0;
  std::uint64_t dropped_ = 0;
};

}  // namespace deepnav::foreign
