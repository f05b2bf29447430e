#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "tools/sim/render/water_optics.h"
#include "tools/sim/sensors/camera_rig.h"
#include "tools/sim/water_config.h"

namespace deepnav::sim {

// Marine snow: particles fixed in the water (panel frame P, which is fixed in odom), drifting with the
// current and sinking, seen by both cameras (so with the parallax of their depth) and lit only by the
// lamps: bright inside the beams, invisible outside (there is no other light at depth).
//
// The particles fill a cube of side kCube_m that repeats through space: particle i sits at
// p_i + v_i t, wrapped into the cube centred kAhead_m in front of the rig, so the same particles are met
// again only a cube's side away (more than the rendered range kRange_m plus the baseline). Each has a
// diameter drawn log-uniformly in the configured range and sinks at the configured speed (x 0.5-1.5).
// Rendering: a particle at distance r from a lamp reflects L_p = albedo sum_lamps I B(phi) / r^2
// exp(-beta r) (a Lambertian sphere seen from about the lamps' direction), seen through exp(-beta s);
// it covers pi (f D / 2 z)^2 pixels, alpha-blended over what lies behind it (depth test against the
// view's depth map): below one pixel spread bilinearly over four pixels, larger ones as discs with a
// one-pixel soft edge. Particles within 5 cm of the camera are skipped (inside the port's housing) and
// fade out over the last 0.5 m of kRange_m.
class MarineSnow {
 public:
  static constexpr float kCube_m = 4.8f;
  static constexpr float kAhead_m = 1.5f;
  static constexpr float kRange_m = 3.0f;

  void init(const WaterConfig& water, const Eigen::Isometry3d& T_odom_panel, std::uint64_t seed);
  bool enabled() const { return !x0_.empty(); }
  // Places the particles at time t around the rig (p_rig: between the cameras, ahead: the optical axis,
  // both in P) and computes each lit one's reflected radiance (B, G, R) from the lamps.
  void update(double t_s, const Eigen::Vector3f& p_rig_in_panel_m, const Eigen::Vector3f& ahead_in_panel,
              const std::array<Eigen::Vector3f, 2>& lamps_in_panel_m, const Eigen::Vector3f& lamp_axis_in_panel,
              const WaterOptics& optics, const LampBeam& beam);
  // Draws the lit particles into one view: radiance (channels 1 grey or 3 BGR, width x height) and its
  // depth map (0 = open water) of the pinhole camera at R_panel_cam, p_cam.
  void draw(const Eigen::Matrix3f& R_panel_cam, const Eigen::Vector3f& p_cam_in_panel_m, const CameraConfig& camera,
            const WaterOptics& optics, int channels, float* radiance, const float* depth_m) const;
  // The lit particles of the last update (tests): position in P, diameter, radiance B, G, R.
  struct Lit {
    Eigen::Vector3f p_in_panel_m;
    float diameter_m;
    std::array<float, 3> radiance;
  };
  const std::vector<Lit>& lit() const { return lit_; }

 private:
  void splat(float u, float v, float area_px, float radius_px, const float* colour, float depth, int channels,
             const CameraConfig& camera, float* radiance, const float* depth_m) const;
  // Structure of arrays: the cube positions at t = 0 (P), sinking speeds, diameters.
  std::vector<float> x0_, y0_, z0_, sink_mps_, diameter_m_;
  Eigen::Vector3d current_in_panel_mps_ = Eigen::Vector3d::Zero();
  float albedo_ = 0.5f;
  std::vector<Lit> lit_;  // per frame, reserved for all particles
};

}  // namespace deepnav::sim
