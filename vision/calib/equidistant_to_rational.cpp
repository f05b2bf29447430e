#include "vision/calib/equidistant_to_rational.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace deepnav {
namespace {

constexpr double kPi = 3.14159265358979323846;

double thetaDistorted(const cv::Vec4d& k, double theta) {
  const double t2 = theta * theta;
  return theta * (1.0 + t2 * (k[0] + t2 * (k[1] + t2 * (k[2] + t2 * k[3]))));
}

// theta with thetaDistorted(theta) = theta_d (Newton from theta_d; the model is monotonic on the image).
double undistortAngle(const cv::Vec4d& k, double theta_d) {
  double theta = theta_d;
  for (int i = 0; i < 50; ++i) {
    const double h = 1e-7;
    const double slope = (thetaDistorted(k, theta + h) - thetaDistorted(k, theta - h)) / (2.0 * h);
    if (!(slope > 0.0)) return -1.0;
    const double step = (thetaDistorted(k, theta) - theta_d) / slope;
    theta -= step;
    if (std::abs(step) < 1e-14) break;
  }
  return theta;
}

double equidistantGain(const cv::Vec4d& k, double r) { return r < 1e-12 ? 1.0 : thetaDistorted(k, std::atan(r)) / r; }

double rationalGain(const double c[6], double r) {
  const double r2 = r * r;
  return (1.0 + r2 * (c[0] + r2 * (c[1] + r2 * c[2]))) / (1.0 + r2 * (c[3] + r2 * (c[4] + r2 * c[5])));
}

}  // namespace

bool equidistantToRational(const cv::Matx33d& K, const cv::Vec4d& k, cv::Size size, EquidistantFit* fit,
                           std::string* error) {
  // Widest ray: the image corners (the radial model grows monotonically with the distance to the centre).
  double widest_theta = 0.0;
  for (const cv::Point2d px : {cv::Point2d(0, 0), cv::Point2d(size.width, 0), cv::Point2d(0, size.height),
                               cv::Point2d(size.width, size.height)}) {
    const double xd = (px.x - K(0, 2)) / K(0, 0), yd = (px.y - K(1, 2)) / K(1, 1);
    const double theta = undistortAngle(k, std::hypot(xd, yd));
    if (theta < 0.0) {
      if (error) *error = "the equidistant model is not monotonic within the image";
      return false;
    }
    widest_theta = std::max(widest_theta, theta);
  }
  fit->max_angle_deg = widest_theta * 180.0 / kPi;
  if (widest_theta >= 89.0 * kPi / 180.0) {
    if (error) {
      char text[160];
      std::snprintf(
          text, sizeof text,
          "the image corners lie %.1f deg from the axis; a pinhole rectification holds rays under 89 deg only",
          fit->max_angle_deg);
      *error = text;
    }
    return false;
  }
  const double r_max = std::tan(widest_theta);
  constexpr int kSamples = 400;
  double c[6] = {0, 0, 0, 0, 0, 0};
  for (int pass = 0; pass < 4; ++pass) {
    cv::Mat A(kSamples, 6, CV_64F), b(kSamples, 1, CV_64F);
    for (int i = 0; i < kSamples; ++i) {
      const double r = r_max * (i + 1) / kSamples, r2 = r * r;
      const double g = equidistantGain(k, r);
      const double den = 1.0 + r2 * (c[3] + r2 * (c[4] + r2 * c[5]));
      const double w = r / std::max(std::abs(den), 1e-6);  // pixel residual of g*den - num is r*(...)/den
      const double powers[3] = {r2, r2 * r2, r2 * r2 * r2};
      for (int j = 0; j < 3; ++j) {
        A.at<double>(i, j) = w * powers[j];
        A.at<double>(i, 3 + j) = -w * g * powers[j];
      }
      b.at<double>(i) = w * (g - 1.0);
    }
    cv::Mat x;
    cv::solve(A, b, x, cv::DECOMP_SVD);
    for (int j = 0; j < 6; ++j) c[j] = x.at<double>(j);
  }
  double worst = 0.0, previous_radius = 0.0;
  for (int i = 0; i <= 4 * kSamples; ++i) {
    const double r = r_max * i / (4.0 * kSamples);
    const double radius = r * rationalGain(c, r);
    if (i > 0 && !(radius > previous_radius)) {
      if (error) *error = "the rational model fitted to the equidistant one is not monotonic within the image";
      return false;
    }
    previous_radius = radius;
    worst = std::max(worst, K(0, 0) * r * std::abs(rationalGain(c, r) - equidistantGain(k, r)));
  }
  fit->max_error_px = worst;
  fit->dist = (cv::Mat_<double>(1, 8) << c[0], c[1], 0.0, 0.0, c[2], c[3], c[4], c[5]);
  return true;
}

}  // namespace deepnav
