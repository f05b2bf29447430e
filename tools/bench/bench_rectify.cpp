// Rectification of one raw stereo pair at the DexROV camera size (688x516) with the start-up maps
// (StereoRectifier: fixed-point maps, bilinear, no allocation; beside it cv::remap on the same maps, which
// allocates scratch images per call), and the one-off cost of building the maps (plain pinhole vs PinAx).
// OpenCV runs on one thread here, so the figures are per core.
#include <benchmark/benchmark.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "tools/sim/calib/charuco_images.h"
#include "vision/calib/stereo_rectification.h"

namespace {

deepnav::RectificationOptions options(bool pinax) {
  deepnav::RectificationOptions o;
  if (pinax) {
    o.correction = deepnav::PortCorrection::kPinax;
    o.pinax.port.glass_thickness_m = 0.012;
    o.pinax.port.pinhole_to_glass_m = 0.004;
  }
  return o;
}

void runRemap(benchmark::State& state, int type, bool pinax, bool opencv = false) {
  cv::setNumThreads(1);
  const deepnav::StereoCalibration rig = deepnav::sim::simulatedCalibrationRig();
  deepnav::StereoRectification maps;
  std::string error;
  deepnav::StereoRectifier rectifier;
  if (!deepnav::computeStereoRectification(rig, options(pinax), &maps, &error) || !rectifier.init(maps, &error)) {
    state.SkipWithError(error.c_str());
    return;
  }
  cv::Mat raw_left(rig.image_size, type), raw_right(rig.image_size, type);
  cv::RNG rng(3);
  rng.fill(raw_left, cv::RNG::UNIFORM, cv::Scalar::all(0), cv::Scalar::all(255));
  rng.fill(raw_right, cv::RNG::UNIFORM, cv::Scalar::all(0), cv::Scalar::all(255));
  cv::Mat left(rig.image_size, type), right(rig.image_size, type);
  for (auto _ : state) {
    if (opencv) {
      cv::remap(raw_left, left, maps.left_map_xy, maps.left_map_frac, cv::INTER_LINEAR, cv::BORDER_CONSTANT);
      cv::remap(raw_right, right, maps.right_map_xy, maps.right_map_frac, cv::INTER_LINEAR, cv::BORDER_CONSTANT);
    } else {
      benchmark::DoNotOptimize(rectifier.rectify(raw_left, raw_right, left, right));
    }
    benchmark::DoNotOptimize(left.data);
  }
}

void runBuild(benchmark::State& state, bool pinax) {
  cv::setNumThreads(1);
  const deepnav::StereoCalibration rig = deepnav::sim::simulatedCalibrationRig();
  std::string error;
  for (auto _ : state) {
    deepnav::StereoRectification maps;
    benchmark::DoNotOptimize(deepnav::computeStereoRectification(rig, options(pinax), &maps, &error));
  }
}

void BM_RectifyPairGrey688x516(benchmark::State& state) { runRemap(state, CV_8UC1, false); }
void BM_RectifyPairBgr688x516(benchmark::State& state) { runRemap(state, CV_8UC3, false); }
void BM_RectifyPairGreyPinax688x516(benchmark::State& state) { runRemap(state, CV_8UC1, true); }
void BM_CvRemapPairGrey688x516(benchmark::State& state) { runRemap(state, CV_8UC1, false, true); }
void BM_CvRemapPairBgr688x516(benchmark::State& state) { runRemap(state, CV_8UC3, false, true); }
void BM_BuildMapsPinhole(benchmark::State& state) { runBuild(state, false); }
void BM_BuildMapsPinax(benchmark::State& state) { runBuild(state, true); }

}  // namespace

BENCHMARK(BM_RectifyPairGrey688x516)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RectifyPairBgr688x516)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RectifyPairGreyPinax688x516)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CvRemapPairGrey688x516)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CvRemapPairBgr688x516)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BuildMapsPinhole)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BuildMapsPinax)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
