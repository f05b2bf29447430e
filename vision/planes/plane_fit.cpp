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

namespace {

// Whether the cell on ray p, moved onto the region's plane (n0, d0), is within the band of a
// neighbouring plane.
bool inNeighbourBand(const cv::Vec3f& p, const Eigen::Vector3f& n0, float d0, float kd,
                     const NeighbourBand& nb) {
  const float np = n0.x() * p[0] + n0.y() * p[1] + n0.z() * p[2];
  if (std::abs(np) < 1e-6f) return false;
  const float scale = d0 / np;
  const float x = p[0] * scale, y = p[1] * scale, z = p[2] * scale;
  for (int j = 0; j < nb.count; ++j) {
    const Eigen::Vector4f& q = nb.planes[j];
    const float r = q.x() * x + q.y() * y + q.z() * z - q.w();
    const float sigma = kd * z * std::abs(q.w());
    if (std::abs(r) <= nb.band_m + nb.band_sigmas * sigma) return true;
  }
  return false;
}

}  // namespace

bool fitPlaneWithUncertainty(const OrganizedCloud& cloud, const std::int32_t* cells, int count,
                             const ScatterSums& sums, const Eigen::Vector3d& normal_unweighted,
                             const PlaneNoiseModel& noise, Plane* plane,
                             const NeighbourBand& neighbours) {
  if (count < 3 || plane == nullptr) return false;
  const Eigen::Vector3d& o = sums.origin;
  const double d0_signed = normal_unweighted.dot(sums.mean());
  const double d0 = std::abs(d0_signed);
  const Eigen::Vector3f n0f = normal_unweighted.cast<float>();
  const float kd = static_cast<float>(noise.disparity_noise_per_fb);
  const double k = noise.disparity_noise_per_fb * d0;  // residual sigma = k Z
  const double floor2 = noise.floor_m * noise.floor_m;
  const int cols = cloud.cols();
  // Weighted moments relative to the region origin (cancellation, see ScatterSums), and the
  // moments of the expected noise: point i scatters along its ray, A_i = (k_d Z_i)^2 p_i p_i^T with
  // k_d = sigma_d / (f B), weighted by w_i: sum w A = sum a_i p_i p_i^T, a_i = w_i (k_d Z_i)^2.
  const double kd2 = noise.disparity_noise_per_fb * noise.disparity_noise_per_fb;
  double W = 0.0, A = 0.0;
  Eigen::Vector3d sq = Eigen::Vector3d::Zero(), aq = Eigen::Vector3d::Zero();
  Eigen::Matrix3d sqq = Eigen::Matrix3d::Zero(), aqq = Eigen::Matrix3d::Zero();
  int fitted = 0;
  for (int i = 0; i < count; ++i) {
    const cv::Vec3f& p = cloud.row(cells[i] / cols)[cells[i] % cols];
    if (neighbours.count > 0 &&
        inNeighbourBand(p, n0f, static_cast<float>(d0_signed), kd, neighbours)) {
      continue;
    }
    ++fitted;
    const double kz = k * p[2];
    const double w = 1.0 / (kz * kz + floor2);
    const double a = w * kd2 * p[2] * p[2];
    const Eigen::Vector3d q(p[0] - o.x(), p[1] - o.y(), p[2] - o.z());
    W += w;
    sq += w * q;
    sqq.selfadjointView<Eigen::Upper>().rankUpdate(q, w);
    A += a;
    aq += a * q;
    aqq.selfadjointView<Eigen::Upper>().rankUpdate(q, a);
  }
  if (fitted < 3) return false;
  sqq = sqq.selfadjointView<Eigen::Upper>();
  aqq = aqq.selfadjointView<Eigen::Upper>();
  const Eigen::Vector3d mq = sq / W;
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
  const Eigen::Matrix4d C = B * info.ldlt().solve(B.transpose());

  plane->n_in_cam = n;
  plane->d_m = d;
  plane->p_centroid_in_cam_m = centroid;
  plane->point_count = count;
  plane->fit_point_count = fitted;
  // rms along the final normal from the unweighted scatter: n^T S_u n / N
  plane->rms_m = std::sqrt(std::max(0.0, n.dot(sums.scatter() * n)) / sums.n);
  plane->hessian = H;
  plane->covariance = C;
  plane->log_pdet_hessian = log_pdet;
  return true;
}

}  // namespace deepnav
