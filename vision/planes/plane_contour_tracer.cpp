#include "vision/planes/plane_contour_tracer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace deepnav {
namespace {

// Directions counter-clockwise on screen (rows grow downwards): E, NE, N, NW, W, SW, S, SE.
constexpr int kDr[8] = {0, -1, -1, -1, 0, 1, 1, 1};
constexpr int kDc[8] = {1, 1, 0, -1, -1, -1, 0, 1};
constexpr int kEast = 0;
constexpr int kWest = 4;

// End (one past) of the run of equal bytes starting at row[c], eight bytes per step.
int runEnd(const std::uint8_t* row, int c, int cols) {
  const std::uint8_t k = row[c];
  const std::uint64_t pattern = 0x0101010101010101ull * k;
  int end = c + 1;
  while (end + 8 <= cols) {
    std::uint64_t word;
    std::memcpy(&word, row + end, sizeof word);
    if (word != pattern) break;
    end += 8;
  }
  while (end < cols && row[end] == k) ++end;
  return end;
}

}  // namespace

bool PlaneContourTracer::init(int rows, int cols) {
  if (rows <= 0 || cols <= 0) return false;
  rows_ = rows;
  cols_ = cols;
  marks_.create(rows, cols, CV_8SC1);
  return true;
}

// Suzuki & Abe, border following, steps 3.1-3.5. (r0, c0) is the start pixel, start_dir points
// to its 0-neighbour (W for an outer border, E for a hole). Emits the vertices of the chain where
// the direction changes (and the start) and accumulates twice the shoelace area.
void PlaneContourTracer::traceBorder(const cv::Mat& labels, int r0, int c0, int start_dir,
                                     std::uint8_t label, int step_px, PlaneSet* set,
                                     double* area2) {
  std::int8_t* marks0 = marks_.ptr<std::int8_t>(0);
  auto mark = [&](int r, int c) -> std::int8_t& { return marks0[r * cols_ + c]; };
  cv::Point first(c0 * step_px, r0 * step_px), last = first;
  auto emit = [&](int r, int c) {
    const cv::Point p(c * step_px, r * step_px);
    set->addPolygonPoint(p);
    *area2 += static_cast<double>(last.x) * p.y - static_cast<double>(p.x) * last.y;
    last = p;
  };
  set->addPolygonPoint(first);
  *area2 = 0.0;
  // 3.1: clockwise from the 0-neighbour, the first pixel of the label.
  int d1 = -1;
  for (int i = 0; i < 8; ++i) {
    const int d = (start_dir - i) & 7;
    if (labelAt(labels, r0 + kDr[d], c0 + kDc[d]) == label) {
      d1 = d;
      break;
    }
  }
  if (d1 < 0) {  // isolated pixel
    mark(r0, c0) = -1;
    return;
  }
  const int r1 = r0 + kDr[d1], c1 = c0 + kDc[d1];
  int r3 = r0, c3 = c0;
  int back = d1;    // direction from (r3, c3) to the previous border pixel (i2, j2)
  int in_dir = -1;  // direction by which (r3, c3) was reached
  for (;;) {
    // 3.3: counter-clockwise from the one after (i2, j2), the first pixel of the label.
    bool east_zero = false;
    int d4 = back;
    for (int i = 1; i <= 8; ++i) {
      const int d = (back + i) & 7;
      if (labelAt(labels, r3 + kDr[d], c3 + kDc[d]) == label) {
        d4 = d;
        break;
      }
      if (d == kEast) east_zero = true;
    }
    // 3.4
    std::int8_t& m = mark(r3, c3);
    if (east_zero) {
      m = -1;
    } else if (m == 0) {
      m = 1;
    }
    if (in_dir >= 0 && in_dir != d4) emit(r3, c3);
    const int r4 = r3 + kDr[d4], c4 = c3 + kDc[d4];
    // 3.5: back at the start, coming from (i1, j1)
    if (r4 == r0 && c4 == c0 && r3 == r1 && c3 == c1) break;
    back = (d4 + 4) & 7;
    in_dir = d4;
    r3 = r4;
    c3 = c4;
  }
  *area2 += static_cast<double>(last.x) * first.y - static_cast<double>(first.x) * last.y;
}

bool PlaneContourTracer::trace(const cv::Mat& labels, const int* plane_of_label, int step_px,
                               double min_hole_area_px2, PlaneSet* set) {
  if (labels.rows != rows_ || labels.cols != cols_ || labels.type() != CV_8UC1 || set == nullptr) {
    return false;
  }
  // memset rather than Mat::setTo, which allocates (marks_ is continuous: created in init()).
  std::memset(marks_.data, 0, marks_.total());
  // A border can only start at the first or the last cell of a run of one label (inside a run
  // both horizontal neighbours hold the label): the scan visits those two cells per run, in
  // column order, and skips the run's interior eight cells at a time.
  auto startBorder = [&](int r, int c, std::uint8_t k, bool left_out, bool right_out) {
    const std::int8_t m = marks_.ptr<std::int8_t>(r)[c];
    bool is_hole;
    if (m == 0 && left_out) {
      is_hole = false;
    } else if (m != -1 && right_out) {
      is_hole = true;
    } else {
      return;
    }
    const bool stored = set->beginPolygon(plane_of_label[k], is_hole);
    double area2 = 0.0;
    traceBorder(labels, r, c, is_hole ? kEast : kWest, k, step_px, set, &area2);
    const double area = 0.5 * std::abs(area2);
    if (!stored) return;
    if (is_hole && area < min_hole_area_px2) {
      set->dropPolygon();
    } else {
      set->endPolygon(area);
    }
  };
  for (int r = 0; r < rows_; ++r) {
    const std::uint8_t* l = labels.ptr<std::uint8_t>(r);
    for (int c = 0; c < cols_;) {
      const std::uint8_t k = l[c];
      const int end = runEnd(l, c, cols_);
      if (k != 0 && plane_of_label[k] >= 0) {
        startBorder(r, c, k, true, end == c + 1);
        if (end - 1 > c) startBorder(r, end - 1, k, false, true);
      }
      c = end;
    }
  }
  // Per plane: outer boundaries, then holes, each largest first.
  PlanePolygon* polygons = set->polygons();
  std::sort(polygons, polygons + set->polygonCount(),
            [](const PlanePolygon& a, const PlanePolygon& b) {
              if (a.plane != b.plane) return a.plane < b.plane;
              if (a.is_hole != b.is_hole) return !a.is_hole;
              if (a.area_px2 != b.area_px2) return a.area_px2 > b.area_px2;
              return a.point_begin < b.point_begin;
            });
  for (int i = 0; i < set->size(); ++i) {
    (*set)[i].polygon_begin = 0;
    (*set)[i].polygon_count = 0;
  }
  for (int i = set->polygonCount() - 1; i >= 0; --i) {
    Plane& plane = (*set)[polygons[i].plane];
    plane.polygon_begin = i;
    ++plane.polygon_count;
  }
  return true;
}

}  // namespace deepnav
