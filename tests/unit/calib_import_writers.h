// Test support: a StereoCalibration written in each format `deepnav import calibration` reads, from the
// formats' documentation (Kalibr wiki "yaml formats", OpenCV's stereo_calib output, ROS camera_info YAML of
// camera_calibration_parsers), for the round trip tests. Numbers printed with 17 significant digits.
#pragma once
#include <cstdio>
#include <fstream>
#include <string>

#include <opencv2/calib3d.hpp>
#include <opencv2/core/persistence.hpp>

#include "vision/calib/stereo_calibration.h"

namespace deepnav::test {

inline std::string numberList(const double* v, int n) {
  std::string text = "[";
  char value[40];
  for (int i = 0; i < n; ++i) {
    std::snprintf(value, sizeof value, "%s%.17g", i ? ", " : "", v[i]);
    text += value;
  }
  return text + "]";
}

// radtan: Kalibr keeps k1 k2 p1 p2 only (k3 must be 0).
inline void writeKalibrCamchain(const StereoCalibration& c, const std::string& path) {
  std::ofstream out(path);
  for (int i = 0; i < 2; ++i) {
    const CameraCalibration& cam = i == 0 ? c.left : c.right;
    const double intrinsics[4] = {cam.K(0, 0), cam.K(1, 1), cam.K(0, 2), cam.K(1, 2)};
    out << "cam" << i << ":\n";
    if (i == 1) {
      out << "  T_cn_cnm1:\n";
      for (int r = 0; r < 3; ++r) {
        const double row[4] = {c.R(r, 0), c.R(r, 1), c.R(r, 2), c.T[r]};
        out << "  - " << numberList(row, 4) << "\n";
      }
      out << "  - [0.0, 0.0, 0.0, 1.0]\n";
    }
    out << "  cam_overlaps: [" << 1 - i << "]\n  camera_model: pinhole\n";
    out << "  distortion_coeffs: " << numberList(cam.dist.ptr<double>(), 4) << "\n";
    out << "  distortion_model: radtan\n";
    out << "  intrinsics: " << numberList(intrinsics, 4) << "\n";
    out << "  resolution: [" << c.image_size.width << ", " << c.image_size.height << "]\n";
    out << "  rostopic: /cam" << i << "/image_raw\n";
  }
}

// As stereo_calib writes them: intrinsics M1 D1 M2 D2, extrinsics R T (and R1 R2 P1 P2 Q, ignored).
inline void writeOpenCvStereo(const StereoCalibration& c, const std::string& intrinsics_path,
                              const std::string& extrinsics_path) {
  cv::FileStorage in(intrinsics_path, cv::FileStorage::WRITE);
  in << "M1" << cv::Mat(c.left.K) << "D1" << c.left.dist << "M2" << cv::Mat(c.right.K) << "D2" << c.right.dist;
  in.release();
  cv::Mat R1, R2, P1, P2, Q;
  cv::stereoRectify(c.left.K, c.left.dist, c.right.K, c.right.dist, c.image_size, c.R, c.T, R1, R2, P1, P2, Q,
                    cv::CALIB_ZERO_DISPARITY, -1, c.image_size);
  cv::FileStorage ex(extrinsics_path, cv::FileStorage::WRITE);
  ex << "R" << cv::Mat(c.R) << "T" << cv::Mat(c.T) << "R1" << R1 << "R2" << R2 << "P1" << P1 << "P2" << P2 << "Q" << Q;
}

inline void writeCameraInfoMatrix(std::ofstream& out, const char* key, const double* v, int rows, int cols) {
  out << key << ":\n  rows: " << rows << "\n  cols: " << cols << "\n  data: " << numberList(v, rows * cols) << "\n";
}

// The pair the ROS stereo calibrator writes: K, D, the rectifying rotations and projections.
inline void writeCameraInfoPair(const StereoCalibration& c, const std::string& left_path,
                                const std::string& right_path) {
  cv::Mat R1, R2, P1, P2, Q;
  cv::stereoRectify(c.left.K, c.left.dist, c.right.K, c.right.dist, c.image_size, c.R, c.T, R1, R2, P1, P2, Q,
                    cv::CALIB_ZERO_DISPARITY, 0.0, c.image_size);
  for (int i = 0; i < 2; ++i) {
    const CameraCalibration& cam = i == 0 ? c.left : c.right;
    std::ofstream out(i == 0 ? left_path : right_path);
    out << "image_width: " << c.image_size.width << "\nimage_height: " << c.image_size.height << "\n";
    out << "camera_name: stereo/" << (i == 0 ? "left" : "right") << "\n";
    writeCameraInfoMatrix(out, "camera_matrix", cam.K.val, 3, 3);
    const int n = static_cast<int>(cam.dist.total());
    out << "distortion_model: " << (n <= 5 ? "plumb_bob" : "rational_polynomial") << "\n";
    writeCameraInfoMatrix(out, "distortion_coefficients", cam.dist.ptr<double>(), 1, n);
    writeCameraInfoMatrix(out, "rectification_matrix", (i == 0 ? R1 : R2).ptr<double>(), 3, 3);
    writeCameraInfoMatrix(out, "projection_matrix", (i == 0 ? P1 : P2).ptr<double>(), 3, 4);
  }
}

}  // namespace deepnav::test
