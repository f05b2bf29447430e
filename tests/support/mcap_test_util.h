#pragma once
// Shared by the MCAP tests (unit and integration).
#include <string>

#include <gtest/gtest.h>

#include "drivers/mcap/compression.h"

namespace deepnav::mcap {

// The writer's three compressions, as the values of a parameterised test.
inline auto everyCompression() { return ::testing::Values(Compression::kNone, Compression::kZstd, Compression::kLz4); }

// A parameterised test's name for each compression ("none" for MCAP's empty name of no compression).
inline std::string compressionTestName(const ::testing::TestParamInfo<Compression>& info) {
  const std::string_view name = compressionName(info.param);
  return name.empty() ? std::string("none") : std::string(name);
}

}  // namespace deepnav::mcap
