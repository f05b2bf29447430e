#include "vision/planes/plane_region_grower.h"

#include <algorithm>
#include <cmath>

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
  stamp_.assign(static_cast<size_t>(rows) * cols, 0u);
  attempt_ = 0;
  members_.assign(static_cast<size_t>(rows) * cols, 0);
  seeds_.assign(static_cast<size_t>(rows / seed_step_cells_ + 1) * (cols / seed_step_cells_ + 1),
                Seed{});
  regions_.assign(config.max_planes, PlaneRegion{});
  label_count_.assign(256, 0);
  return true;
}

std::uint32_t PlaneRegionGrower::nextAttempt() {
  if (++attempt_ == 0) {  // wrapped after 2^32 attempts: forget every stamp once
    std::fill(stamp_.begin(), stamp_.end(), 0u);
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
  if (cloud.rows() != rows_ || cloud.cols() != cols_) return -1;
  labels_.setTo(cv::Scalar(0));
  member_end_ = 0;
  region_count_ = 0;
  seeds_tried_ = 0;
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
  collectRegions(cloud);
  return region_count_;
}

// Expected scatter of the stereo noise along the rays, sum (k_d Z_i)^2 p_i p_i^T, approximated by
// k_d^2 mean(Z^2) sum p p^T (see plane_fit.h for the exact one).
Eigen::Matrix3d PlaneRegionGrower::noiseScatter(const ScatterSums& sums, double sum_z2) const {
  const double kd2 = static_cast<double>(noise_per_z2_) * noise_per_z2_;
  return kd2 * (sum_z2 / sums.n) * sums.secondMoment();
}

// Cells, moments and boxes of every region from the label grid (a counting sort by label).
void PlaneRegionGrower::collectRegions(const OrganizedCloud& cloud) {
  std::fill(label_count_.begin(), label_count_.end(), 0);
  const std::uint8_t* labels = labels_.ptr<std::uint8_t>(0);
  const int n_cells = rows_ * cols_;
  for (int cell = 0; cell < n_cells; ++cell) ++label_count_[labels[cell]];
  int begin = 0;
  for (int i = 0; i < region_count_; ++i) {
    PlaneRegion& region = regions_[i];
    region.member_begin = begin;
    region.member_count = 0;
    begin += label_count_[region.label];
    region.sums.reset(region.sums.origin);
    region.sum_z2 = 0.0;
    region.bbox_cells = cv::Rect(cols_, rows_, 0, 0);
    label_count_[region.label] = i;  // now: region index of the label
  }
  for (int i = 0; i < region_count_; ++i) adjacent_[regions_[i].label].reset();
  int r_min[256], r_max[256], c_min[256], c_max[256];
  for (int i = 0; i < region_count_; ++i) {
    r_min[i] = rows_;
    r_max[i] = -1;
    c_min[i] = cols_;
    c_max[i] = -1;
  }
  for (int r = 0; r < rows_; ++r) {
    const cv::Vec3f* p = cloud.row(r);
    for (int c = 0; c < cols_; ++c) {
      const std::uint8_t l = labels[r * cols_ + c];
      if (l == 0) continue;
      const std::uint8_t right = c + 1 < cols_ ? labels[r * cols_ + c + 1] : 0;
      const std::uint8_t down = r + 1 < rows_ ? labels[(r + 1) * cols_ + c] : 0;
      if (right != 0 && right != l) {
        adjacent_[l].set(right);
        adjacent_[right].set(l);
      }
      if (down != 0 && down != l) {
        adjacent_[l].set(down);
        adjacent_[down].set(l);
      }
      const int i = label_count_[l];
      PlaneRegion& region = regions_[i];
      members_[region.member_begin + region.member_count++] = r * cols_ + c;
      const Eigen::Vector3d& o = region.sums.origin;
      region.sums.add(p[c][0] - o.x(), p[c][1] - o.y(), p[c][2] - o.z());
      region.sum_z2 += static_cast<double>(p[c][2]) * p[c][2];
      r_min[i] = std::min(r_min[i], r);
      r_max[i] = std::max(r_max[i], r);
      c_min[i] = std::min(c_min[i], c);
      c_max[i] = std::max(c_max[i], c);
    }
  }
  member_end_ = begin;
  for (int i = 0; i < region_count_; ++i) {
    PlaneRegion& region = regions_[i];
    region.bbox_cells =
        cv::Rect(c_min[i], r_min[i], c_max[i] - c_min[i] + 1, r_max[i] - r_min[i] + 1);
    region.normal = fitPlane(region.sums, noiseScatter(region.sums, region.sum_z2)).normal;
  }
}

void PlaneRegionGrower::releaseRegion(const PlaneRegion& region) {
  std::uint8_t* labels = labels_.ptr<std::uint8_t>(0);
  for (int i = region.member_begin; i < region.member_begin + region.member_count; ++i) {
    labels[members_[i]] = 0;
  }
  member_end_ = region.member_begin;
}

bool PlaneRegionGrower::growRegion(const OrganizedCloud& cloud, int seed_cell, std::uint8_t label,
                                   PlaneRegion* region) {
  const std::uint32_t attempt = nextAttempt();
  std::uint8_t* labels = labels_.ptr<std::uint8_t>(0);  // continuous: created by init()
  const cv::Vec3f* points = cloud.row(0);
  const bool continuous = cloud.p_point_in_cam_m.isContinuous();
  auto point = [&](int cell) -> const cv::Vec3f& {
    return continuous ? points[cell] : cloud.row(cell / cols_)[cell % cols_];
  };
  const cv::Vec3f& seed = point(seed_cell);
  const Eigen::Vector3d origin(seed[0], seed[1], seed[2]);
  ScatterSums& sums = region->sums;
  sums.reset(origin);
  region->member_begin = member_end_;
  region->label = label;
  double sum_var = 0.0;  // sum of the members' noise variances
  double sum_z2 = 0.0;   // sum of Z^2 of the members
  auto admit = [&](int cell, const cv::Vec3f& p, float sigma) {
    labels[cell] = label;
    stamp_[cell] = attempt;
    members_[member_end_++] = cell;
    sums.add(p[0] - origin.x(), p[1] - origin.y(), p[2] - origin.z());
    sum_var += static_cast<double>(sigma) * sigma;
    sum_z2 += static_cast<double>(p[2]) * p[2];
  };
  // The seed's own noise, before a plane is known: along the ray, sigma_Z = Z^2 sigma_d / (f B).
  for (int dr = -half_window_; dr <= half_window_; ++dr) {
    for (int dc = -half_window_; dc <= half_window_; ++dc) {
      const int cell = seed_cell + dr * cols_ + dc;
      const cv::Vec3f& p = point(cell);
      admit(cell, p, noise_per_z2_ * p[2] * p[2]);
    }
  }

  // Running sums along the current normal n: a = n . (p - origin).
  // The fit removes the expected scatter of the stereo noise along the rays (see plane_fit.h),
  // sum (k_d Z_i)^2 p_i p_i^T, approximated by k_d^2 mean(Z^2) sum p p^T: without it the normal
  // of a patch tilts away from the viewing direction and the distance test, centred on that biased
  // plane, keeps a biased sample.
  Eigen::Vector3d n = fitPlane(sums, noiseScatter(sums, sum_z2)).normal;
  double sum_a = 0.0, sum_aa = 0.0;
  float abs_d = 0.0f;  // |d| of the current plane, for the noise along the normal
  auto refit = [&]() {
    n = fitPlane(sums, noiseScatter(sums, sum_z2)).normal;
    abs_d = static_cast<float>(std::abs(n.dot(sums.mean())));
    sum_a = n.x() * sums.sx + n.y() * sums.sy + n.z() * sums.sz;
    sum_aa = n.x() * n.x() * sums.sxx + n.y() * n.y() * sums.syy + n.z() * n.z() * sums.szz +
             2.0 * (n.x() * n.y() * sums.sxy + n.x() * n.z() * sums.sxz + n.y() * n.z() * sums.syz);
  };
  refit();
  double next_refit = sums.n * config_.refit_growth;
  const double gamma = config_.max_point_distance_m;
  const double k_sigma = config_.distance_sigmas;
  const double max_mse = config_.max_mse_m2;

  // Local normal of the cell at (r, c) against the region's normal; true when it agrees or
  // cannot be computed.
  auto localNormalAgrees = [&](int cell, int r, int c, const cv::Vec3f& p) {
    const int k = std::clamp(static_cast<int>(normal_span_cells_m_ / p[2] + 0.5f), 1, 8);
    if (r < k || c < k || r + k >= rows_ || c + k >= cols_) return true;
    const cv::Vec3f& left = point(cell - k);
    const cv::Vec3f& right = point(cell + k);
    const cv::Vec3f& up = point(cell - k * cols_);
    const cv::Vec3f& down = point(cell + k * cols_);
    if (!OrganizedCloud::isValid(left) || !OrganizedCloud::isValid(right) ||
        !OrganizedCloud::isValid(up) || !OrganizedCloud::isValid(down)) {
      return true;
    }
    const cv::Vec3f local = (right - left).cross(down - up);
    const float dot = static_cast<float>(n.x()) * local[0] + static_cast<float>(n.y()) * local[1] +
                      static_cast<float>(n.z()) * local[2];
    return dot * dot >= cos2_normal_ * local.dot(local);
  };

  auto consider = [&](int cell, int r, int c) {
    if (stamp_[cell] == attempt || labels[cell] != 0) return;
    stamp_[cell] = attempt;
    const cv::Vec3f& p = point(cell);
    if (!OrganizedCloud::isValid(p)) return;
    const double a =
        n.x() * (p[0] - origin.x()) + n.y() * (p[1] - origin.y()) + n.z() * (p[2] - origin.z());
    // Depth noise seen along the normal: sigma_Z |d| / Z (see PlaneNoiseModel).
    const float sigma = noise_per_z2_ * p[2] * abs_d;
    // (1) distance to the plane through the current centroid
    if (std::abs(a - sum_a / sums.n) > gamma + k_sigma * sigma) return;
    // (1b) the surface around the cell faces the same way
    if (!localNormalAgrees(cell, r, c, p)) return;
    // (2) MSE of the region with the candidate, beyond the mean noise variance
    const double n1 = sums.n + 1.0;
    const double s1 = sum_a + a;
    const double s2 = sum_aa + a * a;
    const double var_noise = (sum_var + static_cast<double>(sigma) * sigma) / n1;
    if ((s2 - s1 * s1 / n1) / n1 > max_mse + var_noise) return;
    admit(cell, p, sigma);
    sum_a = s1;
    sum_aa = s2;
    if (sums.n >= next_refit) {
      refit();
      next_refit = sums.n * config_.refit_growth;
    }
  };

  for (int head = region->member_begin; head < member_end_; ++head) {
    const int cell = members_[head];
    const int r = cell / cols_;
    const int c = cell - r * cols_;
    if (c > 0) consider(cell - 1, r, c - 1);
    if (c + 1 < cols_) consider(cell + 1, r, c + 1);
    if (r > 0) consider(cell - cols_, r - 1, c);
    if (r + 1 < rows_) consider(cell + cols_, r + 1, c);
  }
  region->member_count = member_end_ - region->member_begin;
  if (region->member_count < min_cells_) return false;
  refit();
  region->normal = n;
  region->sum_z2 = sum_z2;
  return true;
}

}  // namespace deepnav
