#include "vision/planes/plane_fit.h"

#include <Eigen/Eigenvalues>
#include <cmath>

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
  }
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
