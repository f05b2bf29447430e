#include "vision/calib/pinax_model.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <opencv2/calib3d.hpp>

namespace deepnav {
namespace {

const std::array kPinaxParams = {
    ParamDecl<PinaxConfig>{"reference_distance_m", ParamType::kDouble, "m", 0.2, 50, "",
                           "flat port: distance at which the PinAx mapping is exact (middle of the working range)",
                           DEEPNAV_PARAM_FIELD(PinaxConfig, reference_distance_m)},
};

}  // namespace

std::span<const ParamDecl<PinaxConfig>> pinaxParams() { return kPinaxParams; }

bool validatePinaxConfig(const PinaxConfig& c, std::string* error) {
  return validateFlatPort(c.port, error) &&
         checkParamRanges(pinaxParams(), c, "PinaxConfig", kCameraPortSection, error);
}

double pinaxVirtualCentreZ(const FlatPort& port, double max_theta_air_rad) {
  // The crossing is monotonic in the angle only near d0*, so sample the whole range.
  constexpr int kSamples = 64;
  double lo = paraxialAxisCrossingZ(port);
  double hi = lo;
  for (int i = 1; i <= kSamples; ++i) {
    const double z = axisCrossingZ(port, max_theta_air_rad * i / kSamples);
    lo = std::min(lo, z);
    hi = std::max(hi, z);
  }
  return 0.5 * (lo + hi);
}

bool pinaxVirtualToRealNormalised(const PinaxConfig& config, double z_virtual, const Eigen::Vector3d& dir_virtual,
                                  Eigen::Vector2d* xy_real) {
  if (!(dir_virtual.z() > 0.0)) return false;
  const double reach = (config.reference_distance_m - z_virtual) / dir_virtual.z();
  const Eigen::Vector3d p_cam_m = dir_virtual * reach + Eigen::Vector3d(0.0, 0.0, z_virtual);
  return projectThroughPort(config.port, p_cam_m, xy_real);
}

double maxAirAngleRad(const cv::Matx33d& K, const cv::Mat& dist, cv::Size image_size) {
  const std::vector<cv::Point2d> corners = {{0.0, 0.0},
                                            {image_size.width - 1.0, 0.0},
                                            {0.0, image_size.height - 1.0},
                                            {image_size.width - 1.0, image_size.height - 1.0}};
  std::vector<cv::Point2d> normalised;
  cv::undistortPoints(corners, normalised, K, dist);
  double widest = 0.0;
  for (const auto& p : normalised) widest = std::max(widest, std::atan(std::hypot(p.x, p.y)));
  return widest;
}

double pinaxFocalScale(const PinaxConfig& config, double z_virtual, double max_theta_air_rad) {
  PortRay ray;
  const Eigen::Vector3d dir_air(std::sin(max_theta_air_rad), 0.0, std::cos(max_theta_air_rad));
  if (!traceThroughPort(config.port, dir_air, &ray)) return config.port.n_water / config.port.n_air;
  // The point that corner ray reaches at the reference distance, seen from the virtual centre.
  const double t = (config.reference_distance_m - ray.origin_m.z()) / ray.dir.z();
  const Eigen::Vector3d p = ray.origin_m + t * ray.dir;
  const double tan_virtual = p.x() / (p.z() - z_virtual);
  return std::tan(max_theta_air_rad) / tan_virtual;
}

}  // namespace deepnav
