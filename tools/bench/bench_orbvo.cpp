// ORB stereo visual odometry at the DexROV camera size (688x516), one core (OpenCV threading off).
// Target: <= 30 ms per stereo pair (the paper's ORB odometry: 145 ms). The sequence is the unit
// tests' textured plane scene along a smooth trajectory, played back and forth so the odometry
// keeps tracking (keyframe insertions and their bundle adjustments are part of the average).
#include <benchmark/benchmark.h>

#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "tests/support/synthetic_plane_scene.h"
#include "tools/bench/one_core_main.h"
#include "vision/orbvo/fixed_point_gaussian.h"
#include "vision/orbvo/grid_orb_extractor.h"
#include "vision/orbvo/orb_stereo_odometry.h"
#include "vision/orbvo/stereo_feature_matcher.h"

namespace {

constexpr int kFrames = 40;

struct Pair {
  cv::Mat left, right;
};

// About 1-2 cm and 0.2-0.4 deg per frame (the unit tests' trajectory).
Pair renderFrame(const deepnav::SyntheticPlaneScene& scene, int k) {
  const double s = k;
  const double deg = 3.14159265358979 / 180.0;
  const Eigen::Vector3d p(0.25 * std::sin(0.08 * s), 0.08 * std::sin(0.13 * s),
                          0.15 * (1.0 - std::cos(0.06 * s)));
  const Eigen::Quaterniond q =
      Eigen::AngleAxisd(4.0 * deg * std::sin(0.07 * s), Eigen::Vector3d::UnitY()) *
      Eigen::AngleAxisd(3.0 * deg * (std::sin(0.05 * s + 0.5) - std::sin(0.5)),
                        Eigen::Vector3d::UnitX()) *
      Eigen::AngleAxisd(2.0 * deg * std::sin(0.09 * s), Eigen::Vector3d::UnitZ());
  Pair pair;
  scene.render(deepnav::StereoRig{}, q, p, 90, &pair.left, &pair.right);
  cv::RNG rng(100 + k);
  for (cv::Mat* image : {&pair.left, &pair.right}) {
    cv::Mat noise(image->size(), CV_16SC1), sum;
    rng.fill(noise, cv::RNG::NORMAL, 0.0, 1.5);
    image->convertTo(sum, CV_16SC1);
    sum += noise;
    sum.convertTo(*image, CV_8UC1);
  }
  return pair;
}

const std::vector<Pair>& sequence() {
  static const std::vector<Pair> frames = [] {
    const deepnav::SyntheticPlaneScene scene = deepnav::makeOrbVoTestScene(7, 0.6);
    std::vector<Pair> f;
    for (int k = 0; k < kFrames; ++k) f.push_back(renderFrame(scene, k));
    return f;
  }();
  return frames;
}

void BM_OrbVoFrame(benchmark::State& state) {
  deepnav::OrbStereoOdometry vo;
  std::string error;
  if (!vo.init(deepnav::OrbVoConfig(), deepnav::StereoRig{}, &error))
    state.SkipWithError(error.c_str());
  const std::vector<Pair>& frames = sequence();
  int k = 0;
  int step = 1;
  deepnav::TimeUs t_us = 0;
  double tracked = 0.0;
  double keyframes = 0.0;
  double lost = 0.0;
  deepnav::OrbVoOutput out;
  for (auto _ : state) {
    vo.process(t_us, frames[k].left, frames[k].right, &out);
    benchmark::DoNotOptimize(out);
    tracked += out.tracked_features;
    keyframes += out.keyframe_inserted;
    lost += out.status == deepnav::OrbVoStatus::kLost;
    t_us += 100'000;
    if (k + step < 0 || k + step >= kFrames) step = -step;  // back and forth
    k += step;
  }
  state.counters["tracked"] = benchmark::Counter(tracked, benchmark::Counter::kAvgIterations);
  state.counters["keyframe_rate"] =
      benchmark::Counter(keyframes, benchmark::Counter::kAvgIterations);
  state.counters["lost_rate"] = benchmark::Counter(lost, benchmark::Counter::kAvgIterations);
}

// A lost frame with a full keyframe store: every frame of an unknown scene is tried against all 64
// stored keyframes (ranking, then PnP on the best three).
void BM_OrbVoLostFrameRelocalisation(benchmark::State& state) {
  deepnav::OrbVoConfig config;
  config.keyframe.max_frames = 1;  // a keyframe per frame fills the store quickly
  deepnav::OrbStereoOdometry vo;
  std::string error;
  if (!vo.init(config, deepnav::StereoRig{}, &error)) state.SkipWithError(error.c_str());
  const std::vector<Pair>& frames = sequence();
  deepnav::OrbVoOutput out;
  deepnav::TimeUs t_us = 0;
  for (int pass = 0; pass < 3; ++pass) {
    for (int k = 0; k < kFrames; ++k, t_us += 100'000) {
      const int i = pass % 2 == 0 ? k : kFrames - 1 - k;
      vo.process(t_us, frames[i].left, frames[i].right, &out);
    }
  }
  const deepnav::SyntheticPlaneScene unknown = deepnav::makeOrbVoTestScene(1234, 0.6);
  const Pair lost = renderFrame(unknown, 0);
  int keyframes = out.keyframes;
  for (auto _ : state) {
    vo.process(t_us, lost.left, lost.right, &out);
    benchmark::DoNotOptimize(out);
    t_us += 100'000;
  }
  state.counters["keyframes"] = keyframes;
  state.counters["lost"] = out.status == deepnav::OrbVoStatus::kLost;
}

// One image's features, with the corners from FastCornerMap (arg 1, the default) or from cv::FAST per
// cell (arg 0): the same features either way.
void BM_OrbExtractOneImage(benchmark::State& state) {
  deepnav::GridOrbExtractor extractor;
  deepnav::OrbExtractorConfig config;
  config.fast_corner_map = state.range(0) == 1;
  if (!extractor.init(config, 688, 516)) state.SkipWithError("init");
  std::vector<deepnav::OrbFeature> features;
  std::vector<deepnav::OrbDescriptor> descriptors;
  for (auto _ : state) {
    benchmark::DoNotOptimize(extractor.extract(sequence()[0].left, &features, &descriptors));
  }
  state.counters["features"] = static_cast<double>(features.size());
}

// The smoothing before BRIEF sampling on one 688x516 image, sigma 2 px: OpenCV's cv::GaussianBlur
// (fixed_point:0) against FixedPointGaussian (fixed_point:1), which gives the same bits, with OpenCV's own
// kernel for the sigma (kernel:0, 13 taps: the extractor's default) or 7 taps (OpenCV's ORB and ORB-SLAM).
void BM_BriefSmoothing(benchmark::State& state) {
  const cv::Mat& image = sequence()[0].left;
  const int kernel_px = static_cast<int>(state.range(1));
  deepnav::FixedPointGaussian blur;
  if (state.range(0) == 1 && !blur.init(2.0, kernel_px, {image.size()})) state.SkipWithError("init");
  cv::Mat smoothed(image.size(), CV_8UC1);
  for (auto _ : state) {
    if (state.range(0) == 0) {
      cv::GaussianBlur(image, smoothed, cv::Size(kernel_px, kernel_px), 2.0);
    } else {
      blur.apply(image, &smoothed);
    }
    benchmark::DoNotOptimize(smoothed.data);
  }
}

void BM_StereoMatch(benchmark::State& state) {
  deepnav::GridOrbExtractor extractor;
  if (!extractor.init(deepnav::OrbExtractorConfig(), 688, 516)) state.SkipWithError("init");
  deepnav::StereoFeatureMatcher matcher;
  if (!matcher.init(deepnav::StereoMatchConfig(), deepnav::StereoRig{}, extractor.capacity(),
                    1.2)) {
    state.SkipWithError("init");
  }
  std::vector<deepnav::OrbFeature> left, right;
  std::vector<deepnav::OrbDescriptor> left_desc, right_desc;
  extractor.extract(sequence()[0].left, &left, &left_desc);
  extractor.extract(sequence()[0].right, &right, &right_desc);
  std::vector<float> u_right_px;
  std::vector<Eigen::Vector3d> p_in_cam_m;
  int matches = 0;
  for (auto _ : state) {
    matches = matcher.match(sequence()[0].left, sequence()[0].right, left, left_desc, right,
                            right_desc, &u_right_px, &p_in_cam_m);
    benchmark::DoNotOptimize(matches);
  }
  state.counters["matches"] = matches;
}

}  // namespace

BENCHMARK(BM_OrbVoFrame)->Unit(benchmark::kMillisecond)->MinTime(3.0);
BENCHMARK(BM_OrbVoLostFrameRelocalisation)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OrbExtractOneImage)->Arg(0)->Arg(1)->ArgName("fast_corner_map")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StereoMatch)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BriefSmoothing)
    ->ArgsProduct({{0, 1}, {7, 0}})
    ->ArgNames({"fixed_point", "kernel"})
    ->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) { return deepnav::bench::runBenchmarksOnOneCore(argc, argv); }
