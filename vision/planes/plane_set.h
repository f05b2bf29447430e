#pragma once
#include <vector>

#include "vision/planes/plane.h"

namespace deepnav {

// The planes of one frame with their polygons, in buffers of fixed capacity sized once.
class PlaneSet {
 public:
  // Start-up only. Returns false for non-positive capacities.
  bool allocate(int max_planes, int max_polygons, int max_polygon_points);
  void clear();

  int size() const { return plane_count_; }
  const Plane& operator[](int i) const { return planes_[i]; }
  Plane& operator[](int i) { return planes_[i]; }
  // Appends a default plane; nullptr when full.
  Plane* addPlane();
  void removeLast() {
    if (plane_count_ > 0) --plane_count_;
  }

  int polygonCount() const { return polygon_count_; }
  const PlanePolygon& polygon(int i) const { return polygons_[i]; }
  const cv::Point& polygonPoint(int i) const { return points_[i]; }
  // The outer boundary of plane i, nullptr if it has none (polygon buffers ran out).
  const PlanePolygon* boundary(int plane) const;
  int holeCount(int plane) const;

  // Polygon building (used by the extractor). beginPolygon fails when the polygon buffer is full;
  // addPoint silently drops points beyond capacity and flags the polygon as truncated.
  bool beginPolygon(int plane, bool is_hole);
  void addPolygonPoint(const cv::Point& p);
  void endPolygon(double area_px2);
  void dropPolygon();  // discards the polygon being built
  PlanePolygon* polygons() { return polygons_.data(); }
  int truncatedPolygons() const { return truncated_polygons_; }
  int capacity() const { return static_cast<int>(planes_.size()); }

 private:
  std::vector<Plane> planes_;
  std::vector<PlanePolygon> polygons_;
  std::vector<cv::Point> points_;
  int plane_count_ = 0;
  int polygon_count_ = 0;
  int point_count_ = 0;
  bool building_ = false;
  bool truncated_ = false;
  int truncated_polygons_ = 0;
};

}  // namespace deepnav
