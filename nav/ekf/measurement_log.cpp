#include "nav/ekf/measurement_log.h"

#include <algorithm>

namespace deepnav {

bool MeasurementLog::allocate(int capacity) {
  if (capacity < 1) return false;
  events_.clear();
  events_.shrink_to_fit();
  events_.reserve(static_cast<std::size_t>(capacity));
  return true;
}

int MeasurementLog::insert(const LoggedMeasurement& e) {
  if (full()) return -1;
  const int i = firstAfter(e.t_us);
  events_.insert(events_.begin() + i, e);  // within capacity: no reallocation
  return i;
}

void MeasurementLog::popOldest() {
  if (!events_.empty()) events_.erase(events_.begin());
}

int MeasurementLog::firstAfter(TimeUs t_us) const {
  const auto it = std::upper_bound(events_.begin(), events_.end(), t_us,
                                   [](TimeUs t, const LoggedMeasurement& e) { return t < e.t_us; });
  return static_cast<int>(it - events_.begin());
}

int MeasurementLog::firstAtOrAfter(TimeUs t_us) const {
  const auto it = std::lower_bound(events_.begin(), events_.end(), t_us,
                                   [](const LoggedMeasurement& e, TimeUs t) { return e.t_us < t; });
  return static_cast<int>(it - events_.begin());
}

}  // namespace deepnav
