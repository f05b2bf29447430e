#include <gtest/gtest.h>

#include <array>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "vision/planes/plane_contour_tracer.h"

namespace deepnav {
namespace {

std::vector<cv::Point> points(const PlaneSet& set, const PlanePolygon& polygon) {
  std::vector<cv::Point> pts;
  for (int i = 0; i < polygon.point_count; ++i) {
    pts.push_back(set.polygonPoint(polygon.point_begin + i));
  }
  return pts;
}

// Plane 1: a 40 x 30 rectangle with two holes; plane 2: an island inside the second hole.
cv::Mat nestedLabels() {
  cv::Mat labels(40, 50, CV_8UC1, cv::Scalar(0));
  labels(cv::Rect(5, 5, 40, 30)).setTo(1);
  labels(cv::Rect(10, 10, 10, 5)).setTo(0);   // hole A
  labels(cv::Rect(25, 20, 15, 10)).setTo(0);  // hole B
  labels(cv::Rect(28, 22, 9, 6)).setTo(2);    // island in hole B
  return labels;
}

struct Traced {
  PlaneSet set;
  std::array<int, 256> plane_of_label;
};

Traced trace(const cv::Mat& labels, int step_px, double min_hole_area) {
  Traced t;
  EXPECT_TRUE(t.set.allocate(4, 16, 1024));
  t.set.addPlane()->label = 1;
  t.set.addPlane()->label = 2;
  t.plane_of_label.fill(-1);
  t.plane_of_label[1] = 0;
  t.plane_of_label[2] = 1;
  PlaneContourTracer tracer;
  EXPECT_TRUE(tracer.init(labels.rows, labels.cols));
  EXPECT_TRUE(tracer.trace(labels, t.plane_of_label.data(), step_px, min_hole_area, &t.set));
  return t;
}

TEST(PlaneContourTracer, OuterBoundaryHolesAndIslandOfNestedPlanes) {
  // GIVEN a plane with two rectangular holes and a second plane inside one of them
  const cv::Mat labels = nestedLabels();
  // WHEN traced
  const Traced t = trace(labels, 1, 10.0);
  // THEN plane 1 has its rectangle as boundary (4 corners, through the border cells) and two holes
  // whose polygons run through the plane cells around them
  ASSERT_EQ(t.set[0].polygon_count, 3);
  const PlanePolygon* outer = t.set.boundary(0);
  ASSERT_NE(outer, nullptr);
  EXPECT_EQ(cv::boundingRect(points(t.set, *outer)), cv::Rect(5, 5, 40, 30));
  EXPECT_EQ(outer->point_count, 4);
  EXPECT_DOUBLE_EQ(outer->area_px2, 39.0 * 29.0);
  EXPECT_EQ(t.set.holeCount(0), 2);
  const PlanePolygon& big_hole = t.set.polygon(t.set[0].polygon_begin + 1);  // largest first
  const PlanePolygon& small_hole = t.set.polygon(t.set[0].polygon_begin + 2);
  EXPECT_TRUE(big_hole.is_hole);
  EXPECT_TRUE(small_hole.is_hole);
  EXPECT_EQ(cv::boundingRect(points(t.set, big_hole)), cv::Rect(24, 19, 17, 12));
  EXPECT_EQ(cv::boundingRect(points(t.set, small_hole)), cv::Rect(9, 9, 12, 7));
  EXPECT_NEAR(small_hole.area_px2, 11.0 * 6.0, 2.0);  // corners may be cut diagonally
  // THEN the island is plane 2's outer boundary, without holes
  ASSERT_EQ(t.set[1].polygon_count, 1);
  EXPECT_FALSE(t.set.polygon(t.set[1].polygon_begin).is_hole);
  EXPECT_EQ(cv::boundingRect(points(t.set, *t.set.boundary(1))), cv::Rect(28, 22, 9, 6));
  EXPECT_EQ(t.set.truncatedPolygons(), 0);
}

TEST(PlaneContourTracer, MatchesOpenCvFindContoursOnAConcaveShapeWithHole) {
  // GIVEN a U-shaped region with a hole in one arm
  cv::Mat labels(30, 30, CV_8UC1, cv::Scalar(0));
  labels(cv::Rect(3, 3, 24, 24)).setTo(1);
  labels(cv::Rect(10, 3, 10, 15)).setTo(0);  // the notch of the U, open at the top
  labels(cv::Rect(5, 15, 3, 6)).setTo(0);    // a hole in the left arm
  cv::Mat binary = labels.clone();
  std::vector<std::vector<cv::Point>> contours;
  std::vector<cv::Vec4i> hierarchy;
  cv::findContours(binary, contours, hierarchy, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE);
  // WHEN traced
  const Traced t = trace(labels, 1, 1.0);
  // THEN the same outer contour and the same hole as OpenCV (same algorithm family)
  ASSERT_EQ(contours.size(), 2u);
  ASSERT_EQ(t.set[0].polygon_count, 2);
  const std::vector<cv::Point> outer = points(t.set, *t.set.boundary(0));
  const std::vector<cv::Point> hole = points(t.set, t.set.polygon(t.set[0].polygon_begin + 1));
  const int cv_outer = hierarchy[0][3] < 0 ? 0 : 1;
  EXPECT_EQ(cv::boundingRect(outer), cv::boundingRect(contours[cv_outer]));
  EXPECT_DOUBLE_EQ(t.set.boundary(0)->area_px2, cv::contourArea(contours[cv_outer]));
  EXPECT_EQ(cv::boundingRect(hole), cv::boundingRect(contours[1 - cv_outer]));
  EXPECT_DOUBLE_EQ(t.set.polygon(t.set[0].polygon_begin + 1).area_px2,
                   cv::contourArea(contours[1 - cv_outer]));
}

TEST(PlaneContourTracer, StepScalesVerticesAndSmallHolesAreDropped) {
  const cv::Mat labels = nestedLabels();
  // WHEN traced at step 2 with a minimum hole area between the two holes' areas
  const Traced t = trace(labels, 2, 4.0 * 100.0);
  // THEN vertices are in image pixels and only the big hole is kept
  EXPECT_EQ(cv::boundingRect(points(t.set, *t.set.boundary(0))), cv::Rect(10, 10, 79, 59));
  EXPECT_EQ(t.set.holeCount(0), 1);
  EXPECT_DOUBLE_EQ(t.set.boundary(0)->area_px2, 4.0 * 39.0 * 29.0);
}

TEST(PlaneContourTracer, FullPolygonBufferTruncatesButKeepsTracing) {
  const cv::Mat labels = nestedLabels();
  PlaneSet set;
  ASSERT_TRUE(set.allocate(2, 16, 6));  // room for 6 vertices only
  set.addPlane()->label = 1;
  set.addPlane()->label = 2;
  std::array<int, 256> plane_of_label;
  plane_of_label.fill(-1);
  plane_of_label[1] = 0;
  plane_of_label[2] = 1;
  PlaneContourTracer tracer;
  ASSERT_TRUE(tracer.init(labels.rows, labels.cols));
  ASSERT_TRUE(tracer.trace(labels, plane_of_label.data(), 1, 1.0, &set));
  EXPECT_GT(set.truncatedPolygons(), 0);
  EXPECT_EQ(set[0].polygon_count, 3);  // every border was still found once
  EXPECT_EQ(set[1].polygon_count, 1);
}

}  // namespace
}  // namespace deepnav
