#include "vision/markers/square_marker_pose.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/calib3d.hpp>
#include <vector>

namespace deepnav {
namespace {

// Above this RMS corner error the pose is solved again in a rotated virtual camera (see below), px.
constexpr double kRetryErrorPx = 1.0;

struct Candidate {
  Eigen::Quaterniond q_cam_marker = Eigen::Quaterniond::Identity();
  Eigen::Vector3d p_marker_in_cam_m = Eigen::Vector3d::Zero();
  double error_px = std::numeric_limits<double>::infinity();
};

// Rodrigues vector and translation of OpenCV as (q, p); false when not finite.
bool toCandidate(const cv::Mat& rvec, const cv::Mat& tvec, Candidate* c) {
  const Eigen::Vector3d r(rvec.at<double>(0), rvec.at<double>(1), rvec.at<double>(2));
  const Eigen::Vector3d t(tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2));
  if (!r.allFinite() || !t.allFinite()) return false;
  const double angle = r.norm();
  c->q_cam_marker = angle > 0.0 ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, r / angle))
                                : Eigen::Quaterniond::Identity();
  c->p_marker_in_cam_m = t;
  return true;
}

// Both IPPE solutions for the corners seen by a virtual camera V = R_virtual_cam * C (same centre),
// mapped back to C, best first, each with its reprojection error in the real image. Returns how
// many are valid (finite, in front of the camera); with one, c[1] = c[0].
int solveIppeSquare(const std::array<Eigen::Vector2d, 4>& corners_px, double marker_size_m,
                    const PinholeIntrinsics& camera, const Eigen::Matrix3d& R_virtual_cam,
                    std::array<Candidate, 2>* c) {
  // Stack buffers wrapped by cv::Mat headers: the inputs cost no allocation. Image points are given
  // as normalised coordinates of V, with an identity camera matrix.
  double object[4][3];
  double image[4][2];
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d o = squareMarkerCorner(k, marker_size_m);
    object[k][0] = o.x();
    object[k][1] = o.y();
    object[k][2] = o.z();
    const Eigen::Vector3d ray_cam((corners_px[k].x() - camera.cx_px) / camera.fx_px,
                                  (corners_px[k].y() - camera.cy_px) / camera.fy_px, 1.0);
    const Eigen::Vector3d ray_virtual = R_virtual_cam * ray_cam;
    if (!(ray_virtual.z() > 0.0)) return 0;
    image[k][0] = ray_virtual.x() / ray_virtual.z();
    image[k][1] = ray_virtual.y() / ray_virtual.z();
  }
  const cv::Mat object_points(4, 1, CV_64FC3, object);
  const cv::Mat image_points(4, 1, CV_64FC2, image);
  std::vector<cv::Mat> rvecs;
  std::vector<cv::Mat> tvecs;
  int solutions = 0;
  try {
    solutions = cv::solvePnPGeneric(object_points, image_points, cv::Matx33d::eye(), cv::noArray(),
                                    rvecs, tvecs, false, cv::SOLVEPNP_IPPE_SQUARE);
  } catch (const cv::Exception&) {
    return 0;  // degenerate corners (e.g. collinear): OpenCV asserts
  }
  // Our own reprojection error (RMS corner distance in the real image), not OpenCV's.
  int valid = 0;
  for (int i = 0; i < std::min(solutions, 2); ++i) {
    Candidate cand;
    if (!toCandidate(rvecs[i], tvecs[i], &cand)) continue;
    cand.q_cam_marker =
        Eigen::Quaterniond(R_virtual_cam.transpose()) * cand.q_cam_marker;  // T_cam_V T_V_marker
    cand.p_marker_in_cam_m = R_virtual_cam.transpose() * cand.p_marker_in_cam_m;
    cand.error_px = markerReprojectionErrorPx(corners_px, marker_size_m, camera, cand.q_cam_marker,
                                              cand.p_marker_in_cam_m);
    if (!std::isfinite(cand.error_px)) continue;
    (*c)[valid++] = cand;
  }
  if (valid == 2 && (*c)[1].error_px < (*c)[0].error_px) std::swap((*c)[0], (*c)[1]);
  if (valid == 1) (*c)[1] = (*c)[0];
  return valid;
}

}  // namespace

Eigen::Vector3d squareMarkerCorner(int k, double marker_size_m) {
  const double h = 0.5 * marker_size_m;
  static constexpr double kSx[4] = {-1.0, 1.0, 1.0, -1.0};
  static constexpr double kSy[4] = {1.0, 1.0, -1.0, -1.0};
  return {kSx[k] * h, kSy[k] * h, 0.0};
}

double markerReprojectionErrorPx(const std::array<Eigen::Vector2d, 4>& corners_px,
                                 double marker_size_m, const PinholeIntrinsics& camera,
                                 const Eigen::Quaterniond& q_cam_marker,
                                 const Eigen::Vector3d& p_marker_in_cam_m) {
  const Eigen::Matrix3d R = q_cam_marker.toRotationMatrix();
  double sum_sq = 0.0;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d x = R * squareMarkerCorner(k, marker_size_m) + p_marker_in_cam_m;
    if (!(x.z() > 0.0)) return std::numeric_limits<double>::infinity();
    const Eigen::Vector2d uv(camera.fx_px * x.x() / x.z() + camera.cx_px,
                             camera.fy_px * x.y() / x.z() + camera.cy_px);
    sum_sq += (uv - corners_px[k]).squaredNorm();
  }
  return std::sqrt(sum_sq / 4.0);
}

double markerObliquenessRad(const Eigen::Quaterniond& q_cam_marker,
                            const Eigen::Vector3d& p_marker_in_cam_m) {
  const Eigen::Vector3d normal_in_cam = q_cam_marker * Eigen::Vector3d::UnitZ();
  const double d = p_marker_in_cam_m.norm();
  if (!(d > 0.0)) return 0.0;
  // The ray marker -> camera is -p / |p|.
  const double c = std::clamp(-normal_in_cam.dot(p_marker_in_cam_m) / d, -1.0, 1.0);
  return std::acos(c);
}

bool estimateSquareMarkerPose(const std::array<Eigen::Vector2d, 4>& corners_px,
                              double marker_size_m, const PinholeIntrinsics& camera,
                              const MarkerAmbiguityConfig& ambiguity, MarkerObservation* out) {
  std::array<Candidate, 2> c;
  int valid = solveIppeSquare(corners_px, marker_size_m, camera, Eigen::Matrix3d::Identity(), &c);
  if (valid < 2 || c[0].error_px > kRetryErrorPx) {
    // OpenCV's IPPE turns its rotation matrix into a rotation vector through acos and 1 / sin,
    // which fails at a rotation of exactly pi -- and a marker facing the camera upright is a
    // rotation of pi about x_C. Solve again in a virtual camera turned by a small fixed rotation
    // (the same rays, so the same problem) that moves the pose away from pi, and keep the better
    // answer.
    const Eigen::Matrix3d R_virtual_cam =
        Eigen::AngleAxisd(0.1, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
    std::array<Candidate, 2> retry;
    const int valid_retry =
        solveIppeSquare(corners_px, marker_size_m, camera, R_virtual_cam, &retry);
    if (valid_retry > 0 && (valid == 0 || retry[0].error_px < c[0].error_px)) {
      c = retry;
      valid = valid_retry;
    }
  }
  if (valid == 0) return false;

  out->q_cam_marker = c[0].q_cam_marker;
  out->p_marker_in_cam_m = c[0].p_marker_in_cam_m;
  out->q_cam_marker_alt = c[1].q_cam_marker;
  out->p_marker_in_cam_alt_m = c[1].p_marker_in_cam_m;
  out->reprojection_error_px = c[0].error_px;
  out->reprojection_error_alt_px = c[1].error_px;
  const double s2 = ambiguity.corner_sigma_px * ambiguity.corner_sigma_px;
  const double ssr_gap = 4.0 * (c[1].error_px * c[1].error_px - c[0].error_px * c[0].error_px);
  out->ambiguous = valid == 2 && ssr_gap < ambiguity.ambiguity_chi2 * s2;
  out->distance_m = c[0].p_marker_in_cam_m.norm();
  out->obliqueness_rad = markerObliquenessRad(c[0].q_cam_marker, c[0].p_marker_in_cam_m);
  return true;
}

}  // namespace deepnav
