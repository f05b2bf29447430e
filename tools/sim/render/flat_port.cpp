#include "tools/sim/render/flat_port.h"

#include <cmath>

#include <opencv2/imgproc.hpp>

namespace deepnav::sim {
namespace {

constexpr int kIterations = 4;

}  // namespace

CameraConfig FlatPortResampler::pinholeFor(const CameraConfig& port_camera, const FlatPort& port) {
  CameraConfig pinhole = port_camera;
  const double magnification = port.n_water / port.n_air;
  pinhole.fx_px = port_camera.fx_px * magnification;
  pinhole.fy_px = port_camera.fy_px * magnification;
  return pinhole;
}

bool FlatPortResampler::init(const CameraConfig& port_camera, const FlatPort& port, std::string* error) {
  std::string why;
  if (!validateFlatPort(port, &why)) {
    if (error) *error = "flat port: " + why;
    return false;
  }
  port_camera_ = port_camera;
  pinhole_ = pinholeFor(port_camera, port);
  const int w = port_camera.width_px, h = port_camera.height_px;
  rays_.resize(static_cast<std::size_t>(w) * h);
  for (int v = 0; v < h; ++v) {
    for (int u = 0; u < w; ++u) {
      const Eigen::Vector3d d_air((u - port_camera.cx_px) / port_camera.fx_px, (v - port_camera.cy_px) / port_camera.fy_px,
                                  1.0);
      PortRay ray;
      if (!traceThroughPort(port, d_air, &ray)) {
        if (error) *error = "flat port: a camera ray is totally reflected (check the refractive indices)";
        return false;
      }
      rays_[static_cast<std::size_t>(v) * w + u] = {
          static_cast<float>(ray.origin_m.x()), static_cast<float>(ray.origin_m.y()),
          static_cast<float>(ray.origin_m.z()), static_cast<float>(ray.dir.x()),
          static_cast<float>(ray.dir.y()),      static_cast<float>(ray.dir.z())};
    }
  }
  map_px_.create(h, w, CV_32FC2);
  return true;
}

bool FlatPortResampler::resample(const cv::Mat& pinhole_image, const cv::Mat& pinhole_depth_m, cv::Mat& port_image,
                                 cv::Mat& port_depth_m) {
  const int w = port_camera_.width_px, h = port_camera_.height_px;
  const cv::Size size(w, h);
  if (pinhole_image.size() != size || pinhole_depth_m.size() != size || pinhole_depth_m.type() != CV_32F ||
      port_image.size() != size || port_image.type() != pinhole_image.type() || port_depth_m.size() != size ||
      port_depth_m.type() != CV_32F)
    return false;
  const float fx = static_cast<float>(pinhole_.fx_px), fy = static_cast<float>(pinhole_.fy_px);
  const float cx = static_cast<float>(pinhole_.cx_px), cy = static_cast<float>(pinhole_.cy_px);
  auto depthAt = [&](float u, float v) {
    const int iu = static_cast<int>(std::lround(u)), iv = static_cast<int>(std::lround(v));
    if (iu < 0 || iv < 0 || iu >= w || iv >= h) return 0.0f;
    return pinhole_depth_m.at<float>(iv, iu);
  };
  for (int v = 0; v < h; ++v) {
    auto* map_row = map_px_.ptr<cv::Vec2f>(v);
    auto* depth_row = port_depth_m.ptr<float>(v);
    for (int u = 0; u < w; ++u) {
      const WaterRay& r = rays_[static_cast<std::size_t>(v) * w + u];
      // Open water or first guess: the pinhole pixel looking along the water ray's direction.
      float pu = fx * r.dx / r.dz + cx, pv = fy * r.dy / r.dz + cy;
      float z = depthAt(pu, pv);
      float z_point = 0.0f;
      for (int it = 0; it < kIterations && z > 0.0f; ++it) {
        // The water ray's point at depth z, seen from the pinhole.
        const float t = (z - r.oz) / r.dz;
        const float x = r.ox + t * r.dx, y = r.oy + t * r.dy;
        z_point = z;
        pu = fx * x / z + cx;
        pv = fy * y / z + cy;
        z = depthAt(pu, pv);
      }
      map_row[u] = cv::Vec2f(pu, pv);
      depth_row[u] = z > 0.0f ? z_point : 0.0f;
    }
  }
  cv::remap(pinhole_image, port_image, map_px_, cv::noArray(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  return true;
}

}  // namespace deepnav::sim
