#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <opencv2/imgproc.hpp>

#include "tests/support/synthetic_scene.h"
#include "tests/unit/planes_test_scene.h"
#include "vision/cloud/cloud_from_disparity.h"
#include "vision/planes/plane_extractor.h"
#include "vision/stereo/disparity_estimator.h"

namespace deepnav {
namespace {

using namespace planes_test;

// A rectangle's plane in the camera frame, oriented to the camera: (n, d) with n . p = d < 0.
std::pair<Eigen::Vector3d, double> planeInCamera(const SyntheticRectangle& rect,
                                                 const Eigen::Isometry3d& T_world_cam) {
  const Eigen::Isometry3d T_cam_world = T_world_cam.inverse();
  Eigen::Vector3d n = T_cam_world.linear() * rect.normal();
  const Eigen::Vector3d c = T_cam_world * rect.centre_m;
  double d = n.dot(c);
  if (d > 0.0) {
    n = -n;
    d = -d;
  }
  return {n, d};
}

void addDisparityNoise(double sigma_px, cv::Mat* disparity) {
  cv::Mat noise(disparity->size(), CV_32FC1);
  cv::RNG rng(42);
  rng.fill(noise, cv::RNG::NORMAL, 0.0, sigma_px);
  cv::Mat valid = *disparity > 0.0f;
  cv::add(*disparity, noise, *disparity, valid);
}

struct Fixture {
  SyntheticScene scene = boxOnFloor();
  Eigen::Isometry3d T_world_cam = cameraPitchedDown(30.0 * kDeg, Eigen::Vector3d(0.0, 0.0, 1.6));  // 1.6 m up
  SyntheticView view;
  OrganizedCloud cloud;
  PlaneExtractor extractor;
  PlaneSet planes;
};

// Both growers: the pixel grower (the reference) and the tile grower (the default), which must pass the
// same test.
class PlaneExtractionByGrower : public ::testing::TestWithParam<PlaneGrowingMethod> {};

TEST_P(PlaneExtractionByGrower, FindsFloorAndBoxFacesWithNormalsOffsetsAndHole) {
  // GIVEN a noisy (0.2 px) disparity map of a box on the floor, with a 40 x 20 px patch of the
  // floor without disparity (a dark, textureless spot)
  Fixture f;
  renderSyntheticView(f.scene, geometry(), kWidth, kHeight, f.T_world_cam, false, &f.view);
  const cv::Rect hole(40, 205, 40, 20);
  ASSERT_EQ(cv::countNonZero(f.view.surface(hole + cv::Size(4, 4) - cv::Point(2, 2)) != 0), 0)
      << "the patch and its border lie on the floor";
  addDisparityNoise(0.2, &f.view.disparity_px);
  f.view.disparity_px(hole).setTo(kInvalidDisparity);
  CloudFromDisparity builder;
  ASSERT_TRUE(builder.init(geometry(), CloudConfig{}, kWidth, kHeight));
  ASSERT_TRUE(builder.allocateCloud(&f.cloud));
  ASSERT_TRUE(builder.compute(f.view.disparity_px, &f.cloud));
  PlaneExtractionConfig config;
  config.min_area_px = 1500;
  config.disparity_noise_px = 0.2;
  config.growing = GetParam();
  ASSERT_TRUE(f.extractor.init(config, geometry(), builder.gridRows(), builder.gridCols(), 1));
  ASSERT_TRUE(f.extractor.allocatePlaneSet(&f.planes));

  // WHEN the planes are extracted
  const int count = f.extractor.extract(f.cloud, &f.planes);

  // THEN the floor, the box top and the two visible box sides are found, each once, with their
  // true normal and offset
  ASSERT_EQ(count, 4);
  const int truth_ids[4] = {0, 1, 4, 6};  // floor, box top, box faces -x', -y' (yaw 40 deg)
  for (int id : truth_ids) ASSERT_GT(cv::countNonZero(f.view.surface == id), 3000) << id;
  int floor_index = -1;
  for (int id : truth_ids) {
    const auto [n_true, d_true] = planeInCamera(f.scene.rectangles[id], f.T_world_cam);
    int found = -1;
    for (int i = 0; i < count; ++i) {
      if (f.planes[i].n_in_cam.dot(n_true) > std::cos(3.0 * kDeg) &&
          std::abs(f.planes[i].d_m - d_true) < 0.05) {
        EXPECT_EQ(found, -1) << "surface " << id << " found twice";
        found = i;
      }
    }
    ASSERT_GE(found, 0) << "surface " << id << " not found";
    const Plane& p = f.planes[found];
    EXPECT_LT(std::acos(std::min(1.0, p.n_in_cam.dot(n_true))), 0.5 * kDeg) << id;
    EXPECT_NEAR(p.d_m, d_true, 0.01) << id;
    EXPECT_LT(p.d_m, 0.0);
    EXPECT_LT(p.n_in_cam.dot(p.p_centroid_in_cam_m), 0.0);
    EXPECT_NEAR(p.n_in_cam.dot(p.p_centroid_in_cam_m), p.d_m, 1e-9);
    EXPECT_LT(p.rms_m, 0.03);
    // the bounding box (from the fit's raster pass) is that of the plane's label cells
    EXPECT_EQ(p.bbox_cells, cv::boundingRect(f.extractor.labels() == p.label)) << id;
    // covariance: symmetric, positive semi-definite, tiny for thousands of points
    EXPECT_TRUE(p.covariance.isApprox(p.covariance.transpose(), 1e-9));
    EXPECT_GT(p.covariance.trace(), 0.0);
    EXPECT_LT(p.offsetVariance(), 1e-4);
    // H (n, d) = 0: the Hessian's null direction is the plane vector itself
    Eigen::Vector4d theta;
    theta << p.n_in_cam, p.d_m;
    EXPECT_LT((p.hessian * theta).norm(), 1e-6 * p.hessian.norm());
    if (id == 0) floor_index = found;
  }

  // THEN the floor's outer boundary spans its cells and its holes include the patch: the hole
  // polygon runs through the floor cells around it, one pixel outside the patch
  const PlanePolygon* boundary = f.planes.boundary(floor_index);
  ASSERT_NE(boundary, nullptr);
  const cv::Mat floor_mask = f.extractor.labels() == f.planes[floor_index].label;
  const cv::Rect floor_bbox = cv::boundingRect(floor_mask);
  std::vector<cv::Point> outer;
  for (int i = 0; i < boundary->point_count; ++i) {
    outer.push_back(f.planes.polygonPoint(boundary->point_begin + i));
  }
  EXPECT_EQ(cv::boundingRect(outer), floor_bbox);
  double hole_area = 0.0;
  for (int k = 1; k < f.planes[floor_index].polygon_count; ++k) {
    hole_area += f.planes.polygon(f.planes[floor_index].polygon_begin + k).area_px2;
  }
  // the boundary encloses the holes (the box's silhouette is one)
  const int floor_cells = cv::countNonZero(floor_mask);
  EXPECT_NEAR(boundary->area_px2 - hole_area, floor_cells, 0.05 * floor_cells);
  int patch_holes = 0;
  for (int k = 0; k < f.planes[floor_index].polygon_count; ++k) {
    const PlanePolygon& poly = f.planes.polygon(f.planes[floor_index].polygon_begin + k);
    if (!poly.is_hole) continue;
    std::vector<cv::Point> pts;
    for (int i = 0; i < poly.point_count; ++i)
      pts.push_back(f.planes.polygonPoint(poly.point_begin + i));
    const cv::Rect box = cv::boundingRect(pts);
    if ((box & hole) == hole) {
      ++patch_holes;
      const cv::Rect expected(hole.x - 1, hole.y - 1, hole.width + 2, hole.height + 2);
      EXPECT_LE(std::abs(box.x - expected.x), 1);
      EXPECT_LE(std::abs(box.y - expected.y), 1);
      EXPECT_LE(std::abs(box.br().x - expected.br().x), 1);
      EXPECT_LE(std::abs(box.br().y - expected.br().y), 1);
      EXPECT_NEAR(poly.area_px2, (hole.width + 1) * (hole.height + 1), 0.1 * hole.area());
    }
  }
  EXPECT_EQ(patch_holes, 1);
  // the box faces have no hole
  for (int i = 0; i < count; ++i) {
    if (i != floor_index) {
      EXPECT_EQ(f.planes.holeCount(i), 0) << i;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Growers, PlaneExtractionByGrower,
                         ::testing::Values(PlaneGrowingMethod::kPixels, PlaneGrowingMethod::kTiles),
                         [](const ::testing::TestParamInfo<PlaneGrowingMethod>& info) {
                           return std::string(info.param == PlaneGrowingMethod::kTiles ? "Tiles" : "Pixels");
                         });

TEST(PlaneExtraction, NothingOnAnEmptyCloudAndSizeMismatchIsRefused) {
  PlaneExtractor extractor;
  PlaneExtractionConfig config;
  ASSERT_TRUE(extractor.init(config, geometry(), 60, 80, 2));
  PlaneSet planes;
  ASSERT_TRUE(extractor.allocatePlaneSet(&planes));
  OrganizedCloud cloud;
  ASSERT_TRUE(cloud.allocate(60, 80, 2));
  EXPECT_EQ(extractor.extract(cloud, &planes), 0);
  OrganizedCloud other;
  ASSERT_TRUE(other.allocate(61, 80, 2));
  EXPECT_EQ(extractor.extract(other, &planes), -1);
  EXPECT_FALSE(extractor.init(PlaneExtractionConfig{.max_planes = 0}, geometry(), 60, 80, 2));
}

}  // namespace
}  // namespace deepnav
