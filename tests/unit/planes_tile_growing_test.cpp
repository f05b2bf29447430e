// PlaneGrowingMethod::kTiles (PlaneTileGrower, the default) against the pixel grower on the scene of
// planes_extraction_test, and on a step edge.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "tests/support/synthetic_scene.h"
#include "tests/unit/planes_test_scene.h"
#include "vision/cloud/cloud_from_disparity.h"
#include "vision/planes/plane_extractor.h"
#include "vision/stereo/disparity_estimator.h"

namespace deepnav {
namespace {

using namespace planes_test;

struct Extraction {
  PlaneExtractor extractor;
  PlaneSet planes;
  int count = -1;
};

// The cloud of `scene` seen from T_world_cam with sigma_px disparity noise, on a grid of step_px.
OrganizedCloud noisyCloud(const SyntheticScene& scene, const Eigen::Isometry3d& T_world_cam,
                          double sigma_px, int step_px, SyntheticView* view) {
  renderSyntheticView(scene, geometry(), kWidth, kHeight, T_world_cam, false, view);
  cv::Mat noise(view->disparity_px.size(), CV_32FC1);
  cv::RNG rng(42);
  rng.fill(noise, cv::RNG::NORMAL, 0.0, sigma_px);
  cv::add(view->disparity_px, noise, view->disparity_px, view->disparity_px > 0.0f);
  CloudConfig cloud_config;
  cloud_config.step_px = step_px;
  CloudFromDisparity builder;
  OrganizedCloud cloud;
  EXPECT_TRUE(builder.init(geometry(), cloud_config, kWidth, kHeight));
  EXPECT_TRUE(builder.allocateCloud(&cloud));
  EXPECT_TRUE(builder.compute(view->disparity_px, &cloud));
  return cloud;
}

void extract(const OrganizedCloud& cloud, PlaneExtractionConfig config, PlaneGrowingMethod method,
             Extraction* out) {
  config.growing = method;
  ASSERT_TRUE(out->extractor.init(config, geometry(), cloud.rows(), cloud.cols(), cloud.step_px));
  ASSERT_TRUE(out->extractor.allocatePlaneSet(&out->planes));
  out->count = out->extractor.extract(cloud, &out->planes);
}

// The box on the floor of planes_extraction_test, 0.2 px noise, on a grid of step_px, and the settings
// that test uses.
OrganizedCloud boxOnFloorCloud(int step_px, SyntheticView* view) {
  return noisyCloud(boxOnFloor(), cameraPitchedDown(30.0 * kDeg, Eigen::Vector3d(0.0, 0.0, 1.6)), 0.2,
                    step_px, view);
}

PlaneExtractionConfig boxConfig() {
  PlaneExtractionConfig config;
  config.min_area_px = 1500;
  config.disparity_noise_px = 0.2;
  return config;
}

double angleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::min(1.0, a.dot(b))) * 180.0 / M_PI;
}

// GIVEN the box on the floor of planes_extraction_test (0.2 px noise), on the full and the 2-px grid
// WHEN the planes are extracted by both growers
// THEN the tile grower finds the same planes: same number, normals within 0.5 deg, offsets
// within 1 cm, the standard deviations of the offset and of the normal within 0.7-1.4x the pixel
// grower's, at least 85 % of each plane's cells in common (89 % on the smallest face, 2-px grid)
class TileGrowingMatchesPixelGrowing : public ::testing::TestWithParam<int> {};

TEST_P(TileGrowingMatchesPixelGrowing, SamePlanesNormalsOffsetsAndCovariances) {
  const int step_px = GetParam();
  SyntheticView view;
  const OrganizedCloud cloud = boxOnFloorCloud(step_px, &view);
  const PlaneExtractionConfig config = boxConfig();
  Extraction pixels, tiles;
  extract(cloud, config, PlaneGrowingMethod::kPixels, &pixels);
  extract(cloud, config, PlaneGrowingMethod::kTiles, &tiles);
  ASSERT_EQ(pixels.count, 4);
  ASSERT_EQ(tiles.count, pixels.count);
  for (int i = 0; i < pixels.count; ++i) {
    const Plane& p = pixels.planes[i];
    int match = -1;
    for (int j = 0; j < tiles.count; ++j) {
      if (angleDeg(p.n_in_cam, tiles.planes[j].n_in_cam) < 0.5 &&
          std::abs(p.d_m - tiles.planes[j].d_m) < 0.01) {
        EXPECT_EQ(match, -1) << "plane " << i << " matched twice";
        match = j;
      }
    }
    ASSERT_GE(match, 0) << "plane " << i << " (d " << p.d_m << ") not found by the tile grower";
    const Plane& t = tiles.planes[match];
    const double offset_sd_ratio = std::sqrt(t.offsetVariance() / p.offsetVariance());
    const double normal_sd_ratio = std::sqrt(t.covariance.topLeftCorner<3, 3>().trace() /
                                             p.covariance.topLeftCorner<3, 3>().trace());
    EXPECT_GT(offset_sd_ratio, 0.7) << i;
    EXPECT_LT(offset_sd_ratio, 1.4) << i;
    EXPECT_GT(normal_sd_ratio, 0.7) << i;
    EXPECT_LT(normal_sd_ratio, 1.4) << i;
    const cv::Mat mine = pixels.extractor.labels() == p.label;
    const cv::Mat theirs = tiles.extractor.labels() == t.label;
    EXPECT_GT(cv::countNonZero(mine & theirs), 0.85 * cv::countNonZero(mine)) << i;
    EXPECT_EQ(t.bbox_cells, cv::boundingRect(theirs)) << i;
    EXPECT_LT(t.n_in_cam.dot(t.p_centroid_in_cam_m), 0.0);
  }
}

INSTANTIATE_TEST_SUITE_P(Steps, TileGrowingMatchesPixelGrowing, ::testing::Values(1, 2));

// A floor and, beyond y = 2.6 m, a platform 15 cm above it (no riser: the depth jumps from the
// floor to the platform's edge, which hides the floor behind it). Seen from 1.2 m up, pitched
// down 35 deg.
SyntheticScene stepScene() {
  SyntheticScene scene;
  scene.rectangles.push_back({Eigen::Vector3d(0, 3.4, 0), Eigen::Vector3d::UnitX(),
                              Eigen::Vector3d::UnitY(), 3.0, 2.0, 3});  // floor, y 1.4..5.4
  scene.rectangles.push_back({Eigen::Vector3d(0, 4.0, 0.15), Eigen::Vector3d::UnitX(),
                              Eigen::Vector3d::UnitY(), 3.0, 1.4, 5});  // platform, y 2.6..5.4
  return scene;
}

// Cells of label carried by another surface than `surface`.
int cellsOffSurface(const Extraction& e, int plane, const cv::Mat& surface_of_cell, int surface) {
  const cv::Mat labelled = e.extractor.labels() == e.planes[plane].label;
  return cv::countNonZero(labelled & (surface_of_cell != surface));
}

// GIVEN the step (15 cm) between the floor and the platform, 0.2 px noise
// WHEN the tile grower extracts the planes
// THEN floor and platform are two planes, and neither took more than 1 % of its cells from the
// other surface; with a point test loose enough to cross the step (30 cm) the same count sees
// the leak, so the check can fail
TEST(TileGrowing, DoesNotLeakAcrossAStepEdge) {
  SyntheticView view;
  const OrganizedCloud cloud =
      noisyCloud(stepScene(), cameraPitchedDown(35.0 * kDeg, Eigen::Vector3d(0.0, 0.0, 1.2)), 0.2,
                 1, &view);
  ASSERT_GT(cv::countNonZero(view.surface == 0), 8000);
  ASSERT_GT(cv::countNonZero(view.surface == 1), 8000);
  PlaneExtractionConfig config;
  config.min_area_px = 1500;
  config.disparity_noise_px = 0.2;
  Extraction tiles;
  extract(cloud, config, PlaneGrowingMethod::kTiles, &tiles);
  ASSERT_EQ(tiles.count, 2);
  for (int i = 0; i < 2; ++i) {
    const cv::Mat labelled = tiles.extractor.labels() == tiles.planes[i].label;
    const int surface = cv::countNonZero(labelled & (view.surface == 0)) >
                                cv::countNonZero(labelled & (view.surface == 1))
                            ? 0
                            : 1;
    const int cells = cv::countNonZero(labelled);
    EXPECT_LT(cellsOffSurface(tiles, i, view.surface, surface), 0.01 * cells)
        << "plane " << i << " leaked across the step";
    EXPECT_GT(cells, 0.8 * cv::countNonZero(view.surface == surface)) << i;
  }

  config.max_point_distance_m = 0.30;
  config.max_mse_m2 = 0.05;
  config.tile_max_normal_angle_deg = 90.0;  // tiles across the step have tilted normals
  Extraction loose;
  extract(cloud, config, PlaneGrowingMethod::kTiles, &loose);
  ASSERT_GE(loose.count, 1);
  const cv::Mat labelled = loose.extractor.labels() == loose.planes[0].label;
  EXPECT_GT(cv::countNonZero(labelled & (view.surface == 0)), 1000);
  EXPECT_GT(cv::countNonZero(labelled & (view.surface == 1)), 1000);
}

// Largest 4-connected component of the cells labelled `label`, and their total.
std::pair<int, int> largestComponent(const cv::Mat& labels, std::uint8_t label) {
  cv::Mat components, stats, centroids;
  const int n = cv::connectedComponentsWithStats(labels == label, components, stats, centroids, 4);
  int largest = 0, total = 0;
  for (int k = 1; k < n; ++k) {
    largest = std::max(largest, stats.at<int>(k, cv::CC_STAT_AREA));
    total += stats.at<int>(k, cv::CC_STAT_AREA);
  }
  return {largest, total};
}

// GIVEN the box on the floor (0.2 px noise), full and 2-px grid, where each box face meets the floor
// and the other face along a line
// WHEN the tile grower extracts the planes
// THEN every plane's cells form one 4-connected region, as the pixel grower's do: near an
// intersection line the noise decides which plane is nearer, and taking the nearest plane cell by
// cell (the earlier refinement) left specks of one plane inside the other (on the full grid 31-52
// holes per box face above the hole size) and cells cut off from their region
TEST_P(TileGrowingMatchesPixelGrowing, EveryPlaneIsOneConnectedRegion) {
  const int step_px = GetParam();
  SyntheticView view;
  const OrganizedCloud cloud = boxOnFloorCloud(step_px, &view);
  Extraction tiles;
  extract(cloud, boxConfig(), PlaneGrowingMethod::kTiles, &tiles);
  ASSERT_EQ(tiles.count, 4);
  for (int i = 0; i < tiles.count; ++i) {
    const auto [largest, total] = largestComponent(tiles.extractor.labels(), tiles.planes[i].label);
    EXPECT_EQ(largest, total) << "plane " << i;
  }
}

TEST(TileGrowing, RefusesBadTileSettingsAndMismatchedClouds) {
  PlaneExtractionConfig config;
  config.growing = PlaneGrowingMethod::kTiles;
  PlaneExtractor extractor;
  ASSERT_TRUE(extractor.init(config, geometry(), 60, 80, 2));
  PlaneSet planes;
  ASSERT_TRUE(extractor.allocatePlaneSet(&planes));
  OrganizedCloud cloud;
  ASSERT_TRUE(cloud.allocate(60, 80, 2));
  EXPECT_EQ(extractor.extract(cloud, &planes), 0);
  OrganizedCloud other;
  ASSERT_TRUE(other.allocate(61, 80, 2));
  EXPECT_EQ(extractor.extract(other, &planes), -1);
  for (int size : {3, 65}) {
    PlaneExtractionConfig bad = config;
    bad.tile_size_px = size;
    EXPECT_FALSE(extractor.init(bad, geometry(), 60, 80, 2)) << size;
  }
  PlaneExtractionConfig bad = config;
  bad.tile_min_valid_fraction = 0.0;
  EXPECT_FALSE(extractor.init(bad, geometry(), 60, 80, 2));
  bad = config;
  bad.tile_max_normal_angle_deg = 91.0;
  EXPECT_FALSE(extractor.init(bad, geometry(), 60, 80, 2));
}

}  // namespace
}  // namespace deepnav
