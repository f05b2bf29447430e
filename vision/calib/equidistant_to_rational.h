#pragma once
#include <string>

#include <opencv2/core.hpp>

namespace deepnav {

// The equidistant (Kannala-Brandt, cv::fisheye, Kalibr "equidistant") lens model rewritten as OpenCV's
// rational model, which deepnav's rectification (cv::stereoRectify + initUndistortRectifyMap) uses.
// Both are radial: a normalised undistorted point at radius r lands at radius r g(r), with
//   equidistant: g(r) = theta_d / r, theta = atan r, theta_d = theta (1 + k1 theta^2 + ... + k4 theta^8)
//   rational:    g(r) = (1 + c1 r^2 + c2 r^4 + c3 r^6) / (1 + c4 r^2 + c5 r^4 + c6 r^6)
// c1..c6 are fitted over the radii the image holds (0 to the corners' radius) by linearised least squares,
// iterated with the previous denominator (Sanathanan-Koerner), weighted by r so the residual is in pixels.
struct EquidistantFit {
  cv::Mat dist;                // 1 x 8 OpenCV order: k1 k2 p1 p2 k3 k4 k5 k6 (p1 = p2 = 0)
  double max_error_px = 0.0;   // largest |difference| of the two models on the image, in pixels (fx)
  double max_angle_deg = 0.0;  // widest ray angle from the axis within the image
};

// False with a reason when the image corners reach 89 deg from the axis or beyond (no pinhole rectification
// holds them), or the fitted model is not monotonic over the image. fit->max_error_px is for the caller to judge.
bool equidistantToRational(const cv::Matx33d& K, const cv::Vec4d& k, cv::Size image_size, EquidistantFit* fit,
                           std::string* error);

}  // namespace deepnav
