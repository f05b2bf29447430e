#include "nav/pipeline/pose_history.h"

namespace deepnav {

void PoseHistory::push(TimeUs t_us, const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  if (count_ > 0 && t_us <= at(count_ - 1).t_us) return;  // time only moves forward
  entries_[head_] = Entry{t_us, p, q};
  head_ = (head_ + 1) % kCapacity;
  if (count_ < kCapacity) ++count_;
}

bool PoseHistory::poseAt(TimeUs t_us, Eigen::Isometry3d* T) const {
  if (count_ == 0 || t_us < at(0).t_us || t_us > at(count_ - 1).t_us) return false;
  // Binary search for the first entry at or after t_us.
  std::size_t lo = 0, hi = count_ - 1;
  while (lo < hi) {
    const std::size_t mid = (lo + hi) / 2;
    if (at(mid).t_us < t_us) lo = mid + 1;
    else hi = mid;
  }
  const Entry& b = at(lo);
  const Entry& a = lo > 0 ? at(lo - 1) : b;
  const double span = static_cast<double>(b.t_us - a.t_us);
  const double s = span > 0 ? static_cast<double>(t_us - a.t_us) / span : 1.0;
  T->setIdentity();
  T->linear() = a.q.slerp(s, b.q).toRotationMatrix();
  T->translation() = a.p + s * (b.p - a.p);
  return true;
}

}  // namespace deepnav
