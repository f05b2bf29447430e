// Marker detection and pose at the DexROV camera size (688x516): four markers at 1.4-1.8 m, one
// IPPE_SQUARE pose each; and the per-observation nav work (robot pose measurement, panel
// averaging).
#include <benchmark/benchmark.h>

#include <numbers>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "nav/markers/marker_frame_chain.h"
#include "nav/markers/marker_pose_measurement.h"
#include "nav/markers/panel_pose_estimator.h"
#include "tests/support/synthetic_marker_image.h"
#include "vision/markers/marker_detector.h"

namespace {

using deepnav::MarkerObservations;
constexpr double kDeg = std::numbers::pi / 180.0;

const deepnav::PinholeIntrinsics kCamera{700.0, 700.0, 343.5, 257.5};

deepnav::SyntheticMarker marker(int id, const Eigen::Vector3d& p, double yaw_deg) {
  deepnav::SyntheticMarker m;
  m.id = id;
  const Eigen::Matrix3d facing = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
  m.q_cam_marker =
      Eigen::Quaterniond(facing * Eigen::AngleAxisd(yaw_deg * kDeg, Eigen::Vector3d::UnitY()));
  m.p_marker_in_cam_m = p;
  return m;
}

// Textured grey background (like a panel under lights), 4 markers, blur and noise.
cv::Mat makeImage() {
  cv::Mat image(516, 688, CV_8UC1);
  cv::RNG rng(7);
  rng.fill(image, cv::RNG::UNIFORM, cv::Scalar::all(70), cv::Scalar::all(150));
  cv::GaussianBlur(image, image, cv::Size(9, 9), 3.0);
  const deepnav::SyntheticMarker markers[] = {
      marker(0, {-0.45, -0.3, 1.6}, 20.0), marker(11, {0.45, -0.3, 1.4}, -20.0),
      marker(22, {-0.45, 0.3, 1.8}, 30.0), marker(33, {0.45, 0.3, 1.6}, -35.0)};
  for (const auto& m : markers) deepnav::drawSyntheticMarker("DICT_4X4_50", m, kCamera, 4, &image);
  cv::GaussianBlur(image, image, cv::Size(5, 5), 0.6);
  deepnav::addGaussianNoise(2.0, &rng, &image);
  return image;
}

deepnav::MarkerDetector makeDetector(bool coarse_search = false) {
  deepnav::MarkerDetectorConfig config;
  config.camera = kCamera;
  config.coarse_search = coarse_search;
  deepnav::MarkerDetector detector;
  detector.init(config, nullptr);
  return detector;
}

void runDetect(benchmark::State& state, const cv::Mat& image, bool coarse_search = false) {
  deepnav::MarkerDetector detector = makeDetector(coarse_search);
  MarkerObservations out;
  for (auto _ : state) {
    detector.detect(image, &out);
    benchmark::DoNotOptimize(out.count);
  }
  state.counters["markers"] = out.count;
}

void BM_MarkersDetectAndPoseGrey688x516(benchmark::State& state) { runDetect(state, makeImage()); }

// The same on one core: OpenCV's own worker threads off (cv::setNumThreads(0)).
void BM_MarkersDetectAndPoseGrey688x516OneThread(benchmark::State& state) {
  const int threads = cv::getNumThreads();
  cv::setNumThreads(0);
  runDetect(state, makeImage());
  cv::setNumThreads(threads);
}

// The same, coarse-to-fine (vision.markers_coarse_search): quads at half resolution, the full-resolution
// detector only around them.
void BM_MarkersCoarseDetectAndPoseGrey688x516OneThread(benchmark::State& state) {
  const int threads = cv::getNumThreads();
  cv::setNumThreads(0);
  runDetect(state, makeImage(), true);
  cv::setNumThreads(threads);
}

void BM_MarkersDetectAndPoseBgr688x516(benchmark::State& state) {
  cv::Mat bgr;
  cv::cvtColor(makeImage(), bgr, cv::COLOR_GRAY2BGR);
  runDetect(state, bgr);
}

// The pose alone (IPPE_SQUARE, both solutions, our reprojection errors), per marker.
void BM_MarkersSquarePose(benchmark::State& state) {
  deepnav::MarkerDetector detector = makeDetector();
  MarkerObservations out;
  detector.detect(makeImage(), &out);
  deepnav::MarkerObservation obs = out.items[0];
  for (auto _ : state) {
    deepnav::estimateSquareMarkerPose(out.items[0].corners_px, 0.15, kCamera,
                                      deepnav::MarkerAmbiguityConfig{}, &obs);
    benchmark::DoNotOptimize(obs.reprojection_error_px);
  }
}

// Robot pose measurement from one observation (frame chain + covariance).
void BM_MarkersPoseMeasurement(benchmark::State& state) {
  deepnav::MarkerDetector detector = makeDetector();
  MarkerObservations out;
  detector.detect(makeImage(), &out);
  deepnav::PanelMarker pm;
  pm.id = out.items[0].id;
  deepnav::PanelPoseInOdom panel;
  panel.sigma_position_m = 0.01;
  panel.sigma_rotation_rad = 0.005;
  deepnav::PoseMeasurement m;
  for (auto _ : state) {
    deepnav::markerPoseMeasurement(0, out.items[0], pm, panel, Eigen::Isometry3d::Identity(),
                                   deepnav::MarkerCovarianceConfig{}, &m);
    benchmark::DoNotOptimize(m.cov_pose(0, 0));
  }
}

// One accepted observation into the stage-1 panel average (never fixes: min_observations huge).
void BM_MarkersPanelPoseAdd(benchmark::State& state) {
  deepnav::MarkerDetector detector = makeDetector();
  MarkerObservations out;
  detector.detect(makeImage(), &out);
  deepnav::PanelPoseConfig config;
  config.min_observations = 100000;
  deepnav::PanelPoseEstimator est;
  est.init(config, nullptr);
  deepnav::PanelMarker pm;
  pm.id = out.items[0].id;
  deepnav::MarkerObservation obs = out.items[0];
  obs.ambiguous = false;
  for (auto _ : state) {
    benchmark::DoNotOptimize(est.addObservation(0, obs, pm, Eigen::Isometry3d::Identity(),
                                                Eigen::Isometry3d::Identity()));
    if (est.estimate().observations > 50000) est.reset();
  }
}

}  // namespace

BENCHMARK(BM_MarkersDetectAndPoseGrey688x516)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MarkersDetectAndPoseGrey688x516OneThread)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MarkersCoarseDetectAndPoseGrey688x516OneThread)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MarkersDetectAndPoseBgr688x516)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MarkersSquarePose)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MarkersPoseMeasurement)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MarkersPanelPoseAdd)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
