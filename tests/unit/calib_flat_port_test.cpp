#include "vision/calib/flat_port.h"

#include <cmath>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace deepnav {
namespace {

constexpr double kPi = 3.14159265358979323846;

// GIVEN a 30 deg ray from air into glass of index 1.5 (hand computed: sin(t) = 0.5 / 1.5 = 1/3)
TEST(CalibFlatPort, SnellAirToGlassMatchesHandComputedRay) {
  const Eigen::Vector3d in(0.5, 0.0, std::sqrt(3.0) / 2.0);
  Eigen::Vector3d out;
  ASSERT_TRUE(refractDirection(in, Eigen::Vector3d::UnitZ(), 1.0, 1.5, &out));
  EXPECT_NEAR(out.x(), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(out.y(), 0.0, 1e-12);
  EXPECT_NEAR(out.z(), std::sqrt(8.0) / 3.0, 1e-12);
  EXPECT_NEAR(out.norm(), 1.0, 1e-12);
  // The normal's orientation does not matter.
  Eigen::Vector3d out_flipped;
  ASSERT_TRUE(refractDirection(in, -Eigen::Vector3d::UnitZ(), 1.0, 1.5, &out_flipped));
  EXPECT_NEAR((out - out_flipped).norm(), 0.0, 1e-15);
}

TEST(CalibFlatPort, SnellObliqueNormalKeepsThePlaneOfIncidence) {
  // Surface tilted 20 deg about y; the incident ray at 35 deg from the normal in the x-z plane, with a
  // y component making the plane of incidence oblique: n1 sin(i) = n2 sin(t) and coplanarity must hold.
  const Eigen::Vector3d n(std::sin(20 * kPi / 180), 0.0, std::cos(20 * kPi / 180));
  const Eigen::Vector3d in = Eigen::Vector3d(0.4, 0.3, 0.866).normalized();
  Eigen::Vector3d out;
  ASSERT_TRUE(refractDirection(in, n, 1.49, 1.34, &out));
  const double sin_i = in.cross(n).norm();
  const double sin_t = out.cross(n).norm();
  EXPECT_NEAR(1.49 * sin_i, 1.34 * sin_t, 1e-12);
  EXPECT_NEAR(in.cross(n).normalized().dot(out.cross(n).normalized()), 1.0, 1e-12);
  EXPECT_GT(out.dot(n), 0.0);  // transmitted, not reflected
}

TEST(CalibFlatPort, TotalInternalReflectionIsRefused) {
  // Glass to air at 45 deg: sin(t) = 1.5 sin(45 deg) = 1.06 > 1.
  const Eigen::Vector3d in(std::sqrt(0.5), 0.0, std::sqrt(0.5));
  Eigen::Vector3d out;
  EXPECT_FALSE(refractDirection(in, Eigen::Vector3d::UnitZ(), 1.5, 1.0, &out));
  EXPECT_TRUE(refractDirection(in, Eigen::Vector3d::UnitZ(), 1.5, 1.4, &out));
}

TEST(CalibFlatPort, TraceThroughPortMatchesHandComputedRay) {
  // d0 = 0.1 m, d1 = 0.02 m, n = 1 / 1.5 / 4/3, ray at 30 deg:
  //   inner hit x = 0.1 tan 30 = 0.0577350; in glass sin = 1/3, tan = 0.3535534 -> outer x = 0.0648061;
  //   in water sin = 0.5 / (4/3) = 0.375, cos = 0.9270248.
  FlatPort port;
  port.pinhole_to_glass_m = 0.1;
  port.glass_thickness_m = 0.02;
  port.n_air = 1.0;
  port.n_glass = 1.5;
  port.n_water = 4.0 / 3.0;
  PortRay ray;
  ASSERT_TRUE(traceThroughPort(port, Eigen::Vector3d(0.5, 0.0, std::sqrt(3.0) / 2.0) * 3.0, &ray));
  EXPECT_NEAR(ray.origin_m.x(), 0.0648061, 1e-7);
  EXPECT_NEAR(ray.origin_m.y(), 0.0, 1e-15);
  EXPECT_NEAR(ray.origin_m.z(), 0.12, 1e-15);
  EXPECT_NEAR(ray.dir.x(), 0.375, 1e-12);
  EXPECT_NEAR(ray.dir.z(), 0.9270248, 1e-7);
  // Along the axis nothing bends.
  ASSERT_TRUE(traceThroughPort(port, Eigen::Vector3d::UnitZ(), &ray));
  EXPECT_NEAR((ray.dir - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-15);
  EXPECT_FALSE(traceThroughPort(port, Eigen::Vector3d(1.0, 0.0, 0.0), &ray));
}

TEST(CalibFlatPort, ProjectionInvertsTheTrace) {
  FlatPort port;
  port.pinhole_to_glass_m = 0.012;
  port.glass_thickness_m = 0.015;
  for (double deg : {0.5, 10.0, 25.0, 40.0}) {
    for (double reach_m : {0.3, 1.0, 3.0}) {
      const double a = deg * kPi / 180;
      const Eigen::Vector3d dir(std::sin(a) * 0.6, std::sin(a) * 0.8, std::cos(a));
      PortRay ray;
      ASSERT_TRUE(traceThroughPort(port, dir, &ray));
      const Eigen::Vector3d p = ray.origin_m + reach_m * ray.dir;
      Eigen::Vector2d xy;
      ASSERT_TRUE(projectThroughPort(port, p, &xy));
      EXPECT_NEAR(xy.x(), dir.x() / dir.z(), 1e-12) << deg << " deg, " << reach_m << " m";
      EXPECT_NEAR(xy.y(), dir.y() / dir.z(), 1e-12);
    }
  }
  Eigen::Vector2d xy;
  EXPECT_FALSE(projectThroughPort(port, Eigen::Vector3d(0.1, 0.0, 0.02), &xy));  // inside the housing
}

TEST(CalibFlatPort, AxisCrossingsAgreeAtTheOptimalPinholeDistance) {
  FlatPort port;
  port.glass_thickness_m = 0.01;
  port.pinhole_to_glass_m = optimalPinholeToGlassM(port);
  EXPECT_GT(port.pinhole_to_glass_m, 0.0);
  const double z0 = paraxialAxisCrossingZ(port);
  EXPECT_NEAR(axisCrossingZ(port, 1e-4), z0, 1e-9);
  // Second-order cancellation: over +-20 deg the crossings stay within a few microns ...
  for (double deg = 1; deg <= 20; deg += 1) EXPECT_NEAR(axisCrossingZ(port, deg * kPi / 180), z0, 5e-6) << deg;
  // ... while a housing with the pinhole 2 cm from the glass spreads them over tenths of a millimetre.
  FlatPort far = port;
  far.pinhole_to_glass_m = 0.02;
  EXPECT_GT(std::abs(axisCrossingZ(far, 20 * kPi / 180) - paraxialAxisCrossingZ(far)), 2e-4);
}

TEST(CalibFlatPort, ValidationNamesTheField) {
  FlatPort port;
  std::string error;
  EXPECT_TRUE(validateFlatPort(port, &error));
  port.glass_thickness_m = -0.01;
  EXPECT_FALSE(validateFlatPort(port, &error));
  EXPECT_NE(error.find("glass_thickness_m"), std::string::npos) << error;
  port = FlatPort{};
  port.n_water = 1.0;
  EXPECT_FALSE(validateFlatPort(port, &error));
  EXPECT_NE(error.find("n_water"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav
