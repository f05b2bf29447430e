// Dense disparity at the DexROV camera size (688x516), 64 disparities, one core (OpenCV threading
// off). Target: ELAS <= 60 ms per pair.
#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "vision/stereo/elas_disparity.h"
#include "vision/stereo/sgbm_disparity.h"

namespace {

constexpr int kWidth = 688;
constexpr int kHeight = 516;
constexpr int kDisparities = 64;

// Low-contrast textured scene: a slanted plane (disparity 10 -> 30 px) and a box at 50 px.
struct Pair {
  cv::Mat left, right;
};

Pair makePair() {
  cv::Mat texture(kHeight, kWidth + 128, CV_8UC1), box(kHeight, kWidth + 128, CV_8UC1);
  cv::RNG rng(5);
  rng.fill(texture, cv::RNG::UNIFORM, 0, 256);
  rng.fill(box, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(texture, texture, cv::Size(0, 0), 1.5);
  cv::GaussianBlur(box, box, cv::Size(0, 0), 1.5);
  const cv::Rect box_rect(250, 150, 200, 200);
  Pair pair{cv::Mat(kHeight, kWidth, CV_8UC1), cv::Mat(kHeight, kWidth, CV_8UC1)};
  for (int v = 0; v < kHeight; ++v) {
    for (int u = 0; u < kWidth; ++u) {
      pair.left.at<std::uint8_t>(v, u) = box_rect.contains(cv::Point(u, v))
                                             ? box.at<std::uint8_t>(v, u)
                                             : texture.at<std::uint8_t>(v, u + 64);
      const int u_box = u + 50;
      if (box_rect.contains(cv::Point(u_box, v))) {
        pair.right.at<std::uint8_t>(v, u) = box.at<std::uint8_t>(v, u_box);
      } else {
        // background: u_left - (10 + 20 u_left / W) = u
        const float u_left = (static_cast<float>(u) + 10.0f) / (1.0f - 20.0f / kWidth);
        pair.right.at<std::uint8_t>(v, u) =
            texture.at<std::uint8_t>(v, std::min(kWidth + 127, static_cast<int>(u_left + 64.5f)));
      }
    }
  }
  pair.left.convertTo(pair.left, CV_8U, 0.4, 70);
  pair.right.convertTo(pair.right, CV_8U, 0.4, 70);
  return pair;
}

const Pair& pair() {
  static const Pair p = makePair();
  return p;
}

void runEstimator(benchmark::State& state, deepnav::DisparityEstimator& estimator) {
  cv::Mat disparity_px(kHeight, kWidth, CV_32F);
  for (auto _ : state) {
    benchmark::DoNotOptimize(estimator.compute(pair().left, pair().right, &disparity_px));
    benchmark::ClobberMemory();
  }
}

void BM_ElasRobotics(benchmark::State& state) {
  deepnav::ElasParams params = deepnav::ElasParams::robotics();
  params.num_disparities = kDisparities;
  deepnav::ElasDisparity elas;
  if (!elas.init(params, kWidth, kHeight)) state.SkipWithError("init");
  runEstimator(state, elas);
}

void BM_ElasDense(benchmark::State& state) {
  deepnav::ElasParams params = deepnav::ElasParams::dense();
  params.num_disparities = kDisparities;
  deepnav::ElasDisparity elas;
  if (!elas.init(params, kWidth, kHeight)) state.SkipWithError("init");
  runEstimator(state, elas);
}

void BM_Sgbm(benchmark::State& state) {
  deepnav::SgbmParams params;
  params.num_disparities = kDisparities;
  params.wls = state.range(0) != 0;
  deepnav::SgbmDisparity sgbm;
  if (!sgbm.init(params, kWidth, kHeight)) state.SkipWithError("init");
  runEstimator(state, sgbm);
}

}  // namespace

BENCHMARK(BM_ElasRobotics)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ElasDense)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Sgbm)->Arg(0)->Arg(1)->ArgName("wls")->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  cv::setNumThreads(0);  // one core, as on the vehicle's vision worker
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
