#include "vision/planes/plane_region_grower.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <opencv2/core/hal/intrin.hpp>

namespace deepnav {

bool PlaneRegionGrower::init(const PlaneExtractionConfig& config, double fx_px,
                             double focal_baseline_pxm, int rows, int cols, int step_px) {
  if (rows <= 0 || cols <= 0 || step_px <= 0 || focal_baseline_pxm <= 0.0 || fx_px <= 0.0 ||
      config.normal_span_m <= 0.0 || !(config.max_normal_angle_deg > 0.0) ||
      config.max_planes < 1 || config.max_planes > 250 || config.seed_window_cells < 3 ||
      config.seed_window_cells % 2 == 0 || config.seed_spacing_px < 1 ||
      config.refit_growth <= 1.0 || config.max_point_distance_m <= 0.0 ||
      config.max_mse_m2 <= 0.0 || config.min_area_px < 1) {
    return false;
  }
  config_ = config;
  noise_per_z2_ = static_cast<float>(config.disparity_noise_px / focal_baseline_pxm);
  normal_span_cells_m_ = static_cast<float>(config.normal_span_m * fx_px / step_px);
  const double cos_normal = std::cos(std::min(90.0, config.max_normal_angle_deg) * M_PI / 180.0);
  cos2_normal_ = static_cast<float>(cos_normal * cos_normal);
  rows_ = rows;
  cols_ = cols;
  const int step2 = step_px * step_px;
  min_cells_ = std::max(config.seed_window_cells * config.seed_window_cells,
                        (config.min_area_px + step2 - 1) / step2);
  seed_step_cells_ = std::max(1, config.seed_spacing_px / step_px);
  half_window_ = config.seed_window_cells / 2;
  labels_.create(rows, cols, CV_8UC1);
  stamp_.assign(static_cast<size_t>(rows) * cols, std::uint8_t{0});
  attempt_ = 0;
  members_.assign(static_cast<size_t>(rows) * cols, 0);
  seeds_.assign(static_cast<size_t>(rows / seed_step_cells_ + 1) * (cols / seed_step_cells_ + 1),
                Seed{});
  regions_.assign(config.max_planes, PlaneRegion{});
  return true;
}

// Stamps are bytes (a third of the memory traffic of ints); after 255 attempts they wrap and
// are cleared once.
std::uint8_t PlaneRegionGrower::nextAttempt() {
  if (++attempt_ == 0) {
    std::fill(stamp_.begin(), stamp_.end(), std::uint8_t{0});
    attempt_ = 1;
  }
  return attempt_;
}

// A seed patch: k x k valid cells around the centre, fitted by least squares. Its MSE ranks the
// seeds (flattest first), so regions start inside planes rather than on edges.
int PlaneRegionGrower::collectSeeds(const OrganizedCloud& cloud) {
  int count = 0;
  const int h = half_window_;
  for (int r = h + seed_step_cells_ / 2; r < rows_ - h; r += seed_step_cells_) {
    for (int c = h + seed_step_cells_ / 2; c < cols_ - h; c += seed_step_cells_) {
      ScatterSums sums;
      const cv::Vec3f& centre = cloud.row(r)[c];
      if (!OrganizedCloud::isValid(centre)) continue;
      sums.reset(Eigen::Vector3d(centre[0], centre[1], centre[2]));
      bool complete = true;
      for (int dr = -h; dr <= h && complete; ++dr) {
        const cv::Vec3f* p = cloud.row(r + dr);
        for (int dc = -h; dc <= h; ++dc) {
          const cv::Vec3f& q = p[c + dc];
          if (!OrganizedCloud::isValid(q)) {
            complete = false;
            break;
          }
          sums.add(q[0] - sums.origin.x(), q[1] - sums.origin.y(), q[2] - sums.origin.z());
        }
      }
      if (!complete) continue;
      const PlaneFitResult fit = fitPlane(sums);
      const float sigma_z = noise_per_z2_ * centre[2] * centre[2];
      if (fit.mse > config_.max_mse_m2 + sigma_z * sigma_z) continue;
      seeds_[count++] = Seed{static_cast<float>(fit.mse), r * cols_ + c};
    }
  }
  std::sort(seeds_.begin(), seeds_.begin() + count, [](const Seed& a, const Seed& b) {
    return a.mse < b.mse || (a.mse == b.mse && a.cell < b.cell);
  });
  return count;
}

bool PlaneRegionGrower::patchIsFree(const OrganizedCloud& /*cloud*/, int cell) const {
  const int r = cell / cols_;
  const int c = cell % cols_;
  for (int dr = -half_window_; dr <= half_window_; ++dr) {
    const std::uint8_t* l = labels_.ptr<std::uint8_t>(r + dr);
    for (int dc = -half_window_; dc <= half_window_; ++dc) {
      if (l[c + dc] != 0) return false;
    }
  }
  return true;
}

int PlaneRegionGrower::grow(const OrganizedCloud& cloud) {
  if (cloud.rows() != rows_ || cloud.cols() != cols_ || !cloud.p_point_in_cam_m.isContinuous()) {
    return -1;
  }
  // memset rather than Mat::setTo, which allocates (labels_ is continuous: created in init()).
  std::memset(labels_.data, 0, labels_.total());
  member_end_ = 0;
  region_count_ = 0;
  seeds_tried_ = 0;
  cells_admitted_ = 0;
  for (auto& adjacent : adjacent_) adjacent.reset();
  const int seed_count = collectSeeds(cloud);
  for (int s = 0; s < seed_count && region_count_ < config_.max_planes; ++s) {
    if (!patchIsFree(cloud, seeds_[s].cell)) continue;
    ++seeds_tried_;
    PlaneRegion& region = regions_[region_count_];
    const auto label = static_cast<std::uint8_t>(region_count_ + 1);
    if (growRegion(cloud, seeds_[s].cell, label, &region)) {
      ++region_count_;
    } else {
      releaseRegion(region);
    }
  }
  return region_count_;
}

// Expected scatter of the stereo noise along the rays, sum (k_d Z_i)^2 p_i p_i^T, approximated by
// k_d^2 mean(Z^2) sum p p^T (see plane_fit.h for the exact one).
Eigen::Matrix3d PlaneRegionGrower::noiseScatter(const ScatterSums& sums, double sum_z2) const {
  const double kd2 = static_cast<double>(noise_per_z2_) * noise_per_z2_;
  return kd2 * (sum_z2 / sums.n) * sums.secondMoment();
}

void PlaneRegionGrower::releaseRegion(const PlaneRegion& region) {
  std::uint8_t* labels = labels_.ptr<std::uint8_t>(0);
  for (int i = region.member_begin; i < region.member_begin + region.member_count; ++i) {
    labels[members_[i]] = 0;
  }
  member_end_ = region.member_begin;
}

// The hot loop keeps every running sum and every setting in locals: the label and stamp grids are
// bytes, and a byte store may alias any object whose address is known, so sums in *region or
// settings read through `this` would be reloaded and stored back around every cell.
bool PlaneRegionGrower::growRegion(const OrganizedCloud& cloud, int seed_cell, std::uint8_t label,
                                   PlaneRegion* region) {
  const std::uint8_t attempt = nextAttempt();
  std::uint8_t* stamp = stamp_.data();
  std::int32_t* members = members_.data();
  int member_end = member_end_;
  const int member_begin = member_end_;
  std::uint8_t* labels = labels_.ptr<std::uint8_t>(0);  // continuous: created by init()
  const cv::Vec3f* points = cloud.row(0);               // continuous: checked by grow()
  const int rows = rows_;
  const int cols = cols_;
  const int last_cell = rows * cols - 1;
  const float noise_per_z2 = noise_per_z2_;
  const float span_cells_m = normal_span_cells_m_;
  const float cos2_normal = cos2_normal_;
  const double refit_growth = config_.refit_growth;
  const cv::Vec3f& seed = points[seed_cell];
  const Eigen::Vector3d origin(seed[0], seed[1], seed[2]);
  const cv::v_float64x2 origin_xy(origin.x(), origin.y());
  // ScatterSums::add in SIMD pairs (each lane the scalar product and sum, so bit for bit the
  // same): (sx, sy), (sxx, sxy), (sxz, syy), (syz, szz); n and sz are scalars.
  double count = 0.0, sz = 0.0;
  cv::v_float64x2 s_x_y = cv::v_setzero_f64(), s_xx_xy = cv::v_setzero_f64();
  cv::v_float64x2 s_xz_yy = cv::v_setzero_f64(), s_yz_zz = cv::v_setzero_f64();
  double sum_var = 0.0;  // sum of the members' noise variances
  double sum_z2 = 0.0;   // sum of Z^2 of the members
  std::bitset<256> touched;  // labels met at the border, committed when the region is kept
  // x_y = (x, y) and z: the cell's point relative to the origin.
  auto admit = [&](int cell, const cv::v_float64x2& x_y, double z, float p_z, float sigma)
      __attribute__((always_inline)) {
    labels[cell] = label;
    stamp[cell] = attempt;
    members[member_end++] = cell;
    count += 1.0;
    s_x_y = s_x_y + x_y;
    sz += z;
    const cv::v_float64x2 z_z = cv::v_setall_f64(z);
    s_xx_xy = s_xx_xy + cv::v_combine_low(x_y, x_y) * x_y;
    s_xz_yy = s_xz_yy + x_y * cv::v_combine_high(z_z, x_y);
    s_yz_zz = s_yz_zz + cv::v_combine_high(x_y, z_z) * z_z;
    sum_var += static_cast<double>(sigma) * sigma;
    sum_z2 += static_cast<double>(p_z) * p_z;
  };
  auto relative = [&](const cv::Vec3f& p) __attribute__((always_inline)) {
    return cv::v_float64x2(static_cast<double>(p[0]), static_cast<double>(p[1])) - origin_xy;
  };
  auto snapshot = [&]() {
    alignas(16) double t[8];
    cv::v_store_aligned(t, s_x_y);
    cv::v_store_aligned(t + 2, s_xx_xy);
    cv::v_store_aligned(t + 4, s_xz_yy);
    cv::v_store_aligned(t + 6, s_yz_zz);
    ScatterSums sums;
    sums.reset(origin);
    sums.n = count;
    sums.sx = t[0];
    sums.sy = t[1];
    sums.sz = sz;
    sums.sxx = t[2];
    sums.sxy = t[3];
    sums.sxz = t[4];
    sums.syy = t[5];
    sums.syz = t[6];
    sums.szz = t[7];
    return sums;
  };
  // The seed's own noise, before a plane is known: along the ray, sigma_Z = Z^2 sigma_d / (f B).
  for (int dr = -half_window_; dr <= half_window_; ++dr) {
    for (int dc = -half_window_; dc <= half_window_; ++dc) {
      const int cell = seed_cell + dr * cols + dc;
      const cv::Vec3f& p = points[cell];
      admit(cell, relative(p), p[2] - origin.z(), p[2], noise_per_z2 * p[2] * p[2]);
    }
  }

  // Running sums along the current normal n: a = n . (p - origin). The fit removes the expected
  // scatter of the stereo noise along the rays (noiseScatter): without it the normal of a patch
  // tilts away from the viewing direction, and the distance test, centred on that biased plane,
  // keeps a biased sample.
  Eigen::Vector3d n;
  double sum_a = 0.0, sum_aa = 0.0, mean_a = 0.0;
  float abs_d = 0.0f;  // |d| of the current plane, for the noise along the normal
  float nx = 0.0f, ny = 0.0f, nz = 0.0f;
  cv::v_float64x2 n_xy = cv::v_setzero_f64();
  auto refit = [&]() {
    const ScatterSums sums = snapshot();
    n = fitPlane(sums, noiseScatter(sums, sum_z2)).normal;
    n_xy = cv::v_float64x2(n.x(), n.y());
    nx = static_cast<float>(n.x());
    ny = static_cast<float>(n.y());
    nz = static_cast<float>(n.z());
    abs_d = static_cast<float>(std::abs(n.dot(sums.mean())));
    sum_a = n.x() * sums.sx + n.y() * sums.sy + n.z() * sums.sz;
    sum_aa = n.x() * n.x() * sums.sxx + n.y() * n.y() * sums.syy + n.z() * n.z() * sums.szz +
             2.0 * (n.x() * n.y() * sums.sxy + n.x() * n.z() * sums.sxz + n.y() * n.z() * sums.syz);
    mean_a = sum_a / sums.n;
  };
  refit();
  double next_refit = count * refit_growth;
  const double gamma = config_.max_point_distance_m;
  const double k_sigma = config_.distance_sigmas;
  const double max_mse = config_.max_mse_m2;

  // Local normal of the cell at (r, c) against the region's normal; true when it agrees or cannot
  // be computed. Tested on one colour of a checkerboard only: a leak along an intersection line
  // cannot pass two 4-neighbours in a row unchecked, and the test costs half.
  auto localNormalAgrees = [&](int cell, int r, int c, const cv::Vec3f& p)
      __attribute__((always_inline)) {
    if (((r + c) & 1) != 0) return true;
    const int k = std::clamp(static_cast<int>(span_cells_m / p[2] + 0.5f), 1, 8);
    if (r < k || c < k || r + k >= rows || c + k >= cols) return true;
    const cv::Vec3f& left = points[cell - k];
    const cv::Vec3f& right = points[cell + k];
    const cv::Vec3f& up = points[cell - k * cols];
    const cv::Vec3f& down = points[cell + k * cols];
    if (!OrganizedCloud::isValid(left) || !OrganizedCloud::isValid(right) ||
        !OrganizedCloud::isValid(up) || !OrganizedCloud::isValid(down)) {
      return true;
    }
    const cv::Vec3f local = (right - left).cross(down - up);
    const float dot = nx * local[0] + ny * local[1] + nz * local[2];
    return dot * dot >= cos2_normal * local.dot(local);
  };

  // Inlined into the queue loop (four call sites): a call per candidate is measurable here.
  auto consider = [&](int cell, int r, int c) __attribute__((always_inline)) {
    if (stamp[cell] == attempt) return;
    const std::uint8_t other = labels[cell];
    if (other != 0) {
      touched.set(other);
      return;
    }
    stamp[cell] = attempt;
    const cv::Vec3f& p = points[cell];
    if (!OrganizedCloud::isValid(p)) return;
    // a = n . (p - origin), summed as (nx x + ny y) + nz z like the scalar expression
    const cv::v_float64x2 x_y = relative(p);
    const double z = p[2] - origin.z();
    const double a = cv::v_reduce_sum(n_xy * x_y) + n.z() * z;
    // Depth noise seen along the normal: sigma_Z |d| / Z (see PlaneNoiseModel).
    const float sigma = noise_per_z2 * p[2] * abs_d;
    // (1) distance to the plane through the current centroid
    if (std::abs(a - mean_a) > gamma + k_sigma * sigma) return;
    // (1b) the surface around the cell faces the same way
    if (!localNormalAgrees(cell, r, c, p)) return;
    // (2) MSE of the region with the candidate, beyond the mean noise variance:
    // (s2 - s1^2 / n1) / n1 > max_mse + var / n1, multiplied out by n1^2
    const double n1 = count + 1.0;
    const double s1 = sum_a + a;
    const double s2 = sum_aa + a * a;
    const double var = sum_var + static_cast<double>(sigma) * sigma;
    if (s2 * n1 - s1 * s1 > (max_mse * n1 + var) * n1) return;
    admit(cell, x_y, z, p[2], sigma);
    sum_a = s1;
    sum_aa = s2;
    mean_a = s1 / n1;
    if (count >= next_refit) {
      refit();
      next_refit = count * refit_growth;
    }
  };

  // Row of a cell by multiplication: an integer division per cell costs more than the tests.
  const double inv_cols = 1.0 / cols;
  constexpr int kPrefetchAhead = 8;
  for (int head = member_begin; head < member_end; ++head) {
    const int cell = members[head];
    // The local normal test reads rows +-k around the candidates: fetch them for a cell a few
    // places ahead in the queue, so the loads do not stall (they miss L1 at full resolution).
    if (head + kPrefetchAhead < member_end) {
      const int ahead = members[head + kPrefetchAhead];
      const int k = std::clamp(static_cast<int>(span_cells_m / points[ahead][2] + 0.5f), 1, 8);
      __builtin_prefetch(&points[std::max(0, ahead - (k + 1) * cols)]);
      __builtin_prefetch(&points[std::min(last_cell, ahead + (k + 1) * cols)]);
      __builtin_prefetch(&points[std::max(0, ahead - k * cols)]);
      __builtin_prefetch(&points[std::min(last_cell, ahead + k * cols)]);
    }
    const int r = static_cast<int>((cell + 0.5) * inv_cols);
    const int c = cell - r * cols;
    if (c > 0) consider(cell - 1, r, c - 1);
    if (c + 1 < cols) consider(cell + 1, r, c + 1);
    if (r > 0) consider(cell - cols, r - 1, c);
    if (r + 1 < rows) consider(cell + cols, r + 1, c);
  }
  member_end_ = member_end;
  region->member_begin = member_begin;
  region->member_count = member_end - member_begin;
  region->label = label;
  region->sums = snapshot();
  cells_admitted_ += region->member_count;
  if (region->member_count < min_cells_) return false;
  refit();
  region->normal = n;
  region->sum_z2 = sum_z2;
  touched.reset(label);
  adjacent_[label] = touched;
  for (int l = 1; l < 256; ++l) {
    if (touched.test(l)) adjacent_[l].set(label);
  }
  return true;
}

}  // namespace deepnav
