#include "nav/ekf/state_history.h"

namespace deepnav {

bool StateHistory::allocate(int capacity) {
  if (capacity < 1) return false;
  ring_.assign(static_cast<std::size_t>(capacity), HistoryEntry{});
  clear();
  return true;
}

HistoryEntry& StateHistory::push() {
  if (size_ == capacity()) {
    head_ = (head_ + 1) % capacity();
    ++overwrites_;
  } else {
    ++size_;
  }
  return at(size_ - 1);
}

void StateHistory::popOldest() {
  if (size_ == 0) return;
  head_ = (head_ + 1) % capacity();
  --size_;
}

int StateHistory::latestAtOrBefore(TimeUs t_us) const {
  int lo = 0, hi = size_ - 1, best = -1;
  while (lo <= hi) {  // times are strictly increasing
    const int mid = (lo + hi) / 2;
    if (timeAt(mid) <= t_us) {
      best = mid;
      lo = mid + 1;
    } else {
      hi = mid - 1;
    }
  }
  return best;
}

}  // namespace deepnav
