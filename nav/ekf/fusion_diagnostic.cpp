#include "nav/ekf/fusion_diagnostic.h"

namespace deepnav {

bool FusionDiagnosticBuffer::allocate(int capacity) {
  if (capacity < 1) return false;
  items_.clear();
  items_.reserve(static_cast<std::size_t>(capacity));
  dropped_ = 0;
  return true;
}

void FusionDiagnosticBuffer::push(const FusionDiagnostic& d) {
  if (items_.size() == items_.capacity()) {
    ++dropped_;
    return;
  }
  items_.push_back(d);
}

}  // namespace deepnav
