#include "tests/support/synthetic_marker_image.h"

#include <algorithm>
#include <cmath>
#include <opencv2/aruco.hpp>

#include "vision/markers/aruco_dictionary.h"
#include "vision/markers/square_marker_pose.h"

namespace deepnav {
namespace {

// Grey level at the marker-plane point (x, y) of M, or -1 outside the plate (background).
int plateLevel(const cv::Mat& cells, const SyntheticMarker& m, double x, double y) {
  const double half = 0.5 * m.marker_size_m;
  const double half_plate = half + m.quiet_zone_m;
  if (std::abs(x) > half_plate || std::abs(y) > half_plate) return -1;
  if (std::abs(x) >= half || std::abs(y) >= half) return m.white;
  // Cells: column from x (left to right), row from y (top = +y, image row 0).
  const int n = cells.cols;
  const int col = std::clamp(static_cast<int>((x + half) / m.marker_size_m * n), 0, n - 1);
  const int row = std::clamp(static_cast<int>((half - y) / m.marker_size_m * n), 0, n - 1);
  return cells.at<std::uint8_t>(row, col) > 127 ? m.white : m.black;
}

}  // namespace

Eigen::Vector2d projectMarkerCorner(const SyntheticMarker& marker, const PinholeIntrinsics& camera,
                                    int k) {
  const Eigen::Vector3d x =
      marker.q_cam_marker * squareMarkerCorner(k, marker.marker_size_m) + marker.p_marker_in_cam_m;
  return {camera.fx_px * x.x() / x.z() + camera.cx_px, camera.fy_px * x.y() / x.z() + camera.cy_px};
}

bool drawSyntheticMarker(const std::string& dictionary, const SyntheticMarker& marker,
                         const PinholeIntrinsics& camera, int supersample, cv::Mat* image) {
  int dictionary_id = 0;
  if (!arucoDictionaryFromName(dictionary, &dictionary_id)) return false;
  if (marker.id < 0 || marker.id >= arucoDictionarySize(dictionary_id)) return false;
  if (image->type() != CV_8UC1 || supersample < 1 || supersample > 16) return false;
  const cv::Ptr<cv::aruco::Dictionary> dict = cv::aruco::getPredefinedDictionary(dictionary_id);
  cv::Mat cells;  // one pixel per cell, black border included
  cv::aruco::drawMarker(dict, marker.id, dict->markerSize + 2, cells, 1);

  const Eigen::Matrix3d R = marker.q_cam_marker.toRotationMatrix();
  const Eigen::Vector3d n = R.col(2);
  const Eigen::Vector3d& p = marker.p_marker_in_cam_m;
  if (n.dot(-p) <= 0.0) return true;  // seen from behind: nothing visible

  // Bounding box of the plate's projection (all of the plate in front of the camera).
  const double half_plate = 0.5 * marker.marker_size_m + marker.quiet_zone_m;
  double u_min = image->cols, u_max = -1.0, v_min = image->rows, v_max = -1.0;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d c = R * (squareMarkerCorner(k, 2.0 * half_plate)) + p;
    if (!(c.z() > 1e-6)) return true;  // plate crosses the image plane: not drawn (tests avoid it)
    const double u = camera.fx_px * c.x() / c.z() + camera.cx_px;
    const double v = camera.fy_px * c.y() / c.z() + camera.cy_px;
    u_min = std::min(u_min, u);
    u_max = std::max(u_max, u);
    v_min = std::min(v_min, v);
    v_max = std::max(v_max, v);
  }
  const int c0 = std::max(0, static_cast<int>(std::floor(u_min)));
  const int c1 = std::min(image->cols - 1, static_cast<int>(std::ceil(u_max)));
  const int r0 = std::max(0, static_cast<int>(std::floor(v_min)));
  const int r1 = std::min(image->rows - 1, static_cast<int>(std::ceil(v_max)));

  const double n_dot_p = n.dot(p);
  const double step = 1.0 / supersample;
  for (int r = r0; r <= r1; ++r) {
    auto* row = image->ptr<std::uint8_t>(r);
    for (int c = c0; c <= c1; ++c) {
      double sum = 0.0;
      for (int a = 0; a < supersample; ++a) {
        const double v = r - 0.5 + (a + 0.5) * step;
        for (int b = 0; b < supersample; ++b) {
          const double u = c - 0.5 + (b + 0.5) * step;
          // Ray d through the sample, plane n.(X - p) = 0: X = t d with t = n.p / n.d.
          const Eigen::Vector3d d((u - camera.cx_px) / camera.fx_px,
                                  (v - camera.cy_px) / camera.fy_px, 1.0);
          const double n_dot_d = n.dot(d);
          int level = -1;
          if (std::abs(n_dot_d) > 1e-12) {
            const double t = n_dot_p / n_dot_d;
            if (t > 0.0) {
              const Eigen::Vector3d x_m = R.transpose() * (t * d - p);
              level = plateLevel(cells, marker, x_m.x(), x_m.y());
            }
          }
          sum += level >= 0 ? level : row[c];
        }
      }
      row[c] = cv::saturate_cast<std::uint8_t>(sum / (supersample * supersample));
    }
  }
  return true;
}

void addGaussianNoise(double sigma, cv::RNG* rng, cv::Mat* image) {
  cv::Mat noise(image->size(), CV_16SC1);
  rng->fill(noise, cv::RNG::NORMAL, 0.0, sigma);
  cv::Mat noisy;
  image->convertTo(noisy, CV_16SC1);
  noisy += noise;
  noisy.convertTo(*image, CV_8UC1);
}

}  // namespace deepnav
