#pragma once
#include <string>

#include <gtest/gtest.h>

#include "board/replay/bench_replay.h"

namespace deepnav::testing {

// A bench replay as the tests run it: no progress line; a replay that fails is a test failure naming why.
inline ReplaySummary replayOrFail(ReplayOptions o) {
  o.progress = false;
  ReplaySummary s;
  std::string error;
  EXPECT_TRUE(runBenchReplay(o, &s, &error)) << error;
  return s;
}

}  // namespace deepnav::testing
