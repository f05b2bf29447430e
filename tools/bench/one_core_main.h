#pragma once
#include <benchmark/benchmark.h>
#include <opencv2/core.hpp>

namespace deepnav::bench {

// The main() of a vision benchmark: OpenCV on one core, as on the vehicle's vision worker, then the
// benchmarks the command line selects.
inline int runBenchmarksOnOneCore(int argc, char** argv) {
  cv::setNumThreads(0);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace deepnav::bench
