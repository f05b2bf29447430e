#include "drivers/foreign/stereo_pairing.h"

#include <cstdlib>

namespace deepnav::foreign {

bool StereoPairing::add(bool left, TimeUs t_us, cv::Mat* image, StereoFrame* frame) {
  std::deque<Pending>& mine = left ? left_ : right_;
  std::deque<Pending>& other = left ? right_ : left_;
  std::size_t best = other.size();
  TimeUs best_gap = tolerance_us_ + 1;
  for (std::size_t i = 0; i < other.size(); ++i) {
    const TimeUs gap = std::llabs(other[i].t_us - t_us);
    if (gap < best_gap) {
      best_gap = gap;
      best = i;
    }
  }
  if (best == other.size()) {
    mine.push_back({t_us, std::move(*image)});
    if (mine.size() > kMaxPending) {
      mine.pop_front();
      ++dropped_;
    }
    return false;
  }
  // The partner's older images, and this camera's, will never pair now: the streams move forward.
  dropped_ += best + mine.size();
  Pending partner = std::move(other[best]);
  other.erase(other.begin(), other.begin() + static_cast<std::ptrdiff_t>(best) + 1);
  mine.clear();
  frame->t_us = left ? t_us : partner.t_us;
  frame->exposure_us = 0;
  frame->sequence = pairs_++;
  frame->rectified = false;
  frame->left = left ? std::move(*image) : std::move(partner.image);
  frame->right = left ? std::move(partner.image) : std::move(*image);
  return true;
}

}  // namespace deepnav::foreign
