#include "vision/planes/plane_set.h"

namespace deepnav {

bool PlaneSet::allocate(int max_planes, int max_polygons, int max_polygon_points) {
  if (max_planes <= 0 || max_polygons <= 0 || max_polygon_points <= 0) return false;
  planes_.assign(max_planes, Plane{});
  polygons_.assign(max_polygons, PlanePolygon{});
  points_.assign(max_polygon_points, cv::Point());
  clear();
  return true;
}

void PlaneSet::clear() {
  plane_count_ = 0;
  polygon_count_ = 0;
  point_count_ = 0;
  building_ = false;
  truncated_ = false;
  truncated_polygons_ = 0;
}

Plane* PlaneSet::addPlane() {
  if (plane_count_ >= static_cast<int>(planes_.size())) return nullptr;
  Plane& plane = planes_[plane_count_++];
  plane = Plane{};
  return &plane;
}

const PlanePolygon* PlaneSet::boundary(int plane) const {
  const Plane& p = planes_[plane];
  if (p.polygon_count == 0 || polygons_[p.polygon_begin].is_hole) return nullptr;
  return &polygons_[p.polygon_begin];
}

int PlaneSet::holeCount(int plane) const {
  const Plane& p = planes_[plane];
  return boundary(plane) != nullptr ? p.polygon_count - 1 : p.polygon_count;
}

bool PlaneSet::beginPolygon(int plane, bool is_hole) {
  building_ = polygon_count_ < static_cast<int>(polygons_.size());
  if (!building_) return false;
  PlanePolygon& poly = polygons_[polygon_count_];
  poly = PlanePolygon{plane, is_hole, point_count_, 0, 0.0};
  truncated_ = false;
  return true;
}

void PlaneSet::addPolygonPoint(const cv::Point& p) {
  if (!building_) return;
  if (point_count_ >= static_cast<int>(points_.size())) {
    truncated_ = true;
    return;
  }
  points_[point_count_++] = p;
  ++polygons_[polygon_count_].point_count;
}

void PlaneSet::endPolygon(double area_px2) {
  if (!building_) return;
  polygons_[polygon_count_].area_px2 = area_px2;
  ++polygon_count_;
  if (truncated_) ++truncated_polygons_;
  building_ = false;
}

void PlaneSet::dropPolygon() {
  if (!building_) return;
  point_count_ = polygons_[polygon_count_].point_begin;
  building_ = false;
}

}  // namespace deepnav
