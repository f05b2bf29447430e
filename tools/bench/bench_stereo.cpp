// Dense disparity on one core (OpenCV threading off).
//  - ELAS at the DexROV camera size (688x516), 64 disparities, on a pair rendered by the simulator
//    (the default dive at its 36 s dwell before the valves face, grey), both presets: issue 20's
//    target is twice as fast as libelas (ROBOTICS preset 43 ms on this machine).
//  - ELAS at the vision worker's size (the dive pair halved, 128 disparities, robotics preset).
//  - ELAS dense on the Middlebury pairs (../shared/data/stereo; skipped when absent).
//  - The synthetic low-contrast plane-and-box pair, ELAS and SGBM.
// `bench_stereo --write-dive-pair DIR` writes the rendered pair as DIR/left.png, DIR/right.png
// (to time `deepnav stereo --repeat N` against another program on the same files) and exits.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "tests/support/source_paths.h"
#include "tools/bench/one_core_main.h"
#include "tools/sim/render/stereo_renderer.h"
#include "tools/sim/sensor_simulator.h"
#include "vision/stereo/elas_disparity.h"
#include "vision/stereo/sgbm_disparity.h"

namespace {

constexpr int kWidth = 688;
constexpr int kHeight = 516;
constexpr int kDisparities = 64;
constexpr double kDiveTimeS = 36.0;  // dwell before the valves face

struct Pair {
  cv::Mat left, right;
};

// Low-contrast textured scene: a slanted plane (disparity 10 -> 30 px) and a box at 50 px.
Pair makeSyntheticPair() {
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

// The default scenario's dive pair at kDiveTimeS (seed 1, grey, 688x516); empty on failure.
Pair renderDivePair() {
  const deepnav::sim::Scenario scenario;
  std::string error;
  deepnav::sim::SensorSimulator sim;
  deepnav::sim::StereoRenderer renderer;
  if (!sim.init(scenario, 1, &error) || !renderer.init(scenario, 1, 1, &error)) {
    std::fprintf(stderr, "bench_stereo: %s\n", error.c_str());
    return {};
  }
  deepnav::StereoFrame frame;
  deepnav::allocateStereoFrame(frame, scenario.camera.width_px, scenario.camera.height_px, 1);
  if (!renderer.render(sim.cameraAt(static_cast<deepnav::TimeUs>(kDiveTimeS * 1e6)), &frame, nullptr)) {
    return {};
  }
  return Pair{frame.left.clone(), frame.right.clone()};
}

const Pair& syntheticPair() {
  static const Pair p = makeSyntheticPair();
  return p;
}

const Pair& divePair() {
  static const Pair p = renderDivePair();
  return p;
}

const Pair& halfDivePair() {
  static const Pair p = [] {
    Pair half;
    if (divePair().left.empty()) return half;
    cv::resize(divePair().left, half.left, cv::Size(kWidth / 2, kHeight / 2), 0, 0, cv::INTER_AREA);
    cv::resize(divePair().right, half.right, cv::Size(kWidth / 2, kHeight / 2), 0, 0, cv::INTER_AREA);
    return half;
  }();
  return p;
}

// Middlebury pair NAME (BGR, as `deepnav stereo` reads it) and its disparity range; empty if absent.
struct MiddleburyPair {
  Pair pair;
  int range_px = 0;
};

MiddleburyPair loadMiddlebury(const std::string& name) {
  // $DEEPNAV_SHARED_DATA, else the data beside the source tree (an absolute path: __FILE__ is relative
  // in a ccache build with CCACHE_BASEDIR, as tools/test.sh makes it, and the pair was not found)
  const std::filesystem::path dir =
      deepnav::testing::sharedDataDir() / "stereo" / ("middlebury-" + name);
  MiddleburyPair m;
  double scale = 0.0;
  std::ifstream(dir / "info.txt") >> scale >> m.range_px;
  m.pair.left = cv::imread((dir / "imL.png").string(), cv::IMREAD_COLOR);
  m.pair.right = cv::imread((dir / "imR.png").string(), cv::IMREAD_COLOR);
  return m;
}

void runEstimator(benchmark::State& state, deepnav::DisparityEstimator& estimator, const Pair& pair) {
  cv::Mat disparity_px(pair.left.rows, pair.left.cols, CV_32F);
  for (auto _ : state) {
    benchmark::DoNotOptimize(estimator.compute(pair.left, pair.right, &disparity_px));
    benchmark::ClobberMemory();
  }
}

void runElas(benchmark::State& state, deepnav::ElasParams params, int disparities, const Pair& pair) {
  if (pair.left.empty()) {
    state.SkipWithError("no pair");
    return;
  }
  params.num_disparities = disparities;
  deepnav::ElasDisparity elas;
  if (!elas.init(params, pair.left.cols, pair.left.rows)) {
    state.SkipWithError("init");
    return;
  }
  runEstimator(state, elas, pair);
}

void BM_ElasDiveRobotics(benchmark::State& s) {
  runElas(s, deepnav::ElasParams::robotics(), kDisparities, divePair());
}
void BM_ElasDiveDense(benchmark::State& s) {
  runElas(s, deepnav::ElasParams::dense(), kDisparities, divePair());
}
// The vision worker's configuration (vision.dense_scale_down 2, vision.dense_disparities 128).
void BM_ElasDiveHalfRobotics(benchmark::State& s) {
  runElas(s, deepnav::ElasParams::robotics(), 128, halfDivePair());
}

void middlebury(benchmark::State& state, const std::string& name) {
  const MiddleburyPair m = loadMiddlebury(name);
  runElas(state, deepnav::ElasParams::dense(), m.range_px + 1, m.pair);
}
void BM_ElasTsukubaDense(benchmark::State& s) { middlebury(s, "tsukuba"); }
void BM_ElasVenusDense(benchmark::State& s) { middlebury(s, "venus"); }

void BM_ElasSyntheticRobotics(benchmark::State& s) {
  runElas(s, deepnav::ElasParams::robotics(), kDisparities, syntheticPair());
}
void BM_ElasSyntheticDense(benchmark::State& s) {
  runElas(s, deepnav::ElasParams::dense(), kDisparities, syntheticPair());
}

void BM_Sgbm(benchmark::State& state) {
  deepnav::SgbmParams params;
  params.num_disparities = kDisparities;
  params.wls = state.range(0) != 0;
  deepnav::SgbmDisparity sgbm;
  if (!sgbm.init(params, kWidth, kHeight)) state.SkipWithError("init");
  runEstimator(state, sgbm, syntheticPair());
}

// --write-dive-pair DIR: returns the exit code, or -1 when the flag is absent.
int writeDivePair(int argc, char** argv) {
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "--write-dive-pair") != 0) continue;
    const std::filesystem::path dir = argv[i + 1];
    const Pair& pair = divePair();
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    const bool ok = !pair.left.empty() && cv::imwrite((dir / "left.png").string(), pair.left) &&
                    cv::imwrite((dir / "right.png").string(), pair.right);
    std::printf("%s: %s/left.png, right.png\n", ok ? "written" : "failed", dir.c_str());
    return ok ? 0 : 1;
  }
  return -1;
}

}  // namespace

BENCHMARK(BM_ElasDiveRobotics)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ElasDiveDense)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ElasDiveHalfRobotics)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ElasTsukubaDense)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ElasVenusDense)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ElasSyntheticRobotics)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ElasSyntheticDense)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Sgbm)->Arg(0)->Arg(1)->ArgName("wls")->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  cv::setNumThreads(0);  // writing the dive pair runs on one core too
  if (const int code = writeDivePair(argc, argv); code >= 0) return code;
  return deepnav::bench::runBenchmarksOnOneCore(argc, argv);
}
