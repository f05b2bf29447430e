#include "vision/planes/plane_fit.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <opencv2/core/hal/intrin.hpp>

#include "vision/planes/moment_lanes.h"

namespace deepnav {
namespace {

// H of Pathak et al. for weighted moments: S = sum w p p^T, s = sum w p, W = sum w.
Eigen::Matrix4d planeHessian(const Eigen::Matrix3d& S, const Eigen::Vector3d& s, double W,
                             double lambda) {
  Eigen::Matrix4d H;
  H.topLeftCorner<3, 3>() = S - lambda * Eigen::Matrix3d::Identity();
  H.topRightCorner<3, 1>() = -s;
  H.bottomLeftCorner<1, 3>() = -s.transpose();
  H(3, 3) = W;
  return H;
}

}  // namespace

void PlaneFitAccumulator::reset(const ScatterSums& sums, const Eigen::Vector3d& normal_unweighted,
                                const PlaneNoiseModel& noise, const NeighbourBand& neighbours) {
  origin_ = sums.origin;
  n0_ = normal_unweighted.cast<float>();
  const double d0 = normal_unweighted.dot(sums.mean());
  d0_ = static_cast<float>(d0);
  kd_ = static_cast<float>(noise.disparity_noise_per_fb);
  k_ = noise.disparity_noise_per_fb * std::abs(d0);
  kd2_ = noise.disparity_noise_per_fb * noise.disparity_noise_per_fb;
  floor2_ = noise.floor_m * noise.floor_m;
  independent_points_ = noise.independent_points;
  kf_ = static_cast<float>(k_);
  floor2f_ = static_cast<float>(floor2_);
  neighbour_count_ = std::min(neighbours.count, kMaxNeighbours);
  band_m_ = neighbours.band_m;
  for (int j = 0; j < neighbour_count_; ++j) {
    const Eigen::Vector4f& q = neighbours.planes[j];
    d0_n_[j] = d0_ * q.head<3>();
    d_[j] = q.w();
    sigma_coeff_[j] = neighbours.band_sigmas * kd_ * std::abs(q.w()) * std::abs(d0_);
    const float values[5] = {d0_n_[j].x(), d0_n_[j].y(), d0_n_[j].z(), d_[j], sigma_coeff_[j]};
    for (int v = 0; v < 5; ++v) neighbour_lanes_[j][v].fill(values[v]);
  }
  const float values[6] = {kf_, floor2f_, n0_.x(), n0_.y(), n0_.z(), band_m_};
  for (int v = 0; v < 6; ++v) lanes_[v].fill(values[v]);
  sw_ = WeightedMoments{};
  sa_ = WeightedMoments{};
  fitted_ = 0;
}

// Whether the cell on ray p, moved onto the region's plane (n0, d0) -- p_hat = p d0 / (n0.p) --
// is within band_m + band_sigmas sigma_j(z_hat) of a neighbouring plane j. Multiplied by |n0.p|
// the test needs no division: |d0 (n_j.p) - d_j (n0.p)| <= band_m |n0.p| + band_sigmas kd |d_j|
// |d0| p_z.
bool PlaneFitAccumulator::inNeighbourBand(const cv::Vec3f& p) const {
  const float np = n0_.x() * p[0] + n0_.y() * p[1] + n0_.z() * p[2];
  const float abs_np = std::abs(np);
  for (int j = 0; j < neighbour_count_; ++j) {
    const Eigen::Vector3f& m = d0_n_[j];
    const float lhs = std::abs(m.x() * p[0] + m.y() * p[1] + m.z() * p[2] - d_[j] * np);
    if (lhs <= band_m_ * abs_np + sigma_coeff_[j] * p[2]) return true;
  }
  return false;
}

// inNeighbourBand and the weight of addRun for four cells in SIMD lanes (OpenCV universal
// intrinsics: SSE2 on x86-64, NEON on aarch64). Each lane does the scalar code's float
// operations in the same order (products, then sums left to right, no fused multiply-add), so
// the masks and weights are bit for bit those of the scalar path.
unsigned PlaneFitAccumulator::bandMask4(const cv::Vec3f* p, float* w) const {
  auto lane = [](const std::array<float, 4>& a) { return cv::v_load(a.data()); };
  cv::v_float32x4 x, y, z;
  cv::v_load_deinterleave(&p[0][0], x, y, z);
  const cv::v_float32x4 kz = lane(lanes_[0]) * z;
  cv::v_store(w, cv::v_setall_f32(1.0f) / (kz * kz + lane(lanes_[1])));
  if (neighbour_count_ == 0) return 0u;
  const cv::v_float32x4 np = lane(lanes_[2]) * x + lane(lanes_[3]) * y + lane(lanes_[4]) * z;
  const cv::v_float32x4 band = lane(lanes_[5]) * cv::v_abs(np);
  cv::v_float32x4 in_band = cv::v_setzero_f32();
  for (int j = 0; j < neighbour_count_; ++j) {
    const auto& m = neighbour_lanes_[j];
    const cv::v_float32x4 lhs =
        cv::v_abs(lane(m[0]) * x + lane(m[1]) * y + lane(m[2]) * z - lane(m[3]) * np);
    in_band = in_band | (lhs <= band + lane(m[4]) * z);
  }
  return static_cast<unsigned>(cv::v_signmask(in_band));
}

// |d0 (n_j.p) - d_j (n0.p)| = |m.p| with m = d0 n_j - d_j n0 is linear in p: over the box its
// smallest value is |m.c| - |m|.h (c the centre, h the half sizes, |m| taken per component),
// and the right-hand side band_m |n0.p| + s_j p_z is at most band_m (|n0.c| + |n0|.h) + s_j z_hi.
int PlaneFitAccumulator::neighboursNear(const cv::Vec3f& lo, const cv::Vec3f& hi,
                                        int* active) const {
  const Eigen::Vector3f l(lo[0], lo[1], lo[2]), h(hi[0], hi[1], hi[2]);
  const Eigen::Vector3f c = 0.5f * (l + h), half = 0.5f * (h - l);
  const float np_max = std::abs(n0_.dot(c)) + n0_.cwiseAbs().dot(half);
  int count = 0;
  for (int j = 0; j < neighbour_count_; ++j) {
    const Eigen::Vector3f m = d0_n_[j] - d_[j] * n0_;
    const float lhs_min = std::abs(m.dot(c)) - m.cwiseAbs().dot(half);
    const float rhs_max = band_m_ * np_max + sigma_coeff_[j] * hi[2];
    if (!(lhs_min > 1.01f * rhs_max + 1e-6f)) active[count++] = j;  // margin for rounding
  }
  return count;
}

cv::v_float32x4 PlaneFitAccumulator::bandLanes(const cv::v_float32x4& x, const cv::v_float32x4& y,
                                               const cv::v_float32x4& z, const int* active,
                                               int count) const {
  auto lane = [](const std::array<float, 4>& a) { return cv::v_load(a.data()); };
  cv::v_float32x4 in_band = cv::v_setzero_f32();
  if (count == 0) return in_band;
  const cv::v_float32x4 np = lane(lanes_[2]) * x + lane(lanes_[3]) * y + lane(lanes_[4]) * z;
  const cv::v_float32x4 band = lane(lanes_[5]) * cv::v_abs(np);
  for (int i = 0; i < count; ++i) {
    const auto& m = neighbour_lanes_[active[i]];
    const cv::v_float32x4 lhs =
        cv::v_abs(lane(m[0]) * x + lane(m[1]) * y + lane(m[2]) * z - lane(m[3]) * np);
    in_band = in_band | (lhs <= band + lane(m[4]) * z);
  }
  return in_band;
}

namespace {

// weight * (moments of q + delta), in double, from a tile's moments of q.
WeightedMoments weightedShifted(const TileSums& t, double weight, const Eigen::Vector3d& delta) {
  const double N = t.n, sx = t.sx, sy = t.sy, sz = t.sz;
  const double dx = delta.x(), dy = delta.y(), dz = delta.z();
  WeightedMoments m;
  m.w = weight * N;
  m.x = weight * (sx + N * dx);
  m.y = weight * (sy + N * dy);
  m.z = weight * (sz + N * dz);
  m.xx = weight * (t.sxx + 2.0 * dx * sx + N * dx * dx);
  m.xy = weight * (t.sxy + dx * sy + dy * sx + N * dx * dy);
  m.xz = weight * (t.sxz + dx * sz + dz * sx + N * dx * dz);
  m.yy = weight * (t.syy + 2.0 * dy * sy + N * dy * dy);
  m.yz = weight * (t.syz + dy * sz + dz * sy + N * dy * dz);
  m.zz = weight * (t.szz + 2.0 * dz * sz + N * dz * dz);
  return m;
}

#if CV_SIMD128_64F
// WeightedMoments in five SIMD pairs, (w, x) (y, z) (xx, xy) (xz, yy) (yz, zz): every lane gets
// the scalar add()'s product and sum (w * 1 == w exactly), so the sums are bit for bit the same.
struct PairMoments {
  cv::v_float64x2 wx = cv::v_setzero_f64(), yz = cv::v_setzero_f64();
  cv::v_float64x2 xx_xy = cv::v_setzero_f64(), xz_yy = cv::v_setzero_f64();
  cv::v_float64x2 yz_zz = cv::v_setzero_f64();
  // one_x = (1, x), y_z = (y, z), x_y = (x, y), z_y = (z, y), z_z = (z, z)
  void add(const cv::v_float64x2& one_x, const cv::v_float64x2& y_z, const cv::v_float64x2& x_y,
           const cv::v_float64x2& z_y, const cv::v_float64x2& z_z, double weight) {
    const cv::v_float64x2 w = cv::v_setall_f64(weight);
    wx = wx + w * one_x;
    const cv::v_float64x2 wy_wz = w * y_z;
    yz = yz + wy_wz;
    const cv::v_float64x2 wx_wy = w * x_y;
    xx_xy = xx_xy + cv::v_combine_low(wx_wy, wx_wy) * x_y;
    xz_yy = xz_yy + wx_wy * z_y;
    yz_zz = yz_zz + wy_wz * z_z;
  }
  void mergeInto(WeightedMoments* m) const {
    alignas(16) double t[10];
    cv::v_store_aligned(t, wx);
    cv::v_store_aligned(t + 2, yz);
    cv::v_store_aligned(t + 4, xx_xy);
    cv::v_store_aligned(t + 6, xz_yy);
    cv::v_store_aligned(t + 8, yz_zz);
    const WeightedMoments o{t[0], t[1], t[2], t[3], t[4], t[5], t[6], t[7], t[8], t[9]};
    m->merge(o);
  }
};
#endif

}  // namespace

void PlaneFitAccumulator::addRun(const cv::Vec3f* p, int count) {
  int fitted = 0;
  int i = 0;
  alignas(16) float w4[4];
#if CV_SIMD128_64F
  PairMoments sw, sa;
  const cv::v_float64x2 one = cv::v_setall_f64(1.0);
  const cv::v_float64x2 origin_xy(origin_.x(), origin_.y());
  auto addCellPairs = [&](const cv::Vec3f& q, double w) {
    const cv::v_float64x2 x_y =
        cv::v_float64x2(static_cast<double>(q[0]), static_cast<double>(q[1])) - origin_xy;
    const double z = q[2] - origin_.z();
    const cv::v_float64x2 z_z = cv::v_setall_f64(z);
    const cv::v_float64x2 one_x = cv::v_combine_low(one, x_y);
    const cv::v_float64x2 y_z = cv::v_combine_high(x_y, z_z);
    const cv::v_float64x2 z_y = cv::v_combine_high(z_z, x_y);
    sw.add(one_x, y_z, x_y, z_y, z_z, w);
    sa.add(one_x, y_z, x_y, z_y, z_z, w * kd2_ * q[2] * q[2]);
  };
#else
  WeightedMoments sw, sa;
  auto addCellPairs = [&](const cv::Vec3f& q, double w) { addCell(q, w, &sw, &sa); };
#endif
  for (; i + 4 <= count; i += 4) {
    const unsigned in_band = bandMask4(p + i, w4);
    for (int k = 0; k < 4; ++k) {
      if ((in_band >> k) & 1u) continue;
      ++fitted;
      addCellPairs(p[i + k], w4[k]);
    }
  }
  for (; i < count; ++i) {
    if (neighbour_count_ > 0 && inNeighbourBand(p[i])) continue;
    ++fitted;
    const float kz = kf_ * p[i][2];
    addCellPairs(p[i], 1.0f / (kz * kz + floor2f_));  // weights need no double division
  }
#if CV_SIMD128_64F
  sw.mergeInto(&sw_);
  sa.mergeInto(&sa_);
#else
  sw_.merge(sw);
  sa_.merge(sa);
#endif
  fitted_ += fitted;
}

cv::Rect PlaneFitAccumulator::addTile(const TileView& tile, const cv::Vec3f& ref,
                                      const cv::Vec3f& lo, const cv::Vec3f& hi,
                                      const std::uint8_t* labels, int label_stride,
                                      std::uint8_t label) {
  std::array<int, kMaxNeighbours> active{};
  const int active_count = neighboursNear(lo, hi, active.data());
  MomentLanes lanes;
  const cv::v_uint32x4 wanted = cv::v_setall_u32(label);
  const cv::v_float32x4 rx = cv::v_setall_f32(ref[0]), ry = cv::v_setall_f32(ref[1]),
                        rz = cv::v_setall_f32(ref[2]);
  int r0 = tile.rows, r1 = -1, c0 = tile.cols, c1 = -1;
  for (int r = 0; r < tile.rows; ++r) {
    const cv::Vec3f* p = tile.points + static_cast<std::ptrdiff_t>(r) * tile.stride;
    const std::uint8_t* l = labels + r * label_stride;
    for (int c = 0; c < tile.cols; c += 4) {
      cv::v_float32x4 x, y, z, mine;
      if (c + 4 <= tile.cols) {
        cv::v_load_deinterleave(&p[c][0], x, y, z);
        mine = cv::v_reinterpret_as_f32(cv::v_load_expand_q(l + c) == wanted);
      } else {  // the last columns of a partial tile: the missing lanes are not mine
        alignas(16) float px[4] = {}, py[4] = {}, pz[4] = {};
        alignas(16) unsigned ok[4] = {};
        for (int k = 0; c + k < tile.cols; ++k) {
          px[k] = p[c + k][0];
          py[k] = p[c + k][1];
          pz[k] = p[c + k][2];
          ok[k] = l[c + k] == label ? ~0u : 0u;
        }
        x = cv::v_load_aligned(px);
        y = cv::v_load_aligned(py);
        z = cv::v_load_aligned(pz);
        mine = cv::v_reinterpret_as_f32(cv::v_load_aligned(ok));
      }
      const unsigned bits = static_cast<unsigned>(cv::v_signmask(mine));
      if (bits == 0u) continue;
      r0 = std::min(r0, r);
      r1 = r;
      c0 = std::min(c0, c + __builtin_ctz(bits));
      c1 = std::max(c1, c + 31 - __builtin_clz(bits));
      lanes.add(mine & ~bandLanes(x, y, z, active.data(), active_count), x - rx, y - ry, z - rz);
    }
  }
  if (r1 < 0) return cv::Rect();
  addTileMoments(lanes.reduce(), ref);
  return cv::Rect(c0, r0, c1 - c0 + 1, r1 - r0 + 1);
}

// One weight per tile, at the mean Z^2 of its fitted cells (Z varies by a few per cent over a
// tile): w = 1 / (k^2 Z^2 + floor^2), and a = w kd^2 Z^2 for the noise scatter.
void PlaneFitAccumulator::addTileMoments(const TileSums& t, const cv::Vec3f& ref) {
  if (t.n <= 0.0f) return;
  const double rz = ref[2];
  const double z2 = rz * rz + (2.0 * rz * t.sz + t.szz) / t.n;
  const double w = 1.0 / (k_ * k_ * z2 + floor2_);
  const Eigen::Vector3d delta = Eigen::Vector3d(ref[0], ref[1], ref[2]) - origin_;
  sw_.merge(weightedShifted(t, w, delta));
  sa_.merge(weightedShifted(t, w * kd2_ * z2, delta));
  fitted_ += static_cast<int>(t.n);
}

bool PlaneFitAccumulator::addWholeTile(const TileSums& sums, const cv::Vec3f& ref,
                                       const cv::Vec3f& lo, const cv::Vec3f& hi) {
  std::array<int, kMaxNeighbours> active{};
  if (neighboursNear(lo, hi, active.data()) > 0) return false;
  addTileMoments(sums, ref);
  return true;
}

bool PlaneFitAccumulator::solve(const ScatterSums& sums, int point_count, Plane* plane) const {
  if (fitted_ < 3 || plane == nullptr) return false;
  const Eigen::Vector3d& o = origin_;
  const double W = sw_.w;
  const double A = sa_.w;
  const Eigen::Vector3d aq = sa_.first();
  const Eigen::Matrix3d sqq = sw_.second();
  const Eigen::Matrix3d aqq = sa_.second();
  const Eigen::Vector3d mq = sw_.first() / W;
  const Eigen::Vector3d centroid = o + mq;
  // sum a p p^T from the origin-relative sums (p = o + q)
  const Eigen::Matrix3d noise_abs =
      aqq + aq * o.transpose() + o * aq.transpose() + A * o * o.transpose();
  // Total least squares is biased by noise that is not isotropic (here: along the rays, mostly
  // along z): E[M] = M_true + sum w A. The corrected scatter removes it (first order, as in
  // Kanatani's / Chojnacki's renormalisation), so the smallest eigenvector is unbiased.
  const Eigen::Matrix3d M = sqq - W * mq * mq.transpose() - noise_abs;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(M);
  Eigen::Vector3d n = eig.eigenvectors().col(0);
  const double lambda = eig.eigenvalues()(0);
  if (n.dot(centroid) > 0.0) n = -n;  // towards the camera
  const double d = n.dot(centroid);

  // Absolute weighted moments: sum w p p^T = M + W c c^T, sum w p = W c.
  const Eigen::Matrix3d S = M + W * centroid * centroid.transpose();
  const Eigen::Matrix4d H = planeHessian(S, W * centroid, W, lambda);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eig_h(H, Eigen::EigenvaluesOnly);
  double log_pdet = 0.0;
  for (int i = 1; i < 4; ++i) log_pdet += std::log(std::max(eig_h.eigenvalues()(i), 1e-300));

  // Covariance on the tangent space of |n| = 1.
  Eigen::Matrix<double, 4, 3> B = Eigen::Matrix<double, 4, 3>::Zero();
  B.block<3, 1>(0, 0) = eig.eigenvectors().col(1);
  B.block<3, 1>(0, 1) = eig.eigenvectors().col(2);
  B(3, 2) = 1.0;
  const Eigen::Matrix3d info = B.transpose() * H * B;
  Eigen::Matrix4d C = B * info.ldlt().solve(B.transpose());
  if (independent_points_ > 0.0 && fitted_ > independent_points_) C *= fitted_ / independent_points_;

  plane->n_in_cam = n;
  plane->d_m = d;
  plane->p_centroid_in_cam_m = centroid;
  plane->point_count = point_count;
  plane->fit_point_count = fitted_;
  // rms along the final normal from the unweighted scatter: n^T S_u n / N
  plane->rms_m = std::sqrt(std::max(0.0, n.dot(sums.scatter() * n)) / sums.n);
  plane->hessian = H;
  plane->covariance = C;
  plane->log_pdet_hessian = log_pdet;
  return true;
}

bool fitPlaneWithUncertainty(const OrganizedCloud& cloud, const std::int32_t* cells, int count,
                             const ScatterSums& sums, const Eigen::Vector3d& normal_unweighted,
                             const PlaneNoiseModel& noise, Plane* plane,
                             const NeighbourBand& neighbours) {
  PlaneFitAccumulator fit;
  fit.reset(sums, normal_unweighted, noise, neighbours);
  const int cols = cloud.cols();
  for (int i = 0; i < count; ++i) fit.add(cloud.row(cells[i] / cols)[cells[i] % cols]);
  return fit.solve(sums, count, plane);
}

}  // namespace deepnav
