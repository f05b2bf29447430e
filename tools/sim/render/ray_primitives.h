#pragma once
#include <cmath>
#include <utility>

#include <Eigen/Core>

#include "tools/sim/render/primitive.h"

namespace deepnav::sim {

// Where a ray o + t d (in a primitive's local frame) meets it: the parameter t, the local point and the
// unit local normal turned towards the ray; `back` when the ray meets the back side of a rect or arc.
struct LocalHit {
  float t = 0.0f;
  Eigen::Vector3f p = Eigen::Vector3f::Zero();
  Eigen::Vector3f n = Eigen::Vector3f::UnitZ();
  bool back = false;
};

// Each returns true and fills *hit for the nearest intersection with t in (t_min, t_max). Analytic:
// one plane, one quadratic, or three slabs. d need not be unit length.

inline bool intersectRect(const Eigen::Vector3f& o, const Eigen::Vector3f& d, const Primitive& s, float t_min,
                          float t_max, LocalHit* hit) {
  if (d.z() == 0.0f) return false;
  const float t = -o.z() / d.z();
  if (!(t > t_min && t < t_max)) return false;
  const float x = o.x() + t * d.x(), y = o.y() + t * d.y();
  if (x < s.lo.x() || x > s.hi.x() || y < s.lo.y() || y > s.hi.y()) return false;
  hit->t = t;
  hit->p = Eigen::Vector3f(x, y, 0.0f);
  hit->back = d.z() > 0.0f;
  hit->n = Eigen::Vector3f(0.0f, 0.0f, hit->back ? -1.0f : 1.0f);
  return true;
}

inline bool intersectArc(const Eigen::Vector3f& o, const Eigen::Vector3f& d, const Primitive& s, float t_min,
                         float t_max, LocalHit* hit) {
  const float r = s.hi.x();
  const float a = d.x() * d.x() + d.y() * d.y();
  if (a <= 0.0f) return false;
  const float b = o.x() * d.x() + o.y() * d.y();
  const float c = o.x() * o.x() + o.y() * o.y() - r * r;
  const float disc = b * b - a * c;
  if (disc < 0.0f) return false;
  const float sq = std::sqrt(disc);
  const float roots[2] = {(-b - sq) / a, (-b + sq) / a};
  for (float t : roots) {
    if (!(t > t_min && t < t_max)) continue;
    const Eigen::Vector3f p = o + t * d;
    if (p.x() < 0.0f || p.y() < 0.0f || p.z() < s.lo.z() || p.z() > s.hi.z()) continue;
    const Eigen::Vector3f n_out(p.x() / r, p.y() / r, 0.0f);
    hit->t = t;
    hit->p = p;
    hit->back = n_out.dot(d) > 0.0f;
    hit->n = hit->back ? Eigen::Vector3f(-n_out) : n_out;
    return true;
  }
  return false;
}

inline bool intersectBox(const Eigen::Vector3f& o, const Eigen::Vector3f& d, const Primitive& s, float t_min,
                         float t_max, LocalHit* hit) {
  float t_near = -INFINITY, t_far = INFINITY;
  int axis = 0;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0f) {
      if (o[k] < s.lo[k] || o[k] > s.hi[k]) return false;
      continue;
    }
    const float inv = 1.0f / d[k];
    float t0 = (s.lo[k] - o[k]) * inv, t1 = (s.hi[k] - o[k]) * inv;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > t_near) t_near = t0, axis = k;
    if (t1 < t_far) t_far = t1;
  }
  // Seen from outside only: a ray starting inside a box is not a camera ray of this scene.
  if (t_near > t_far || !(t_near > t_min && t_near < t_max)) return false;
  hit->t = t_near;
  hit->p = o + t_near * d;
  hit->n = Eigen::Vector3f::Zero();
  hit->n[axis] = d[axis] > 0.0f ? -1.0f : 1.0f;
  hit->back = false;
  return true;
}

inline bool intersectCylinder(const Eigen::Vector3f& o, const Eigen::Vector3f& d, const Primitive& s,
                              float t_min, float t_max, LocalHit* hit) {
  const float r = s.hi.x();
  bool found = false;
  const float a = d.x() * d.x() + d.y() * d.y();
  if (a > 0.0f) {
    const float b = o.x() * d.x() + o.y() * d.y();
    const float c = o.x() * o.x() + o.y() * o.y() - r * r;
    const float disc = b * b - a * c;
    if (disc >= 0.0f) {
      const float t = (-b - std::sqrt(disc)) / a;
      const float z = o.z() + t * d.z();
      if (t > t_min && t < t_max && z >= s.lo.z() && z <= s.hi.z()) {
        hit->t = t_max = t;
        hit->p = o + t * d;
        hit->n = Eigen::Vector3f(hit->p.x() / r, hit->p.y() / r, 0.0f);
        found = true;
      }
    }
  }
  if (d.z() != 0.0f) {
    // The cap that faces the ray: the bottom one for a ray going up, else the top one.
    const float z_cap = d.z() > 0.0f ? s.lo.z() : s.hi.z();
    const float t = (z_cap - o.z()) / d.z();
    if (t > t_min && t < t_max) {
      const float x = o.x() + t * d.x(), y = o.y() + t * d.y();
      if (x * x + y * y <= r * r) {
        hit->t = t;
        hit->p = Eigen::Vector3f(x, y, z_cap);
        hit->n = Eigen::Vector3f(0.0f, 0.0f, d.z() > 0.0f ? -1.0f : 1.0f);
        found = true;
      }
    }
  }
  hit->back = false;
  return found;
}

inline bool intersectEllipsoid(const Eigen::Vector3f& o, const Eigen::Vector3f& d, const Primitive& s,
                               float t_min, float t_max, LocalHit* hit) {
  const Eigen::Vector3f inv = s.hi.cwiseInverse();
  const Eigen::Vector3f os = o.cwiseProduct(inv), ds = d.cwiseProduct(inv);
  const float a = ds.squaredNorm(), b = os.dot(ds), c = os.squaredNorm() - 1.0f;
  const float disc = b * b - a * c;
  if (disc < 0.0f) return false;
  const float t = (-b - std::sqrt(disc)) / a;
  if (!(t > t_min && t < t_max)) return false;
  hit->t = t;
  hit->p = o + t * d;
  hit->n = hit->p.cwiseProduct(inv).cwiseProduct(inv).normalized();
  hit->back = false;
  return true;
}

inline bool intersectPrimitive(const Eigen::Vector3f& o_local, const Eigen::Vector3f& d_local,
                               const Primitive& s, float t_min, float t_max, LocalHit* hit) {
  switch (s.kind) {
    case ShapeKind::kRect: return intersectRect(o_local, d_local, s, t_min, t_max, hit);
    case ShapeKind::kArc: return intersectArc(o_local, d_local, s, t_min, t_max, hit);
    case ShapeKind::kBox: return intersectBox(o_local, d_local, s, t_min, t_max, hit);
    case ShapeKind::kCylinder: return intersectCylinder(o_local, d_local, s, t_min, t_max, hit);
    case ShapeKind::kEllipsoid: return intersectEllipsoid(o_local, d_local, s, t_min, t_max, hit);
  }
  return false;
}

}  // namespace deepnav::sim
