#pragma once
#include <array>
#include <vector>

#include "vision/cloud/organized_cloud.h"
#include "vision/cloud/stereo_geometry.h"
#include "vision/planes/plane_contour_tracer.h"
#include "vision/planes/plane_extraction_config.h"
#include "vision/planes/plane_fit.h"
#include "vision/planes/plane_region_grower.h"
#include "vision/planes/plane_set.h"
#include "vision/planes/plane_tile_grower.h"

namespace deepnav {

// Planes of one organised cloud: region growing (PlaneRegionGrower, or PlaneTileGrower when
// config.growing is kTiles), a weighted fit with the
// plane-parameter Hessian and covariance per region (fitPlaneWithUncertainty), then boundary and
// hole polygons (PlaneContourTracer). Every buffer is sized in init(); extract() allocates nothing.
class PlaneExtractor {
 public:
  // rows, cols, step_px: the cloud grid (CloudFromDisparity::gridRows() ...); geometry gives the
  // stereo noise model (f B).
  bool init(const PlaneExtractionConfig& config, const StereoGeometry& geometry, int rows, int cols,
            int step_px);
  // Sizes a PlaneSet for this config (start-up).
  bool allocatePlaneSet(PlaneSet* set) const;
  // Fills *planes (cleared first); returns the number of planes, -1 on a size mismatch.
  int extract(const OrganizedCloud& cloud, PlaneSet* planes);

  // label of plane i: planes[i].label
  const cv::Mat& labels() const { return tiles() ? tile_grower_.labels() : grower_.labels(); }
  const PlaneRegionGrower& grower() const { return grower_; }  // growing == kPixels
  const PlaneTileGrower& tileGrower() const { return tile_grower_; }  // growing == kTiles
  const PlaneExtractionConfig& config() const { return config_; }

 private:
  bool tiles() const { return config_.growing == PlaneGrowingMethod::kTiles; }
  // The fit and polygons of the regions of either grower.
  template <class Grower>
  int fitAndTrace(const Grower& grower, int regions, const OrganizedCloud& cloud,
                  PlaneSet* planes);

  // Every region's cells into fits_ and bbox_of_label_: one raster pass over the labels
  // (bit for bit the sums of the pixel grower's fit), or tile by tile (the tile grower).
  void feedFits(const PlaneRegionGrower& grower, const OrganizedCloud& cloud);
  void feedFits(const PlaneTileGrower& grower, const OrganizedCloud& cloud);

  bool ready_ = false;
  PlaneExtractionConfig config_;
  PlaneNoiseModel noise_;
  int step_px_ = 1;
  PlaneRegionGrower grower_;
  PlaneTileGrower tile_grower_;
  PlaneContourTracer tracer_;
  std::array<int, 256> plane_of_label_{};
  std::array<int, 256> region_of_label_{};
  std::array<cv::Rect, 256> bbox_of_label_{};  // cells of each label, from the raster pass
  std::vector<Eigen::Vector4f> neighbour_planes_;  // max_planes per plane
  std::vector<PlaneFitAccumulator> fits_;
};

}  // namespace deepnav
