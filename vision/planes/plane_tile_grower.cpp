#include "vision/planes/plane_tile_grower.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <Eigen/Eigenvalues>
#include <limits>
#include <opencv2/core/hal/intrin.hpp>

namespace deepnav {
namespace {

Eigen::Vector3d toDouble(const cv::Vec3f& p) { return Eigen::Vector3d(p[0], p[1], p[2]); }

Eigen::Matrix3d secondMomentOf(const TileSums& t) {
  Eigen::Matrix3d s;
  s << t.sxx, t.sxy, t.sxz, t.sxy, t.syy, t.syz, t.sxz, t.syz, t.szz;
  return s;
}

// Sum of Z^2 of the points of sums (Z = z + origin_z).
double sumDepthSquared(const ScatterSums& s) {
  const double oz = s.origin.z();
  return s.szz + 2.0 * oz * s.sz + s.n * oz * oz;
}

}  // namespace

bool PlaneTileGrower::init(const PlaneExtractionConfig& config, double fx_px,
                           double focal_baseline_pxm, int rows, int cols, int step_px) {
  if (rows <= 0 || cols <= 0 || step_px <= 0 || focal_baseline_pxm <= 0.0 || fx_px <= 0.0 ||
      config.max_planes < 1 || config.max_planes > 250 || config.max_point_distance_m <= 0.0 ||
      config.max_mse_m2 <= 0.0 || config.min_area_px < 1 || config.tile_size_px < 4 ||
      config.tile_size_px > 64 || !(config.tile_min_valid_fraction > 0.0) ||
      config.tile_min_valid_fraction > 1.0 || !(config.tile_max_normal_angle_deg > 0.0) ||
      config.tile_max_normal_angle_deg > 90.0) {
    return false;
  }
  config_ = config;
  noise_per_z2_ = static_cast<float>(config.disparity_noise_px / focal_baseline_pxm);
  max_tile_angle_rad_ = config.tile_max_normal_angle_deg * M_PI / 180.0;
  rows_ = rows;
  cols_ = cols;
  tile_cells_ = std::max(2, config.tile_size_px / step_px);
  tile_rows_ = (rows + tile_cells_ - 1) / tile_cells_;
  tile_cols_ = (cols + tile_cells_ - 1) / tile_cells_;
  const int step2 = step_px * step_px;
  min_cells_ = (config.min_area_px + step2 - 1) / step2;
  min_valid_per_tile_ = std::max(
      3, static_cast<int>(std::ceil(config.tile_min_valid_fraction * tile_cells_ * tile_cells_)));
  labels_.create(rows, cols, CV_8UC1);
  tiles_.assign(static_cast<std::size_t>(tile_rows_) * tile_cols_, Tile{});
  seeds_.assign(tiles_.size(), Seed{});
  queue_.assign(tiles_.size(), 0);
  tile_candidates_.assign(tiles_.size(), TileCandidates{});
  has_whole_tile_.assign(config.max_planes, false);
  tile_row_of_.resize(rows);
  for (int r = 0; r < rows; ++r) tile_row_of_[r] = r / tile_cells_;
  tile_col_of_.resize(cols);
  for (int c = 0; c < cols; ++c) tile_col_of_[c] = c / tile_cells_;
  cell_queue_.assign(static_cast<std::size_t>(rows) * cols, 0);
  regions_.assign(config.max_planes, PlaneRegion{});
  pixel_planes_.assign(config.max_planes, PixelPlane{});
  region_of_label_.assign(256, -1);
  attempt_ = 0;
  return true;
}

// Expected scatter of the stereo noise along the rays (as PlaneRegionGrower::noiseScatter).
Eigen::Matrix3d PlaneTileGrower::noiseScatter(const ScatterSums& sums, double sum_z2) const {
  const double kd2 = static_cast<double>(noise_per_z2_) * noise_per_z2_;
  return kd2 * (sum_z2 / sums.n) * sums.secondMoment();
}

// Step 1: moments, plane and flatness of every tile. Partial tiles at the right and bottom edges
// are kept (their valid fraction is judged on the full tile size).
void PlaneTileGrower::fitTiles(const OrganizedCloud& cloud) {
  for (int tr = 0; tr < tile_rows_; ++tr) {
    for (int tc = 0; tc < tile_cols_; ++tc) {
      Tile& t = tiles_[tr * tile_cols_ + tc];
      const int r0 = tr * tile_cells_, c0 = tc * tile_cells_;
      t = Tile{};
      t.view = TileView{cloud.row(r0) + c0, cols_, std::min(tile_cells_, rows_ - r0),
                        std::min(tile_cells_, cols_ - c0)};
      bool found = false;
      for (int r = 0; r < t.view.rows && !found; ++r) {
        const cv::Vec3f* p = t.view.points + r * t.view.stride;
        for (int c = 0; c < t.view.cols; ++c) {
          if (OrganizedCloud::isValid(p[c])) {
            t.ref = p[c];
            found = true;
            break;
          }
        }
      }
      if (!found) continue;
      t.sums = sumTile(t.view, t.ref, &t.lo, &t.hi);
      if (t.sums.n < static_cast<float>(min_valid_per_tile_)) continue;
      ScatterSums s;
      s.reset(toDouble(t.ref));
      addTileSums(t.sums, t.ref, &s);
      t.sum_z2 = sumDepthSquared(s);
      // The plain fit, as PlaneRegionGrower's seed patches: over a tile a few centimetres wide the
      // modelled noise scatter is of the order of the scatter itself (dense stereo errors are
      // smoother than the model), and subtracting it turns the normal towards the viewing ray.
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
      eig.computeDirect(s.scatter());
      const double mse = std::max(0.0, eig.eigenvalues()(0)) / s.n;
      t.normal = eig.eigenvectors().col(0);
      t.centroid = s.mean();
      t.mse = static_cast<float>(mse);
      const double sigma_z = noise_per_z2_ * t.centroid.z() * t.centroid.z();
      t.planar = mse <= config_.max_mse_m2 + sigma_z * sigma_z;
      // Normal test widened by the tile's own roughness: atan(rms / in-plane spread) along its
      // narrower axis, sqrt(lambda_0 / lambda_1), twice. Dense stereo errors are correlated over
      // a tile (ELAS interpolates between support points), so the least-squares slope error of
      // independent points, that over sqrt(n), is far too small: on a face 3.7 m away (rms 2 cm
      // over 10 cm tiles) the tile normals were 10-80 deg off the face's and growth stopped.
      // Such tiles are then joined on the distance and MSE tests alone.
      const double roughness = std::atan(std::sqrt(std::max(0.0, eig.eigenvalues()(0)) /
                                                    std::max(eig.eigenvalues()(1), 1e-12)));
      t.cos_max_angle = std::cos(std::min(M_PI / 2.0, max_tile_angle_rad_ + 2.0 * roughness));
    }
  }
}

// Step 2: breadth-first growth over the tile graph from one seed tile.
// The region's plane refitted from its sums (noise-corrected normal), and the running sums along its
// normal n, a = n . (p - origin), as in PlaneRegionGrower.
void PlaneTileGrower::refit(GrowingRegion* r) const {
  r->n = fitPlane(r->sums, noiseScatter(r->sums, r->sum_z2)).normal;
  r->d = r->n.dot(r->sums.mean());
  r->abs_d = std::abs(r->d);
  const ScatterSums& m = r->sums;
  Eigen::Matrix3d s;
  s << m.sxx, m.sxy, m.sxz, m.sxy, m.syy, m.syz, m.sxz, m.syz, m.szz;
  r->sum_a = r->n.dot(Eigen::Vector3d(m.sx, m.sy, m.sz));
  r->sum_aa = r->n.dot(s * r->n);
}

// Normal test, point test on the tile's centroid, region test with the tile's cells, all from moments.
bool PlaneTileGrower::admits(const GrowingRegion& r, const Tile& t) const {
  const Eigen::Vector3d& n = r.n;
  const double kd = noise_per_z2_;
  if (std::abs(n.dot(t.normal)) < t.cos_max_angle) return false;
  // point test on the centroid: sigma = sigma_d / (f B) Z |d| (PlaneNoiseModel)
  if (std::abs(n.dot(t.centroid) - r.d) >
      config_.max_point_distance_m + config_.distance_sigmas * kd * t.centroid.z() * r.abs_d) {
    return false;
  }
  // region test with the tile's cells: a = n . (q + delta), q relative to the tile's ref
  const Eigen::Vector3d delta = toDouble(t.ref) - r.sums.origin;
  const Eigen::Vector3d s1_t(t.sums.sx, t.sums.sy, t.sums.sz);
  const double nt = t.sums.n;
  const double n_delta = n.dot(delta);
  const double n_s = n.dot(s1_t);
  const double a1 = n_s + nt * n_delta;
  const double a2 = n.dot(secondMomentOf(t.sums) * n) + 2.0 * n_delta * n_s + nt * n_delta * n_delta;
  const double n1 = r.sums.n + nt;
  const double s1 = r.sum_a + a1;
  const double s2 = r.sum_aa + a2;
  const double var = kd * kd * r.abs_d * r.abs_d * (r.sum_z2 + t.sum_z2);
  return s2 * n1 - s1 * s1 <= (config_.max_mse_m2 * n1 + var) * n1;
}

bool PlaneTileGrower::growRegion(int seed, int region_index) {
  const int attempt = ++attempt_;
  Tile& first = tiles_[seed];
  GrowingRegion r;
  r.sums.reset(toDouble(first.ref));
  addTileSums(first.sums, first.ref, &r.sums);
  r.sum_z2 = first.sum_z2;
  first.region = region_index;
  first.stamp = attempt;
  int queue_end = 0;
  queue_[queue_end++] = seed;
  refit(&r);

  for (int head = 0; head < queue_end; ++head) {
    const int tile = queue_[head];
    const int tr = tile / tile_cols_, tc = tile % tile_cols_;
    const int neighbours[4] = {tc > 0 ? tile - 1 : -1, tc + 1 < tile_cols_ ? tile + 1 : -1,
                               tr > 0 ? tile - tile_cols_ : -1,
                               tr + 1 < tile_rows_ ? tile + tile_cols_ : -1};
    for (int next : neighbours) {
      if (next < 0) continue;
      Tile& t = tiles_[next];
      if (t.stamp == attempt) continue;
      t.stamp = attempt;
      if (!t.planar || t.region >= 0 || !admits(r, t)) continue;
      t.region = region_index;
      queue_[queue_end++] = next;
      addTileSums(t.sums, t.ref, &r.sums);
      r.sum_z2 += t.sum_z2;
      refit(&r);  // a few hundred tiles per frame: the 3x3 solve after each is cheap
    }
  }
  tiles_admitted_ += queue_end;
  // Half the minimum here: the tiles hold a region's interior only, the pixel refinement adds
  // its border cells (a 4400-cell box face had 3200 cells in whole tiles); the full minimum is
  // applied after the refinement.
  if (2.0 * r.sums.n < min_cells_) {
    for (int i = 0; i < queue_end; ++i) tiles_[queue_[i]].region = -1;
    return false;
  }
  PlaneRegion& region = regions_[region_index];
  region = PlaneRegion{};
  region.label = static_cast<std::uint8_t>(region_index + 1);
  region.sums = r.sums;
  region.sum_z2 = r.sum_z2;
  region.normal = r.n;
  return true;
}

int PlaneTileGrower::grow(const OrganizedCloud& cloud) {
  if (cloud.rows() != rows_ || cloud.cols() != cols_ || !cloud.p_point_in_cam_m.isContinuous()) {
    return -1;
  }
  seeds_tried_ = 0;
  tiles_admitted_ = 0;
  attempt_ = 0;
  fitTiles(cloud);
  int seed_count = 0;
  for (int i = 0; i < static_cast<int>(tiles_.size()); ++i) {
    if (tiles_[i].planar) seeds_[seed_count++] = Seed{tiles_[i].mse, i};
  }
  std::sort(seeds_.begin(), seeds_.begin() + seed_count, [](const Seed& a, const Seed& b) {
    return a.mse < b.mse || (a.mse == b.mse && a.tile < b.tile);
  });
  int regions = 0;
  for (int s = 0; s < seed_count && regions < config_.max_planes; ++s) {
    if (tiles_[seeds_[s].tile].region >= 0) continue;
    ++seeds_tried_;
    if (growRegion(seeds_[s].tile, regions)) ++regions;
  }
  regions = refineAndSum(cloud, regions);
  findAdjacency(regions);
  return regions;
}

// The regions among tile's own and its 8 neighbours', each once.
int PlaneTileGrower::candidatesOf(int tile, std::array<int, 9>* candidates) const {
  const int tr = tile / tile_cols_, tc = tile % tile_cols_;
  int count = 0;
  auto add = [&](int region) {
    if (region < 0) return;
    for (int i = 0; i < count; ++i) {
      if ((*candidates)[i] == region) return;
    }
    (*candidates)[count++] = region;
  };
  add(tiles_[tile].region);
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) {
      const int r = tr + dr, c = tc + dc;
      if (r < 0 || c < 0 || r >= tile_rows_ || c >= tile_cols_) continue;
      add(tiles_[r * tile_cols_ + c].region);
    }
  }
  return count;
}

int PlaneTileGrower::tileLabels(int i, std::array<std::uint8_t, 9>* labels) const {
  if (tiles_[i].sums.n == 0.0f) return 0;
  std::array<int, 9> candidates{};
  const int count = candidatesOf(i, &candidates);
  for (int j = 0; j < count; ++j) (*labels)[j] = regions_[candidates[j]].label;
  return count;
}

// Step 3a: each valid cell of a region's tile gets the region's label when its plane is the nearest
// of those whose point test the cell passes (the candidates of the tile: its own region and its 8
// neighbours'), else 0; returns the cells labelled. Four cells per SIMD step.
int PlaneTileGrower::labelOwnTile(const Tile& tile, const TileCandidates& t, std::uint8_t* labels) {
  const float gamma = static_cast<float>(config_.max_point_distance_m);
  const cv::v_float32x4 v_gamma = cv::v_setall_f32(gamma);
  const cv::v_float32x4 v_zero = cv::v_setzero_f32();
  const cv::v_float32x4 v_inf = cv::v_setall_f32(std::numeric_limits<float>::infinity());
  const cv::v_float32x4 v_own = cv::v_setall_f32(pixel_planes_[tile.region].label);
  int labelled = 0;
  for (int r = 0; r < tile.view.rows; ++r) {
    const cv::Vec3f* p = tile.view.points + r * tile.view.stride;
    std::uint8_t* l = labels + r * cols_;
    int c = 0;
    for (; c + 4 <= tile.view.cols; c += 4) {
      cv::v_float32x4 x, y, z;
      cv::v_load_deinterleave(&p[c][0], x, y, z);
      const cv::v_float32x4 valid = z > v_zero;
      cv::v_float32x4 best = v_inf, best_label = v_zero;
      for (int j = 0; j < t.count; ++j) {
        const PixelPlane& q = pixel_planes_[t.region[j]];
        const cv::v_float32x4 dist = cv::v_abs(cv::v_setall_f32(q.nx) * x +
                                               cv::v_setall_f32(q.ny) * y +
                                               cv::v_setall_f32(q.nz) * z - cv::v_setall_f32(q.d));
        const cv::v_float32x4 pass =
            valid & (dist <= v_gamma + cv::v_setall_f32(q.k_per_z) * z) & (dist < best);
        best = cv::v_select(pass, dist, best);
        best_label = cv::v_select(pass, cv::v_setall_f32(q.label), best_label);
      }
      alignas(16) float out[4];
      cv::v_store_aligned(out, cv::v_select(best_label == v_own, v_own, v_zero));
      for (int k = 0; k < 4; ++k) {
        l[c + k] = static_cast<std::uint8_t>(out[k]);
        labelled += out[k] != 0.0f;
      }
    }
    for (; c < tile.view.cols; ++c) {
      l[c] = OrganizedCloud::isValid(p[c]) && nearestPassing(t, p[c]) == tile.region
                 ? pixel_planes_[tile.region].label
                 : 0;
      labelled += l[c] != 0;
    }
  }
  return labelled;
}

float PlaneTileGrower::distance(const PixelPlane& q, const cv::Vec3f& p) {
  return std::abs(q.nx * p[0] + q.ny * p[1] + q.nz * p[2] - q.d);
}

bool PlaneTileGrower::passes(const PixelPlane& q, const cv::Vec3f& p, float dist) const {
  return dist <= static_cast<float>(config_.max_point_distance_m) + q.k_per_z * p[2];
}

// Step 3b: the regions grow from the labelled cells of their core tiles into the unlabelled valid
// cells around them, breadth-first and all at once, within the tiles where a region may hold cells
// (its own and their 8 neighbours): first a cell joins a region that reaches it only if that region's
// plane is the nearest it passes, then the cells still free join any region that reaches them and
// whose test they pass. Boundaries so follow the cells as in the pixel grower: each region stays
// connected and no region leaves specks inside another (taking, per cell, the nearest plane alone did
// both where two planes meet: near the intersection line the noise decides which plane is nearer).
void PlaneTileGrower::growBorders(const OrganizedCloud& cloud) {
  std::uint8_t* labels = labels_.ptr<std::uint8_t>(0);
  const cv::Vec3f* points = cloud.row(0);
  std::int32_t* queue = cell_queue_.data();
  int end = 0;
  // Seeds: labelled cells with an unlabelled 4-neighbour (the others cannot pass anything on); in a
  // whole tile only its edge cells can have one.
  const auto seed = [&](int r, int c) {
    const int cell = r * cols_ + c;
    if (labels[cell] == 0) return;
    if ((c > 0 && labels[cell - 1] == 0) || (c + 1 < cols_ && labels[cell + 1] == 0) ||
        (r > 0 && labels[cell - cols_] == 0) || (r + 1 < rows_ && labels[cell + cols_] == 0)) {
      queue[end++] = cell;
    }
  };
  for (const Tile& tile : tiles_) {
    if (tile.region < 0 || (tile.whole_label == 0 && has_whole_tile_[tile.region])) continue;
    const int offset = static_cast<int>(tile.view.points - points);
    const int r0 = offset / cols_, c0 = offset % cols_;
    const int last_r = tile.view.rows - 1, last_c = tile.view.cols - 1;
    for (int r = 0; r <= last_r; ++r) {
      const bool edge_row = r == 0 || r == last_r || tile.whole_label == 0;
      for (int c = 0; c <= last_c; c += edge_row ? 1 : std::max(1, last_c)) seed(r0 + r, c0 + c);
    }
  }
  // First every cell joins the region nearest to it (of those it passes) when that region reaches
  // it; then the cells still free join any region that reaches them and whose test they pass (their
  // nearest plane's region never got to them): both passes through the same queue.
  for (int pass = 0; pass < 2; ++pass) {
    const bool nearest_only = pass == 0;
    for (int head = 0; head < end; ++head) {
      const int cell = queue[head];
      const std::uint8_t label = labels[cell];
      const int region = label - 1;
      ScatterSums* sums = &regions_[region].sums;
      const int r = cell / cols_, c = cell - r * cols_;
      const auto visit = [&](int n, int rn, int cn) {
        if (labels[n] != 0 || !OrganizedCloud::isValid(points[n])) return;
        const TileCandidates& t = tile_candidates_[tile_row_of_[rn] * tile_cols_ + tile_col_of_[cn]];
        if (nearest_only ? nearestPassing(t, points[n]) != region : !mayHold(t, region, points[n])) return;
        labels[n] = label;
        queue[end++] = n;
        const Eigen::Vector3d& o = sums->origin;
        sums->add(points[n][0] - o.x(), points[n][1] - o.y(), points[n][2] - o.z());
      };
      if (c > 0) visit(cell - 1, r, c - 1);
      if (c + 1 < cols_) visit(cell + 1, r, c + 1);
      if (r > 0) visit(cell - cols_, r - 1, c);
      if (r + 1 < rows_) visit(cell + cols_, r + 1, c);
    }
  }
}

// True when the region is one a tile may hold and p passes its point test.
bool PlaneTileGrower::mayHold(const TileCandidates& t, int region, const cv::Vec3f& p) const {
  for (int i = 0; i < t.count; ++i) {
    if (t.region[i] == region) {
      const PixelPlane& q = pixel_planes_[region];
      return passes(q, p, distance(q, p));
    }
  }
  return false;
}

// Of the regions a tile may hold, the one whose plane is nearest to p among those whose point test p
// passes; -1 when none.
int PlaneTileGrower::nearestPassing(const TileCandidates& t, const cv::Vec3f& p) const {
  int best = -1;
  float best_dist = std::numeric_limits<float>::infinity();
  for (int i = 0; i < t.count; ++i) {
    const PixelPlane& q = pixel_planes_[t.region[i]];
    const float dist = distance(q, p);
    if (passes(q, p, dist) && dist < best_dist) {
      best_dist = dist;
      best = t.region[i];
    }
  }
  return best;
}

// The plane of each region from the cells its tiles kept (noise-corrected fit), for the border growth:
// the tiles' plane also held the cells that failed its point test.
void PlaneTileGrower::refitPixelPlanes(int regions) {
  const float k_sigma = static_cast<float>(config_.distance_sigmas);
  for (int i = 0; i < regions; ++i) {
    const ScatterSums& sums = regions_[i].sums;
    if (sums.n < 3.0) continue;
    const Eigen::Vector3d n = fitPlane(sums, noiseScatter(sums, sumDepthSquared(sums))).normal;
    const double d = n.dot(sums.mean());
    PixelPlane& q = pixel_planes_[i];
    q = PixelPlane{static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z()),
                   static_cast<float>(d), k_sigma * noise_per_z2_ * static_cast<float>(std::abs(d)),
                   q.label};
  }
}

// Step 3 for every tile, then each region's moments and normal from its cells; regions left
// below the minimum size are dropped and the labels renumbered. Returns the regions kept.
int PlaneTileGrower::refineAndSum(const OrganizedCloud& cloud, int regions) {
  std::memset(labels_.data, 0, labels_.total());
  const float k_sigma = static_cast<float>(config_.distance_sigmas);
  for (int i = 0; i < regions; ++i) {
    const PlaneRegion& region = regions_[i];
    const Eigen::Vector3f n = region.normal.cast<float>();
    const double d = region.normal.dot(region.sums.mean());
    pixel_planes_[i] = PixelPlane{n.x(), n.y(), n.z(), static_cast<float>(d),
                                  k_sigma * noise_per_z2_ * static_cast<float>(std::abs(d)),
                                  region.label};
    regions_[i].sums.reset(region.sums.origin);
    regions_[i].member_count = 0;
  }
  std::uint8_t* labels = labels_.ptr<std::uint8_t>(0);
  const cv::Vec3f* points = cloud.row(0);
  // Whole tiles (every valid cell nearest to the tile's own plane among the planes it passes) are the
  // cores the borders grow from; the cells of the other tiles are left to the growth, so that every
  // cell is connected to its region's core (a region without a whole tile keeps its partial tiles).
  std::fill(has_whole_tile_.begin(), has_whole_tile_.begin() + regions, false);
  for (int i = 0; i < static_cast<int>(tiles_.size()); ++i) {
    Tile& tile = tiles_[i];
    TileCandidates& t = tile_candidates_[i];
    t.count = candidatesOf(i, &t.region);
    tile.whole_label = 0;
    if (tile.region < 0) continue;
    const int labelled = labelOwnTile(tile, t, labels + (tile.view.points - points));
    if (static_cast<float>(labelled) == tile.sums.n) {
      addTileSums(tile.sums, tile.ref, &regions_[tile.region].sums);  // every cell joined
      tile.whole_label = pixel_planes_[tile.region].label;
      has_whole_tile_[tile.region] = true;
    }
  }
  for (Tile& tile : tiles_) {
    if (tile.region < 0 || tile.whole_label != 0) continue;
    std::uint8_t* tile_labels = labels + (tile.view.points - points);
    if (has_whole_tile_[tile.region]) {
      for (int r = 0; r < tile.view.rows; ++r) std::memset(tile_labels + r * cols_, 0, tile.view.cols);
    } else {
      const std::uint8_t label = pixel_planes_[tile.region].label;
      const TileSums part = sumTileLabel(tile.view, tile.ref, tile_labels, cols_, label);
      if (part.n > 0.0f) addTileSums(part, tile.ref, &regions_[tile.region].sums);
    }
  }
  refitPixelPlanes(regions);
  growBorders(cloud);
  // Keep the regions still large enough, renumbered 1..kept in order.
  std::array<std::uint8_t, 256> relabel{};
  std::array<int, 256> new_index{};
  int kept = 0;
  for (int i = 0; i < regions; ++i) {
    PlaneRegion& region = regions_[i];
    new_index[i] = -1;
    if (region.sums.n < min_cells_) continue;
    new_index[i] = kept;
    relabel[region.label] = static_cast<std::uint8_t>(kept + 1);
    region.member_count = static_cast<int>(region.sums.n);
    region.sum_z2 = sumDepthSquared(region.sums);
    region.normal = fitPlane(region.sums, noiseScatter(region.sums, region.sum_z2)).normal;
    region.label = static_cast<std::uint8_t>(kept + 1);
    if (kept != i) regions_[kept] = region;
    ++kept;
  }
  if (kept != regions) {
    for (std::size_t i = 0; i < labels_.total(); ++i) labels[i] = relabel[labels[i]];
    for (Tile& tile : tiles_) {
      if (tile.region >= 0) tile.region = new_index[tile.region];
      tile.whole_label = relabel[tile.whole_label];
    }
  }
  return kept;
}

// Labels whose cells touch (4-neighbourhood): one raster pass, 16 cells compared at a time and
// only the blocks with a change looked at cell by cell.
void PlaneTileGrower::findAdjacency(int regions) {
  for (int l = 0; l <= regions; ++l) adjacent_[l].reset();
  auto touch = [&](std::uint8_t a, std::uint8_t b) {
    if (a != b && a != 0 && b != 0) {
      adjacent_[a].set(b);
      adjacent_[b].set(a);
    }
  };
  for (int r = 0; r < rows_; ++r) {
    const std::uint8_t* l = labels_.ptr<std::uint8_t>(r);
    const std::uint8_t* below = r + 1 < rows_ ? labels_.ptr<std::uint8_t>(r + 1) : l;
    int c = 0;
    for (; c + 17 <= cols_; c += 16) {
      const cv::v_uint8x16 a = cv::v_load(l + c);
      const cv::v_uint8x16 differs = (a != cv::v_load(l + c + 1)) | (a != cv::v_load(below + c));
      if (!cv::v_check_any(differs)) continue;
      for (int k = c; k < c + 16; ++k) {
        touch(l[k], l[k + 1]);
        touch(l[k], below[k]);
      }
    }
    for (; c < cols_; ++c) {
      if (c + 1 < cols_) touch(l[c], l[c + 1]);
      touch(l[c], below[c]);
    }
  }
}

}  // namespace deepnav
