// MDM image quality at the DexROV camera size (688x516). Target: <= 3 ms per image on one core.
#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "vision/iqa/mdm.h"

namespace {

// A low-contrast textured image like an underwater frame: smooth noise squeezed into [60, 160].
cv::Mat makeImage(int type) {
  cv::Mat noise(516, 688, CV_8UC(CV_MAT_CN(type)));
  cv::RNG rng(7);
  rng.fill(noise, cv::RNG::UNIFORM, cv::Scalar::all(60), cv::Scalar::all(160));
  cv::GaussianBlur(noise, noise, cv::Size(5, 5), 1.5);
  return noise;
}

void runMdm(benchmark::State& state, int type) {
  const cv::Mat image = makeImage(type);
  deepnav::MdmWorkspace ws;
  deepnav::MdmScore score;
  for (auto _ : state) {
    benchmark::DoNotOptimize(deepnav::computeMdm(image, &score, &ws));
    benchmark::DoNotOptimize(score.score);
  }
}

void BM_MdmGrey688x516(benchmark::State& state) { runMdm(state, CV_8UC1); }
void BM_MdmBgr688x516(benchmark::State& state) { runMdm(state, CV_8UC3); }

}  // namespace

BENCHMARK(BM_MdmGrey688x516)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MdmBgr688x516)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
