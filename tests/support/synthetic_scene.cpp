#include "tests/support/synthetic_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "vision/stereo/disparity_estimator.h"

namespace deepnav {
namespace {

std::uint32_t hash3(std::uint32_t seed, std::int32_t x, std::int32_t y) {
  std::uint32_t h = seed * 0x9E3779B1u ^ static_cast<std::uint32_t>(x) * 0x85EBCA77u ^
                    static_cast<std::uint32_t>(y) * 0xC2B2AE3Du;
  h ^= h >> 15;
  h *= 0x2C1B3C6Du;
  h ^= h >> 12;
  h *= 0x297A2D39u;
  h ^= h >> 15;
  return h;
}

// Smooth value noise in [0, 1] at lattice spacing cell_m (bilinear with smoothstep).
double valueNoise(std::uint32_t seed, double s, double t, double cell_m) {
  const double x = s / cell_m, y = t / cell_m;
  const double fx = std::floor(x), fy = std::floor(y);
  const auto ix = static_cast<std::int32_t>(fx), iy = static_cast<std::int32_t>(fy);
  double ax = x - fx, ay = y - fy;
  ax = ax * ax * (3.0 - 2.0 * ax);
  ay = ay * ay * (3.0 - 2.0 * ay);
  auto v = [&](std::int32_t dx, std::int32_t dy) {
    return static_cast<double>(hash3(seed, ix + dx, iy + dy) & 0xFFFF) / 65535.0;
  };
  const double top = v(0, 0) + ax * (v(1, 0) - v(0, 0));
  const double bottom = v(0, 1) + ax * (v(1, 1) - v(0, 1));
  return top + ay * (bottom - top);
}

// Low-contrast texture of grey levels ~[60, 190]: three octaves of value noise.
double texture(std::uint32_t seed, double s, double t) {
  const double n = 0.5 * valueNoise(seed, s, t, 0.012) + 0.3 * valueNoise(seed + 1, s, t, 0.04) +
                   0.2 * valueNoise(seed + 2, s, t, 0.15);
  return 60.0 + 130.0 * n;
}

struct Hit {
  double range = std::numeric_limits<double>::infinity();  // along the unit ray
  int surface = -1;
  double s = 0.0, t = 0.0;
  std::uint32_t seed = 0;
};

void intersect(const SyntheticRectangle& rect, const Eigen::Vector3d& n, int id,
               const Eigen::Vector3d& o, const Eigen::Vector3d& dir, Hit* hit) {
  const double denom = n.dot(dir);
  if (std::abs(denom) < 1e-12) return;
  const double range = n.dot(rect.centre_m - o) / denom;
  if (range <= 1e-6 || range >= hit->range) return;
  const Eigen::Vector3d q = o + range * dir - rect.centre_m;
  const double s = q.dot(rect.axis_u), t = q.dot(rect.axis_v);
  if (std::abs(s) > rect.half_u_m || std::abs(t) > rect.half_v_m) return;
  *hit = Hit{range, id, s, t, rect.texture_seed};
}

void intersect(const SyntheticSphere& sphere, int id, const Eigen::Vector3d& o,
               const Eigen::Vector3d& dir, Hit* hit) {
  const Eigen::Vector3d oc = o - sphere.centre_m;
  const double b = oc.dot(dir);
  const double disc = b * b - (oc.squaredNorm() - sphere.radius_m * sphere.radius_m);
  if (disc < 0.0) return;
  const double range = -b - std::sqrt(disc);
  if (range <= 1e-6 || range >= hit->range) return;
  const Eigen::Vector3d q = o + range * dir - sphere.centre_m;
  *hit = Hit{range, id, std::atan2(q.y(), q.x()) * sphere.radius_m, q.z(), sphere.texture_seed};
}

}  // namespace

void SyntheticScene::addBox(const Eigen::Vector3d& base_m, const Eigen::Vector3d& size_m,
                            double yaw_rad, std::uint32_t seed) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d ex = R.col(0), ey = R.col(1), ez = R.col(2);
  const Eigen::Vector3d c = base_m + 0.5 * size_m.z() * ez;
  const double hx = 0.5 * size_m.x(), hy = 0.5 * size_m.y(), hz = 0.5 * size_m.z();
  rectangles.push_back({c + hz * ez, ex, ey, hx, hy, seed});       // top
  rectangles.push_back({c - hz * ez, ey, ex, hy, hx, seed + 10});  // bottom
  rectangles.push_back({c + hx * ex, ey, ez, hy, hz, seed + 20});
  rectangles.push_back({c - hx * ex, ez, ey, hz, hy, seed + 30});
  rectangles.push_back({c + hy * ey, ez, ex, hz, hx, seed + 40});
  rectangles.push_back({c - hy * ey, ex, ez, hx, hz, seed + 50});
}

void renderSyntheticView(const SyntheticScene& scene, const StereoGeometry& geometry, int width_px,
                         int height_px, const Eigen::Isometry3d& T_world_cam, bool with_image,
                         SyntheticView* view) {
  view->disparity_px.create(height_px, width_px, CV_32FC1);
  view->surface.create(height_px, width_px, CV_32SC1);
  if (with_image) view->image.create(height_px, width_px, CV_8UC1);
  const Eigen::Matrix3d R = T_world_cam.linear();
  const Eigen::Vector3d o = T_world_cam.translation();
  const int n_rect = static_cast<int>(scene.rectangles.size());
  constexpr int kCached = 64;  // normals of the first rectangles, computed once per view
  std::array<Eigen::Vector3d, kCached> normals;
  for (int i = 0; i < std::min(n_rect, kCached); ++i) normals[i] = scene.rectangles[i].normal();
  for (int v = 0; v < height_px; ++v) {
    for (int u = 0; u < width_px; ++u) {
      const Eigen::Vector3d ray_cam((u - geometry.cx_px) / geometry.fx_px,
                                    (v - geometry.cy_px) / geometry.fy_px, 1.0);
      const Eigen::Vector3d dir = (R * ray_cam).normalized();
      Hit hit;
      for (int i = 0; i < n_rect; ++i) {
        const SyntheticRectangle& rect = scene.rectangles[i];
        intersect(rect, i < kCached ? normals[i] : rect.normal(), i, o, dir, &hit);
      }
      for (int i = 0; i < static_cast<int>(scene.spheres.size()); ++i) {
        intersect(scene.spheres[i], n_rect + i, o, dir, &hit);
      }
      const double z = hit.range / ray_cam.norm();  // depth along the optical axis
      view->surface.at<std::int32_t>(v, u) = hit.surface;
      view->disparity_px.at<float>(v, u) =
          hit.surface >= 0 ? static_cast<float>(geometry.focalBaseline() / z) : kInvalidDisparity;
      if (with_image) {
        const double g = hit.surface >= 0 ? texture(hit.seed, hit.s, hit.t) : 40.0;
        view->image.at<std::uint8_t>(v, u) = cv::saturate_cast<std::uint8_t>(g);
      }
    }
  }
}

void renderSyntheticStereoPair(const SyntheticScene& scene, const StereoGeometry& geometry,
                               int width_px, int height_px, const Eigen::Isometry3d& T_world_cam,
                               SyntheticView* left, SyntheticView* right) {
  renderSyntheticView(scene, geometry, width_px, height_px, T_world_cam, true, left);
  const Eigen::Isometry3d T_world_right =
      T_world_cam * Eigen::Translation3d(geometry.baseline_m, 0.0, 0.0);
  renderSyntheticView(scene, geometry, width_px, height_px, T_world_right, true, right);
}

}  // namespace deepnav
