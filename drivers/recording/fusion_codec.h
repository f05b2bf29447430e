#pragma once
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "nav/types/fusion_diagnostic.h"

namespace deepnav {

// CDR of deepnav_msgs/msg/FusionDiagnostic (topic /nav/fusion, topics.h): one measurement's fusion. The
// encoder writes into a caller buffer and never allocates (0 when it is too small); the decoder is
// bounds-checked and false on a malformed message.
std::size_t encodeFusion(const FusionDiagnostic& d, std::uint8_t* out, std::size_t capacity);
bool decodeFusion(const std::uint8_t* data, std::size_t size, FusionDiagnostic* out);

// Names as written in the message (source_name, reason_name), for plots and Foxglove filters.
std::string_view sourceName(NavSource source);
std::string_view fusionReasonName(FusionReason reason);

}  // namespace deepnav
