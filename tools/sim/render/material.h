#pragma once
#include <cstdint>

#include <Eigen/Core>

namespace deepnav::sim {

enum class MaterialKind : std::uint8_t {
  kSolid,        // constant albedo
  kRectTexture,  // texture over a rect: u = (x - u0) * texels_per_m, v = (v0 - y) * texels_per_m
  kArcTexture,   // texture over an arc: u = angle * radius * texels_per_m, v = (v0 - z) * texels_per_m
};

// How a surface reflects the lights: Lambertian, albedo per channel in BGR order, in [0, 1].
struct Material {
  MaterialKind kind = MaterialKind::kSolid;
  Eigen::Vector3f albedo_bgr = Eigen::Vector3f::Constant(0.5f);       // kSolid
  Eigen::Vector3f back_albedo_bgr = Eigen::Vector3f::Constant(0.12f);  // back side of a rect or arc
  int texture = -1;  // index into the scene's textures
  float texels_per_m = 500.0f;
  float u0_m = 0.0f;
  float v0_m = 0.0f;
};

}  // namespace deepnav::sim
