#pragma once
#include <cstdint>

#include "nav/ekf/filter_state.h"

namespace deepnav {

enum class CloneStatus : std::uint8_t { kOk, kFull, kDuplicateId, kUnknownId };

// Augments the state with a copy of the current pose (p, q) as clone `id` (Roumeliotis & Burdick 2002):
//   x_aug = [x; J x],  P_aug = [P, P J^T; J P, J P J^T],  J selects (dp, dtheta) of the core state.
// The clone is appended after the existing ones; max_clones bounds the count (<= es::kMaxClones).
CloneStatus augmentClone(std::uint32_t id, int max_clones, FilterState* s);

// Removes a clone: marginalising a Gaussian is dropping its rows and columns. Later clones move up.
CloneStatus marginaliseClone(std::uint32_t id, FilterState* s);

}  // namespace deepnav
