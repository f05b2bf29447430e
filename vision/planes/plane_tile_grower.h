#pragma once
#include <array>
#include <bitset>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "vision/cloud/organized_cloud.h"
#include "vision/planes/plane_extraction_config.h"
#include "vision/planes/plane_region_grower.h"
#include "vision/planes/tile_sums.h"

namespace deepnav {

// Cell-based region growing after Proenca & Gao, "Fast Cylinder and Plane Extraction from Depth
// Cameras for Visual Odometry" (CAPE, IROS 2018), with the stereo noise model and the tests of
// PlaneRegionGrower:
//  1. the cloud is cut into tiles of tile_size_px; each tile's moments are summed once (TileSums,
//     SIMD) and the tile is planar when enough of its cells are valid and its noise-corrected MSE
//     is small;
//  2. planar tiles are seeds, flattest first; a region grows breadth-first over the 4-neighbour
//     tile graph: a tile joins when its normal agrees with the region's, its centroid passes the
//     point-to-plane test and the region's MSE with it passes the region test (all from the
//     moments, refitted after every tile); a region smaller than min_area_px releases its tiles;
//  3. pixel refinement (so boundaries are cut at the cell, not at the tile): a region's tiles whose
//     every valid cell is nearest to its plane (of the planes of the tile and its 8 neighbours that
//     the cell passes) are its core; the regions then grow breadth-first from their cores, all at
//     once, into the other cells of their tiles and of the tiles around them, a cell joining the
//     region that reaches it when that region's plane is the nearest it passes; the cells left over
//     then join any region that reaches them and whose point test they pass. Each region is thus
//     one connected set of cells, as in the pixel grower (the nearest plane per cell alone, the
//     first version, left specks of one plane inside the other along intersection lines), and its
//     moments and normal are taken from the cells it ends with.
// The outputs are PlaneRegionGrower's: a label grid (0 = no plane), one PlaneRegion per label
// (moments, noise-corrected normal, cell count) and the 4-neighbour adjacency of the labels.
// All buffers are sized in init(); grow() allocates nothing.
class PlaneTileGrower {
 public:
  bool init(const PlaneExtractionConfig& config, double fx_px, double focal_baseline_pxm, int rows,
            int cols, int step_px);
  // Grows the regions of cloud; returns their number (-1 if the cloud does not match init()).
  int grow(const OrganizedCloud& cloud);

  const cv::Mat& labels() const { return labels_; }  // CV_8UC1: 0 = no plane
  const PlaneRegion& region(int i) const { return regions_[i]; }
  const std::bitset<256>& adjacentLabels(std::uint8_t l) const { return adjacent_[l]; }
  int seedsTried() const { return seeds_tried_; }
  long tilesAdmitted() const { return tiles_admitted_; }  // over all attempts, kept or released
  int tileRows() const { return tile_rows_; }
  int tileCols() const { return tile_cols_; }
  int tileCount() const { return static_cast<int>(tiles_.size()); }
  const TileView& tileView(int i) const { return tiles_[i].view; }
  const cv::Vec3f& tileRef(int i) const { return tiles_[i].ref; }  // a valid point of the tile
  const cv::Vec3f& tileLow(int i) const { return tiles_[i].lo; }  // box of its valid points
  const cv::Vec3f& tileHigh(int i) const { return tiles_[i].hi; }
  const TileSums& tileSums(int i) const { return tiles_[i].sums; }  // relative to tileRef
  // The label of every valid cell of tile i when they all got the same one, else 0.
  std::uint8_t tileWholeLabel(int i) const { return tiles_[i].whole_label; }
  // The labels the cells of tile i may hold after growing (its own region's and its 8
  // neighbours'); returns their number (0 for a tile without points).
  int tileLabels(int i, std::array<std::uint8_t, 9>* labels) const;
  // Region index of tile (tr, tc) after growing (-1: none).
  int tileRegion(int tr, int tc) const { return tiles_[tr * tile_cols_ + tc].region; }

 private:
  struct Tile {
    TileView view;
    cv::Vec3f ref;  // first valid point: origin of the sums
    cv::Vec3f lo, hi;  // bounding box of the valid points
    TileSums sums;
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    double sum_z2 = 0.0;  // sum of Z^2
    float mse = 0.0f;
    double cos_max_angle = 1.0;  // normal test of this tile against a region
    std::uint8_t whole_label = 0;  // see tileWholeLabel()
    bool planar = false;
    int region = -1;
    int stamp = 0;  // attempt that last examined the tile
  };
  struct Seed {
    float mse;
    std::int32_t tile;
  };
  // The plane of a region, for the pixel tests: |n.p - d| <= gamma + k_per_z * Z.
  struct PixelPlane {
    float nx, ny, nz, d, k_per_z;
    std::uint8_t label;
  };
  // A region while it grows: its sums, its plane and the sums along the plane's normal.
  struct GrowingRegion {
    ScatterSums sums;
    double sum_z2 = 0.0;
    Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
    double d = 0.0, abs_d = 0.0, sum_a = 0.0, sum_aa = 0.0;
  };
  void fitTiles(const OrganizedCloud& cloud);
  bool growRegion(int seed, int region_index);
  void refit(GrowingRegion* r) const;
  bool admits(const GrowingRegion& r, const Tile& t) const;
  int refineAndSum(const OrganizedCloud& cloud, int regions);
  int candidatesOf(int tile, std::array<int, 9>* candidates) const;
  struct TileCandidates;
  int labelOwnTile(const Tile& tile, const TileCandidates& t, std::uint8_t* labels);
  static float distance(const PixelPlane& q, const cv::Vec3f& p);  // |n.p - d|, m
  bool passes(const PixelPlane& q, const cv::Vec3f& p, float dist) const;
  void growBorders(const OrganizedCloud& cloud);
  void refitPixelPlanes(int regions);
  int nearestPassing(const TileCandidates& t, const cv::Vec3f& p) const;
  bool mayHold(const TileCandidates& t, int region, const cv::Vec3f& p) const;
  void findAdjacency(int regions);
  Eigen::Matrix3d noiseScatter(const ScatterSums& sums, double sum_z2) const;

  PlaneExtractionConfig config_;
  float noise_per_z2_ = 0.0f;  // sigma_d / (f B)
  double max_tile_angle_rad_ = 0.0;
  int rows_ = 0, cols_ = 0;
  int tile_cells_ = 2;  // tile side in grid cells
  int tile_rows_ = 0, tile_cols_ = 0;
  int min_cells_ = 0;
  int min_valid_per_tile_ = 1;
  cv::Mat labels_;
  std::vector<Tile> tiles_;
  std::vector<Seed> seeds_;
  std::vector<std::int32_t> queue_;
  std::vector<PlaneRegion> regions_;
  std::vector<PixelPlane> pixel_planes_;
  // The regions whose cells a tile may hold (its own and its 8 neighbours'), for the border growth.
  struct TileCandidates {
    std::array<int, 9> region{};
    int count = 0;
  };
  std::vector<TileCandidates> tile_candidates_;
  std::vector<bool> has_whole_tile_;    // per region, this frame
  std::vector<std::int32_t> tile_row_of_, tile_col_of_;  // tile row of a cell row, tile column of a cell column
  std::vector<std::int32_t> cell_queue_;  // the border growth's queue: each cell enters once
  std::vector<int> region_of_label_;  // label -> region index, -1 once dropped
  int attempt_ = 0;
  int seeds_tried_ = 0;
  long tiles_admitted_ = 0;
  std::array<std::bitset<256>, 256> adjacent_{};
};

}  // namespace deepnav
