#pragma once
#include <cstddef>
#include <cstdint>

#include "nav/types/estimator_states.h"

namespace deepnav {

// CDR of deepnav_msgs/msg/EstimatorStates (topic /nav/estimator_states, topics.h). The encoder writes
// into a caller buffer and never allocates (0 when it is too small); the decoder is bounds-checked and
// false on a malformed message.
std::size_t encodeEstimatorStates(const EstimatorStates& e, std::uint8_t* out, std::size_t capacity);
bool decodeEstimatorStates(const std::uint8_t* data, std::size_t size, EstimatorStates* out);

}  // namespace deepnav
