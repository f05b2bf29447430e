#pragma once
#include <cstdint>
#include <vector>

#include "nav/ekf/error_state.h"
#include "nav/types/fusion_diagnostic.h"

namespace deepnav {

static_assert(kFusionMaxDim == es::kMaxMeasDim, "a diagnostic holds the largest measurement");

// Diagnostics produced since the last drain, in production order. Capacity reserved once; when full the
// newest are dropped and counted (the loop drains it every tick, so it fills only on a stall).
class FusionDiagnosticBuffer {
 public:
  bool allocate(int capacity);
  void push(const FusionDiagnostic& d);
  void clear() { items_.clear(); }
  int size() const { return static_cast<int>(items_.size()); }
  const FusionDiagnostic& at(int i) const { return items_[static_cast<std::size_t>(i)]; }
  std::uint32_t dropped() const { return dropped_; }

 private:
  std::vector<FusionDiagnostic> items_;
  std::uint32_t dropped_ = 0;
};

}  // namespace deepnav
