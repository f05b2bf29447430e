// MarkerDetector's coarse-to-fine mode (coarse_search): quads at half resolution, then the whole-image
// detector only in rectangles around them. What it finds must be exactly what the whole-image search
// finds (same ids, same corners to the bit, same poses).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "tests/support/synthetic_marker_image.h"
#include "vision/markers/coarse_marker_regions.h"
#include "vision/markers/marker_detector.h"

namespace deepnav {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

PinholeIntrinsics camera() { return PinholeIntrinsics{700.0, 700.0, 343.5, 257.5}; }

MarkerDetectorConfig detectorConfig(bool coarse) {
  MarkerDetectorConfig c;
  c.camera = camera();
  c.coarse_search = coarse;
  return c;
}

SyntheticMarker markerAt(int id, const Eigen::Vector3d& p, double yaw_deg, double pitch_deg = 0.0) {
  SyntheticMarker m;
  m.id = id;
  m.quiet_zone_m = 0.04;
  const Eigen::Matrix3d facing = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
  m.q_cam_marker = Eigen::Quaterniond(facing * Eigen::AngleAxisd(yaw_deg * kDeg, Eigen::Vector3d::UnitY()) *
                                      Eigen::AngleAxisd(pitch_deg * kDeg, Eigen::Vector3d::UnitX()));
  m.p_marker_in_cam_m = p;
  return m;
}

// Textured background (a panel under lights: many small blobs for the contour tracer), the markers,
// blur and noise.
cv::Mat texturedScene(const std::vector<SyntheticMarker>& markers, std::uint64_t seed) {
  cv::Mat image(516, 688, CV_8UC1);
  cv::RNG rng(seed);
  rng.fill(image, cv::RNG::UNIFORM, cv::Scalar::all(60), cv::Scalar::all(160));
  cv::GaussianBlur(image, image, cv::Size(7, 7), 1.5);
  for (const auto& m : markers) EXPECT_TRUE(drawSyntheticMarker("DICT_4X4_50", m, camera(), 4, &image));
  cv::GaussianBlur(image, image, cv::Size(5, 5), 0.6);
  addGaussianNoise(3.0, &rng, &image);
  return image;
}

const MarkerObservation* findId(const MarkerObservations& out, int id) {
  for (int i = 0; i < out.count; ++i) {
    if (out.items[i].id == id) return &out.items[i];
  }
  return nullptr;
}

TEST(MarkersCoarseSearch, FindsTheWholeImageMarkersWithTheSameCorners) {
  // GIVEN markers at 1.2-2.5 m, tilted, on a textured background, one of them near the image border
  const std::vector<SyntheticMarker> markers = {
      markerAt(0, {-0.45, -0.3, 1.6}, 20.0),  markerAt(11, {0.45, -0.3, 1.4}, -20.0),
      markerAt(22, {-0.45, 0.3, 1.8}, 30.0, 10.0), markerAt(33, {0.45, 0.3, 1.6}, -35.0),
      markerAt(44, {0.0, 0.0, 2.5}, 45.0),    markerAt(5, {-0.47, 0.0, 1.2}, 0.0, 25.0)};
  MarkerDetector whole, coarse;
  ASSERT_TRUE(whole.init(detectorConfig(false), nullptr));
  ASSERT_TRUE(coarse.init(detectorConfig(true), nullptr));
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const cv::Mat image = texturedScene(markers, seed);
    // WHEN detected on the whole image and coarse-to-fine
    MarkerObservations a, b;
    ASSERT_TRUE(whole.detect(image, &a));
    ASSERT_TRUE(coarse.detect(image, &b));
    // THEN the same markers, each with bit-identical corners and pose
    ASSERT_EQ(a.count, static_cast<int>(markers.size())) << seed;
    ASSERT_EQ(b.count, a.count) << seed;
    for (int i = 0; i < a.count; ++i) {
      const MarkerObservation* same = findId(b, a.items[i].id);
      ASSERT_NE(same, nullptr) << a.items[i].id;
      for (int k = 0; k < 4; ++k) EXPECT_EQ(same->corners_px[k], a.items[i].corners_px[k]) << a.items[i].id;
      EXPECT_EQ(same->p_marker_in_cam_m, a.items[i].p_marker_in_cam_m);
      EXPECT_EQ(same->q_cam_marker.coeffs(), a.items[i].q_cam_marker.coeffs());
    }
  }
}

TEST(MarkersCoarseSearch, RegionsAreDisjointAndHoldEveryMarker) {
  // GIVEN two markers side by side (their rectangles overlap) and one apart
  const std::vector<SyntheticMarker> markers = {markerAt(1, {-0.1, 0.0, 1.5}, 0.0),
                                                markerAt(2, {0.1, 0.0, 1.5}, 0.0),
                                                markerAt(3, {0.5, 0.3, 1.5}, 0.0)};
  const cv::Mat image = texturedScene(markers, 4);
  CoarseMarkerRegions regions;
  regions.init(cv::aruco::getPredefinedDictionary(cv::aruco::DICT_4X4_50), CoarseRegionConfig{});
  std::vector<cv::Rect> rects;
  // WHEN the coarse search runs
  regions.find(image, {}, &rects);
  // THEN no two rectangles overlap, each is inside the image, and each marker's corners lie in one
  for (std::size_t i = 0; i < rects.size(); ++i) {
    EXPECT_EQ(rects[i] & cv::Rect(0, 0, image.cols, image.rows), rects[i]);
    for (std::size_t j = i + 1; j < rects.size(); ++j) EXPECT_EQ((rects[i] & rects[j]).area(), 0);
  }
  for (const auto& m : markers) {
    int holding = 0;
    for (const cv::Rect& r : rects) {
      bool all = true;
      for (int k = 0; k < 4; ++k) {
        const Eigen::Vector2d c = projectMarkerCorner(m, camera(), k);
        all = all && r.contains(cv::Point(static_cast<int>(c.x()), static_cast<int>(c.y())));
      }
      holding += all ? 1 : 0;
    }
    EXPECT_EQ(holding, 1) << m.id;
  }
}

TEST(MarkersCoarseSearch, MergesChainsOfOverlappingRectangles) {
  // GIVEN A overlapping C, C overlapping D (A and D apart), and B alone
  std::vector<cv::Rect> rects = {{0, 0, 10, 10}, {50, 50, 5, 5}, {8, 8, 10, 10}, {16, 0, 10, 10}};
  // WHEN merged
  mergeOverlappingRects(&rects);
  // THEN A | C | D, and B
  ASSERT_EQ(rects.size(), 2u);
  EXPECT_EQ(rects[0], cv::Rect(0, 0, 26, 18));
  EXPECT_EQ(rects[1], cv::Rect(50, 50, 5, 5));
}

TEST(MarkersCoarseSearch, InitRejectsBadCoarseConfigNamingTheKey) {
  MarkerDetectorConfig c = detectorConfig(true);
  c.coarse.threshold_window_max_px = 2;
  std::string error;
  MarkerDetector detector;
  EXPECT_FALSE(detector.init(c, &error));
  EXPECT_NE(error.find("coarse.threshold_window_max_px"), std::string::npos) << error;
}

TEST(MarkersCoarseSearch, AFarMarkerIsFoundByThePeriodicWholeImageSearchThenTracked) {
  // GIVEN a marker 6 m away, turned 40 deg: too small for a quad at half resolution
  const cv::Mat image = texturedScene({markerAt(7, {0.1, 0.05, 6.0}, 40.0)}, 5);
  MarkerDetector whole, coarse;
  ASSERT_TRUE(whole.init(detectorConfig(false), nullptr));
  ASSERT_TRUE(coarse.init(detectorConfig(true), nullptr));
  MarkerObservations reference;
  ASSERT_TRUE(whole.detect(image, &reference));
  ASSERT_EQ(reference.count, 1);
  const int every = CoarseRegionConfig{}.full_search_every_pairs;
  // WHEN the same view comes pair after pair
  for (int pair = 1; pair <= every + 3; ++pair) {
    MarkerObservations out;
    ASSERT_TRUE(coarse.detect(image, &out));
    // THEN the coarse search misses it until the whole image is searched (pair `every`), and from then on
    // the previous pair's marker is searched again at full resolution: found, with the same corners
    ASSERT_EQ(out.count, pair < every ? 0 : 1) << "pair " << pair;
    if (out.count == 1) {
      for (int k = 0; k < 4; ++k) EXPECT_EQ(out.items[0].corners_px[k], reference.items[0].corners_px[k]);
    }
  }
}

}  // namespace
}  // namespace deepnav
