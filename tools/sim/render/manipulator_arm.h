#pragma once
#include <array>
#include <vector>

#include <Eigen/Core>

#include "tools/sim/render/primitive.h"
#include "tools/sim/sensors/camera_rig.h"

namespace deepnav::sim {

// The manipulator arm in front of the cameras (camera.arm), an occluder fixed to the robot frame R (FLU):
// a base under the camera bar (kBase_in_robot_m, 0.15 m ahead of and 0.35 m below the default left
// camera), a shoulder, an upper arm (kUpperArm_m), an elbow, a forearm (kForearm_m) and a gripper
// (kGripper_m), as capped cylinders and boxes. The arm is planar in a vertical plane yawed towards the
// gripper's target; inside a window it unfolds over deploy_s from the stowed pose (folded under the
// vehicle, out of the cameras' view) to the elbow-up solution reaching the wrist target
//   base + (reach_m, lateral_m, height_m) + sway_m (sin(2 pi t / P), 0, 0.5 sin(1.4 pi t / P + 1))
// (a slow working motion, P = sway_period_s), holds it and folds back before t_end_s. Joint angles are
// blended with the quintic smootherstep, so the motion starts and stops smoothly. Outside every window
// the arm is stowed. Deterministic: a function of t only.
class ManipulatorArm {
 public:
  static constexpr int kParts = 6;  // base, shoulder, upper arm, elbow, forearm, gripper
  static constexpr float kUpperArm_m = 0.55f;
  static constexpr float kForearm_m = 0.60f;
  static constexpr float kGripper_m = 0.15f;
  static const Eigen::Vector3f kBase_in_robot_m;

  // One part: its primitive's shape (kind, lo, hi, material index 0 = links, 1 = joints and gripper) and
  // its pose in R.
  struct Part {
    Primitive shape;
    Eigen::Matrix3f R_robot_part = Eigen::Matrix3f::Identity();
    Eigen::Vector3f p_part_in_robot_m = Eigen::Vector3f::Zero();
  };
  using Parts = std::array<Part, kParts>;

  void init(const std::vector<ArmWindow>& windows);
  bool enabled() const { return !windows_.empty(); }
  // How far the arm is deployed at t: 0 stowed, 1 at its target.
  double deployment(double t_s) const;
  // Every part's pose at t, in R.
  void partsAt(double t_s, Parts* parts) const;
  // The wrist's position at t, in R (tests).
  Eigen::Vector3f wristAt(double t_s) const;

 private:
  struct Joints {
    float yaw_rad = 0.0f;       // of the arm's plane about R's z, at the base
    float shoulder_rad = 0.0f;  // upper arm's elevation from the plane's forward axis, up positive
    float forearm_rad = 0.0f;   // forearm's elevation (absolute, not relative to the upper arm)
  };
  Joints jointsAt(double t_s) const;
  static Joints stowed();
  static Joints reaching(const ArmWindow& w, double t_s);

  std::vector<ArmWindow> windows_;
};

}  // namespace deepnav::sim
