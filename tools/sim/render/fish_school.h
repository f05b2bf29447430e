#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace deepnav::sim {

// A few fish (ellipsoids) swimming around the panel between its faces and the ROV, each on its own
// superellipse x^4 + y^4 = R^4 about the panel centre (the shape the ROV follows, so they never cross
// the panel), at its own height, speed and direction, with a slow bob. Drawn from the seed.
class FishSchool {
 public:
  struct Fish {
    float path_radius_m = 1.5f;
    float z_m = 1.0f;
    float omega_radps = 0.2f;    // signed: direction of travel around the panel
    float phase_rad = 0.0f;
    float bob_amplitude_m = 0.05f;
    float bob_omega_radps = 1.0f;
    Eigen::Vector3f semi_axes_m{0.1f, 0.025f, 0.035f};  // length, width, height
  };

  // Paths lie between panel_half_width + 0.35 m and panel_half_width + standoff - 0.25 m.
  void init(int count, double panel_half_width_m, double standoff_m, std::uint64_t seed);
  // Pose of fish i at time t (panel frame P): x along the swimming direction, z up.
  void poseAt(int i, double t_s, Eigen::Matrix3f* R_panel_fish, Eigen::Vector3f* p_fish_in_panel_m) const;
  const std::vector<Fish>& fish() const { return fish_; }

 private:
  Eigen::Vector3f positionAt(const Fish& f, double t_s) const;
  std::vector<Fish> fish_;
};

}  // namespace deepnav::sim
