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

// Step 3: each valid cell of the tile gets the label of the nearest candidate plane whose point
// test it passes (0 if none); returns the cells labelled. Four cells per SIMD step.
int PlaneTileGrower::labelTile(const Tile& tile, std::uint8_t* labels, const int* candidates,
                               int count) {
  const float gamma = static_cast<float>(config_.max_point_distance_m);
  const cv::v_float32x4 v_gamma = cv::v_setall_f32(gamma);
  const cv::v_float32x4 v_zero = cv::v_setzero_f32();
  const cv::v_float32x4 v_inf = cv::v_setall_f32(std::numeric_limits<float>::infinity());
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
      for (int j = 0; j < count; ++j) {
        const PixelPlane& q = pixel_planes_[candidates[j]];
        const cv::v_float32x4 dist = cv::v_abs(cv::v_setall_f32(q.nx) * x +
                                               cv::v_setall_f32(q.ny) * y +
                                               cv::v_setall_f32(q.nz) * z - cv::v_setall_f32(q.d));
        const cv::v_float32x4 pass =
            valid & (dist <= v_gamma + cv::v_setall_f32(q.k_per_z) * z) & (dist < best);
        best = cv::v_select(pass, dist, best);
        best_label = cv::v_select(pass, cv::v_setall_f32(q.label), best_label);
      }
      alignas(16) float out[4];
      cv::v_store_aligned(out, best_label);
      for (int k = 0; k < 4; ++k) {
        l[c + k] = static_cast<std::uint8_t>(out[k]);
        labelled += out[k] != 0.0f;
      }
    }
    for (; c < tile.view.cols; ++c) {
      l[c] = 0;
      if (!OrganizedCloud::isValid(p[c])) continue;
      float best = std::numeric_limits<float>::infinity();
      for (int j = 0; j < count; ++j) {
        const PixelPlane& q = pixel_planes_[candidates[j]];
        const float dist = std::abs(q.nx * p[c][0] + q.ny * p[c][1] + q.nz * p[c][2] - q.d);
        if (dist <= gamma + q.k_per_z * p[c][2] && dist < best) {
          best = dist;
          l[c] = q.label;
        }
      }
      labelled += l[c] != 0;
    }
  }
  return labelled;
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
  std::array<int, 9> candidates{};
  for (int i = 0; i < static_cast<int>(tiles_.size()); ++i) {
    const Tile& tile = tiles_[i];
    const int count = candidatesOf(i, &candidates);
    if (count == 0) continue;
    std::uint8_t* tile_labels = labels + (tile.view.points - points);
    const int labelled = labelTile(tile, tile_labels, candidates.data(), count);
    if (labelled == 0) continue;
    if (count == 1 && static_cast<float>(labelled) == tile.sums.n) {
      addTileSums(tile.sums, tile.ref, &regions_[candidates[0]].sums);  // every cell joined
      tiles_[i].whole_label = regions_[candidates[0]].label;
      continue;
    }
    for (int j = 0; j < count; ++j) {
      const PixelPlane& q = pixel_planes_[candidates[j]];
      const TileSums s = sumTileLabel(tile.view, tile.ref, tile_labels, cols_, q.label);
      if (s.n > 0.0f) addTileSums(s, tile.ref, &regions_[candidates[j]].sums);
    }
  }
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
