#pragma once
// The scene both plane test files use: a 320 x 240 camera (f 400 px, baseline 0.15 m) over a floor with a
// box on it.
#include <cmath>

#include "tests/support/synthetic_scene.h"

namespace deepnav::planes_test {

constexpr int kWidth = 320;
constexpr int kHeight = 240;
constexpr double kDeg = M_PI / 180.0;

inline StereoGeometry geometry() { return centredStereoGeometry(400.0, kWidth, kHeight, 0.15); }

// World z up. A floor and a box yawed 40 deg (its top parallel to the floor, two side faces and the top
// visible from a camera looking along world y: three non-parallel directions).
inline SyntheticScene boxOnFloor() {
  SyntheticScene scene;
  scene.rectangles.push_back(
      {Eigen::Vector3d(0, 3, 0), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 4.0, 4.0, 3});
  scene.addBox(Eigen::Vector3d(0.0, 2.4, 0.0), Eigen::Vector3d(0.7, 0.7, 0.5), 40.0 * kDeg, 11);
  return scene;
}

}  // namespace deepnav::planes_test
