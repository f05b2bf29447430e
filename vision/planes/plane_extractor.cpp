#include "vision/planes/plane_extractor.h"

#include <algorithm>

namespace deepnav {

bool PlaneExtractor::init(const PlaneExtractionConfig& config, const StereoGeometry& geometry,
                          int rows, int cols, int step_px) {
  ready_ = false;
  if (!geometry.isValid() || config.max_polygons < 1 || config.max_polygon_points < 1 ||
      config.disparity_noise_px <= 0.0 || config.point_noise_floor_m < 0.0 ||
      config.independent_points < 0.0) {
    return false;
  }
  const bool grower_ready =
      config.growing == PlaneGrowingMethod::kTiles
          ? tile_grower_.init(config, geometry.fx_px, geometry.focalBaseline(), rows, cols, step_px)
          : grower_.init(config, geometry.fx_px, geometry.focalBaseline(), rows, cols, step_px);
  if (!grower_ready) return false;
  if (!tracer_.init(rows, cols)) return false;
  config_ = config;
  step_px_ = step_px;
  noise_.disparity_noise_per_fb = config.disparity_noise_px / geometry.focalBaseline();
  noise_.floor_m = config.point_noise_floor_m;
  noise_.independent_points = config.independent_points;
  neighbour_planes_.assign(static_cast<std::size_t>(config.max_planes) * config.max_planes,
                           Eigen::Vector4f::Zero());
  fits_.assign(config.max_planes, PlaneFitAccumulator{});
  ready_ = true;
  return true;
}

bool PlaneExtractor::allocatePlaneSet(PlaneSet* set) const {
  return ready_ && set != nullptr &&
         set->allocate(config_.max_planes, config_.max_polygons, config_.max_polygon_points);
}

int PlaneExtractor::extract(const OrganizedCloud& cloud, PlaneSet* planes) {
  if (!ready_ || planes == nullptr || cloud.step_px != step_px_ ||
      planes->capacity() < config_.max_planes) {
    return -1;
  }
  planes->clear();
  if (tiles()) {
    const int regions = tile_grower_.grow(cloud);
    return regions < 0 ? -1 : fitAndTrace(tile_grower_, regions, cloud, planes);
  }
  const int regions = grower_.grow(cloud);
  return regions < 0 ? -1 : fitAndTrace(grower_, regions, cloud, planes);
}

void PlaneExtractor::feedFits(const PlaneRegionGrower& grower, const OrganizedCloud& cloud) {
  // One raster pass feeds every plane's fit (sequential reads of the cloud) and bounding box
  // (x, y: the smallest column and row; width, height: the largest, made sizes below).
  const cv::Mat& labels = grower.labels();
  for (int r = 0; r < cloud.rows(); ++r) {
    const std::uint8_t* l = labels.ptr<std::uint8_t>(r);
    const cv::Vec3f* p = cloud.row(r);
    for (int c = 0; c < cloud.cols();) {
      const std::uint8_t label = l[c];
      int end = c + 1;
      while (end < cloud.cols() && l[end] == label) ++end;
      if (label != 0) {
        fits_[region_of_label_[label]].addRun(p + c, end - c);
        cv::Rect& box = bbox_of_label_[label];
        box.x = std::min(box.x, c);
        box.y = std::min(box.y, r);
        box.width = std::max(box.width, end - 1);
        box.height = r;  // rows are visited in order
      }
      c = end;
    }
  }
}

// Tile by tile (the cells of a tile hold at most the labels of it and its neighbours): the
// moments in float lanes per tile (PlaneFitAccumulator::addTile), the boxes from the tiles' boxes.
// bbox_of_label_ as in the raster pass: x, y the smallest column and row, width, height the
// largest.
void PlaneExtractor::feedFits(const PlaneTileGrower& grower, const OrganizedCloud& cloud) {
  const std::uint8_t* labels = grower.labels().ptr<std::uint8_t>(0);
  const cv::Vec3f* points = cloud.row(0);
  std::array<std::uint8_t, 9> tile_labels{};
  for (int t = 0; t < grower.tileCount(); ++t) {
    const int count = grower.tileLabels(t, &tile_labels);
    const TileView& view = grower.tileView(t);
    const std::ptrdiff_t offset = view.points - points;
    const int r = static_cast<int>(offset / cloud.cols());
    const int c = static_cast<int>(offset % cloud.cols());
    // A tile wholly of one plane, every cell valid and no neighbouring plane's band near: its
    // moments are the grower's, its box the tile's.
    const std::uint8_t whole = grower.tileWholeLabel(t);
    if (whole != 0 && grower.tileSums(t).n == static_cast<float>(view.rows * view.cols) &&
        fits_[region_of_label_[whole]].addWholeTile(grower.tileSums(t), grower.tileRef(t),
                                                    grower.tileLow(t), grower.tileHigh(t))) {
      cv::Rect& b = bbox_of_label_[whole];
      b.x = std::min(b.x, c);
      b.y = std::min(b.y, r);
      b.width = std::max(b.width, c + view.cols - 1);
      b.height = std::max(b.height, r + view.rows - 1);
      continue;
    }
    for (int j = 0; j < count; ++j) {
      const std::uint8_t label = tile_labels[j];
      const cv::Rect box = fits_[region_of_label_[label]].addTile(
          view, grower.tileRef(t), grower.tileLow(t), grower.tileHigh(t), labels + offset,
          cloud.cols(), label);
      if (box.empty()) continue;
      cv::Rect& b = bbox_of_label_[label];
      b.x = std::min(b.x, c + box.x);
      b.y = std::min(b.y, r + box.y);
      b.width = std::max(b.width, c + box.x + box.width - 1);
      b.height = std::max(b.height, r + box.y + box.height - 1);
    }
  }
}

template <class Grower>
int PlaneExtractor::fitAndTrace(const Grower& grower, int regions, const OrganizedCloud& cloud,
                                PlaneSet* planes) {
  plane_of_label_.fill(-1);
  region_of_label_.fill(-1);
  for (int i = 0; i < regions; ++i) region_of_label_[grower.region(i).label] = i;
  // Neighbouring planes (the grower's estimates): their intersections are kept out of the fit.
  for (int i = 0; i < regions; ++i) {
    const PlaneRegion& region = grower.region(i);
    NeighbourBand band;
    band.planes = neighbour_planes_.data() + i * config_.max_planes;
    band.band_m = static_cast<float>(config_.max_point_distance_m);
    band.band_sigmas = static_cast<float>(config_.distance_sigmas + 3.0);
    const std::bitset<256>& adjacent = grower.adjacentLabels(region.label);
    for (int l = 1; l < 256 && band.count < config_.max_planes; ++l) {
      if (!adjacent.test(l) || region_of_label_[l] < 0) continue;
      const PlaneRegion& other = grower.region(region_of_label_[l]);
      neighbour_planes_[i * config_.max_planes + band.count++] << other.normal.cast<float>(),
          static_cast<float>(other.normal.dot(other.sums.mean()));
    }
    fits_[i].reset(region.sums, region.normal, noise_, band);
  }
  for (int i = 0; i < regions; ++i) {
    bbox_of_label_[grower.region(i).label] = cv::Rect(cloud.cols(), cloud.rows(), -1, -1);
  }
  feedFits(grower, cloud);
  for (int i = 0; i < regions; ++i) {
    const PlaneRegion& region = grower.region(i);
    Plane* plane = planes->addPlane();
    if (plane == nullptr) break;
    if (!fits_[i].solve(region.sums, region.member_count, plane)) {
      planes->removeLast();
      continue;
    }
    plane->label = region.label;
    const cv::Rect& box = bbox_of_label_[region.label];
    plane->bbox_cells = cv::Rect(box.x, box.y, box.width - box.x + 1, box.height - box.y + 1);
    plane_of_label_[region.label] = planes->size() - 1;
  }
  const double min_hole_area_px2 = config_.min_hole_area_px;
  tracer_.trace(grower.labels(), plane_of_label_.data(), step_px_, min_hole_area_px2, planes);
  return planes->size();
}

}  // namespace deepnav
