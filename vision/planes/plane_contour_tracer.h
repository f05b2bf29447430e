#pragma once
#include <opencv2/core.hpp>

#include "vision/planes/plane_set.h"

namespace deepnav {

// Boundaries and holes of every plane of a label grid in one raster scan: the border following
// of Suzuki & Abe (1985, the algorithm behind cv::findContours) run on all labels at once, each
// label being the "1-pixels" of its own binary image. An outer-border start (left neighbour not
// the label, pixel unmarked) begins an outer boundary, a hole-border start (right neighbour not
// the label, pixel not marked as a right border) a hole; 8-connected borders, 4-connected holes,
// straight runs compressed to their ends (CHAIN_APPROX_SIMPLE). Unlike cv::findContours it needs
// no per-plane mask and allocates nothing per frame (marks grid sized in init(), vertices into
// the PlaneSet's fixed buffers).
class PlaneContourTracer {
 public:
  bool init(int rows, int cols);
  // labels: CV_8UC1 grid; plane_of_label[l] = index of label l's plane in *set, or -1 to skip;
  // 256 entries. Vertices are written in image pixels (cell * step_px). Holes whose polygon
  // encloses less than min_hole_area_px2 are dropped. Polygons are ordered per plane: outer
  // boundaries first (largest first), then holes (largest first); each Plane's polygon_begin/count
  // is set.
  bool trace(const cv::Mat& labels, const int* plane_of_label, int step_px,
             double min_hole_area_px2, PlaneSet* set);

 private:
  void traceBorder(const cv::Mat& labels, int r0, int c0, int start_dir, std::uint8_t label,
                   int step_px, PlaneSet* set, double* area2);
  std::uint8_t labelAt(const cv::Mat& labels, int r, int c) const {
    return (r < 0 || c < 0 || r >= rows_ || c >= cols_) ? 0 : labels.ptr<std::uint8_t>(r)[c];
  }

  int rows_ = 0;
  int cols_ = 0;
  cv::Mat marks_;  // CV_8SC1: 0 unmarked, 1 on a traced border, -1 traced with the east examined
};

}  // namespace deepnav
