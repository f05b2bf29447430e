#include "tools/sim/render/manipulator_arm.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace deepnav::sim {

const Eigen::Vector3f ManipulatorArm::kBase_in_robot_m(0.75f, 0.0f, -0.55f);

namespace {

constexpr double kPi = std::numbers::pi;
constexpr float kDeg = static_cast<float>(kPi / 180.0);

double smootherstep01(double s) {
  s = std::clamp(s, 0.0, 1.0);
  return s * s * s * (s * (6.0 * s - 15.0) + 10.0);
}

// Frame whose z axis is `axis` (a cylinder's axis) and y axis `y_axis` (perpendicular to it).
Eigen::Matrix3f frameAlong(const Eigen::Vector3f& axis, const Eigen::Vector3f& y_axis) {
  Eigen::Matrix3f R;
  R.col(2) = axis.normalized();
  R.col(1) = y_axis.normalized();
  R.col(0) = R.col(1).cross(R.col(2));
  return R;
}

Primitive cylinder(float radius, float length, int material) {
  Primitive p;
  p.kind = ShapeKind::kCylinder;
  p.material = material;
  p.lo = Eigen::Vector3f(-radius, -radius, 0.0f);
  p.hi = Eigen::Vector3f(radius, radius, length);
  return p;
}

Primitive box(const Eigen::Vector3f& lo, const Eigen::Vector3f& hi, int material) {
  Primitive p;
  p.kind = ShapeKind::kBox;
  p.material = material;
  p.lo = lo;
  p.hi = hi;
  return p;
}

}  // namespace

void ManipulatorArm::init(const std::vector<ArmWindow>& windows) { windows_ = windows; }

double ManipulatorArm::deployment(double t_s) const {
  for (const ArmWindow& w : windows_) {
    if (t_s < w.t_start_s || t_s > w.t_end_s) continue;
    const double up = (t_s - w.t_start_s) / w.deploy_s, down = (w.t_end_s - t_s) / w.deploy_s;
    return smootherstep01(std::min(up, down));
  }
  return 0.0;
}

ManipulatorArm::Joints ManipulatorArm::stowed() {
  // Upper arm back and slightly down, forearm folded forward under it: the wrist 0.2 m below the base,
  // the gripper more than 55 deg below the cameras' axis (outside a 688 x 516, f 580-700 px view).
  Joints j;
  j.shoulder_rad = 190.0f * kDeg;
  j.forearm_rad = -10.0f * kDeg;
  return j;
}

// Elbow-up two-link inverse kinematics to the wrist target (clamped to 99 % of the arm's length).
ManipulatorArm::Joints ManipulatorArm::reaching(const ArmWindow& w, double t_s) {
  const double phase = 2.0 * kPi * t_s / w.sway_period_s;
  const double x = w.reach_m + w.sway_m * std::sin(phase), z = w.height_m + 0.5 * w.sway_m * std::sin(0.7 * phase + 1.0);
  Joints j;
  j.yaw_rad = static_cast<float>(std::atan2(w.lateral_m, x));
  const double r = std::hypot(x, w.lateral_m);
  const double l1 = kUpperArm_m, l2 = kForearm_m;
  const double d = std::clamp(std::hypot(r, z), std::abs(l1 - l2) + 1e-3, 0.99 * (l1 + l2));
  const double elevation = std::atan2(z, r);
  const double alpha = std::acos(std::clamp((l1 * l1 + d * d - l2 * l2) / (2.0 * l1 * d), -1.0, 1.0));
  const double shoulder = elevation + alpha;
  const double ex = l1 * std::cos(shoulder), ez = l1 * std::sin(shoulder);
  const double wx = d * std::cos(elevation), wz = d * std::sin(elevation);
  j.shoulder_rad = static_cast<float>(shoulder);
  j.forearm_rad = static_cast<float>(std::atan2(wz - ez, wx - ex));
  return j;
}

ManipulatorArm::Joints ManipulatorArm::jointsAt(double t_s) const {
  const double s = deployment(t_s);
  const Joints a = stowed();
  if (!(s > 0.0)) return a;
  const ArmWindow* window = nullptr;
  for (const ArmWindow& w : windows_)
    if (t_s >= w.t_start_s && t_s <= w.t_end_s) window = &w;
  const Joints b = reaching(*window, t_s);
  const float f = static_cast<float>(s);
  Joints j;
  j.yaw_rad = a.yaw_rad + f * (b.yaw_rad - a.yaw_rad);
  j.shoulder_rad = a.shoulder_rad + f * (b.shoulder_rad - a.shoulder_rad);
  j.forearm_rad = a.forearm_rad + f * (b.forearm_rad - a.forearm_rad);
  return j;
}

void ManipulatorArm::partsAt(double t_s, Parts* parts) const {
  const Joints j = jointsAt(t_s);
  const Eigen::Vector3f forward(std::cos(j.yaw_rad), std::sin(j.yaw_rad), 0.0f);
  const Eigen::Vector3f normal(-std::sin(j.yaw_rad), std::cos(j.yaw_rad), 0.0f);  // joint axes
  const Eigen::Vector3f up = Eigen::Vector3f::UnitZ();
  const Eigen::Vector3f upper = std::cos(j.shoulder_rad) * forward + std::sin(j.shoulder_rad) * up;
  const Eigen::Vector3f fore = std::cos(j.forearm_rad) * forward + std::sin(j.forearm_rad) * up;
  const Eigen::Vector3f base = kBase_in_robot_m;
  const Eigen::Vector3f elbow = base + kUpperArm_m * upper, wrist = elbow + kForearm_m * fore;
  const Eigen::Matrix3f R_yaw = frameAlong(up, normal);
  const Eigen::Matrix3f R_joint = frameAlong(normal, up);
  Parts& p = *parts;
  p[0] = {box(Eigen::Vector3f(-0.09f, -0.09f, -0.14f), Eigen::Vector3f(0.09f, 0.09f, -0.02f), 1), R_yaw, base};
  p[1] = {cylinder(0.07f, 0.18f, 1), R_joint, base - 0.09f * normal};
  p[2] = {cylinder(0.045f, kUpperArm_m, 0), frameAlong(upper, normal), base};
  p[3] = {cylinder(0.055f, 0.13f, 1), R_joint, elbow - 0.065f * normal};
  p[4] = {cylinder(0.04f, kForearm_m, 0), frameAlong(fore, normal), elbow};
  p[5] = {box(Eigen::Vector3f(-0.03f, -0.06f, 0.0f), Eigen::Vector3f(0.03f, 0.06f, kGripper_m), 1), frameAlong(fore, normal),
          wrist};
}

Eigen::Vector3f ManipulatorArm::wristAt(double t_s) const {
  Parts parts;
  partsAt(t_s, &parts);
  return parts[4].p_part_in_robot_m + kForearm_m * parts[4].R_robot_part.col(2);
}

}  // namespace deepnav::sim
