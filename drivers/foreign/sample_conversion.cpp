#include "drivers/foreign/sample_conversion.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "drivers/foreign/frame_conventions.h"

namespace deepnav::foreign {
namespace {

Eigen::Vector3d toEigen(const ros::Vector3& v) { return {v.x, v.y, v.z}; }

double wrapTwoPi(double a) {
  const double two_pi = 2.0 * std::numbers::pi;
  a = std::fmod(a, two_pi);
  return a < 0.0 ? a + two_pi : a;
}

// The sensor's orientation in ENU/FLU, or false when the message has none (REP-145: covariance[0] = -1)
// or it is not a rotation.
bool orientationOf(const ros::Imu& m, FrameConvention convention, Eigen::Quaterniond* q_odom_sensor) {
  if (m.orientation_covariance[0] == -1.0) return false;
  const Eigen::Quaterniond q(m.orientation.w, m.orientation.x, m.orientation.y, m.orientation.z);
  if (!q.coeffs().allFinite() || std::abs(q.norm() - 1.0) > 0.01) return false;
  *q_odom_sensor = orientationToEnuFlu(q.normalized(), convention);
  return true;
}

double sigmaFromVariance(double variance) {
  return std::isfinite(variance) && variance > 0.0 ? std::sqrt(variance) : 0.0;
}

}  // namespace

TimeUs stampUs(const ros::Time& t) {
  return static_cast<TimeUs>(t.sec) * 1'000'000 + static_cast<TimeUs>(t.nanosec / 1000);
}

bool imuSampleFromRos(const ros::Imu& m, const TopicMapping& map, TimeUs t_us, ImuSample* out) {
  // REP-145: covariance[0] = -1 says the field is not provided (an orientation-only AHRS message).
  if (m.angular_velocity_covariance[0] == -1.0 || m.linear_acceleration_covariance[0] == -1.0) return false;
  ImuSample s;
  s.t_us = t_us;
  s.w_imu_radps = bodyVectorToFlu(toEigen(m.angular_velocity), map.convention);
  s.f_imu_mps2 = bodyVectorToFlu(toEigen(m.linear_acceleration), map.convention);
  if (!s.w_imu_radps.allFinite() || !s.f_imu_mps2.allFinite()) return false;
  Eigen::Quaterniond q;
  if (orientationOf(m, map.convention, &q)) {
    s.has_orientation = true;
    s.q_odom_imu = q;
    s.orientation_sigma_rad = sigmaFromVariance(std::max(m.orientation_covariance[0], m.orientation_covariance[4]));
  }
  *out = s;
  return true;
}

bool attitudeSampleFromRos(const ros::Imu& m, const TopicMapping& map, const Eigen::Quaterniond& q_robot_sensor,
                           TimeUs t_us, AttitudeSample* out) {
  Eigen::Quaterniond q_odom_sensor;
  if (!orientationOf(m, map.convention, &q_odom_sensor)) return false;
  const Eigen::Matrix3d R = (q_odom_sensor * q_robot_sensor.conjugate()).toRotationMatrix();
  AttitudeSample s;
  s.t_us = t_us;
  s.roll_rad = std::atan2(R(2, 1), R(2, 2));
  s.pitch_rad = std::atan2(-R(2, 0), std::hypot(R(2, 1), R(2, 2)));
  s.sigma_rad = sigmaFromVariance(std::max(m.orientation_covariance[0], m.orientation_covariance[4]));
  *out = s;
  return true;
}

bool headingSampleFromRos(const ros::Imu& m, const TopicMapping& map, const Eigen::Quaterniond& q_robot_sensor,
                          TimeUs t_us, HeadingSample* out) {
  Eigen::Quaterniond q_odom_sensor;
  if (!orientationOf(m, map.convention, &q_odom_sensor)) return false;
  const Eigen::Matrix3d R = (q_odom_sensor * q_robot_sensor.conjugate()).toRotationMatrix();
  HeadingSample s;
  s.t_us = t_us;
  s.heading_rad = wrapTwoPi(std::numbers::pi / 2.0 - std::atan2(R(1, 0), R(0, 0)));
  s.is_true = map.heading_is_true;
  s.sigma_rad = sigmaFromVariance(m.orientation_covariance[8]);
  *out = s;
  return true;
}

bool dvlSampleFromRos(const ros::Vector3& v_mps, const std::array<double, 36>* covariance, const TopicMapping& map,
                      TimeUs t_us, DvlSample* out) {
  DvlSample s;
  s.t_us = t_us;
  s.v_dvl_mps = bodyVectorToFlu(toEigen(v_mps), map.convention);
  if (!s.v_dvl_mps.allFinite()) return false;
  s.valid = true;
  if (covariance != nullptr) {
    Eigen::Matrix3d C;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) C(r, c) = (*covariance)[static_cast<std::size_t>(r * 6 + c)];
    }
    const bool known = C.allFinite() && (C.diagonal().array() > 0.0).all();
    if (known) s.cov_v_dvl_mps2 = bodyCovarianceToFlu(0.5 * (C + C.transpose()), map.convention);
  }
  *out = s;
  return true;
}

bool depthSampleFromRos(const ros::FluidPressure& m, const TopicMapping& map, TimeUs t_us, DepthSample* out) {
  if (!std::isfinite(m.fluid_pressure)) return false;
  const double rho_g = map.water_density_kgpm3 * map.gravity_mps2;
  DepthSample s;
  s.t_us = t_us;
  s.pressure_pa = m.fluid_pressure;
  s.depth_m = (m.fluid_pressure - map.atmospheric_pa) / rho_g;
  s.sigma_m = sigmaFromVariance(m.variance) / rho_g;
  *out = s;
  return true;
}

bool compassHeadingFromRos(const ros::MagneticField& m, const TopicMapping& map,
                           const Eigen::Quaterniond& q_robot_sensor, const AttitudeSample& attitude, TimeUs t_us,
                           HeadingSample* out) {
  const Eigen::Vector3d m_sensor = bodyVectorToFlu(toEigen(m.magnetic_field), map.convention) - map.hard_iron_t;
  if (!m_sensor.allFinite()) return false;
  const Eigen::Vector3d m_robot = q_robot_sensor * m_sensor;
  const Eigen::Vector3d m_level = (Eigen::AngleAxisd(attitude.pitch_rad, Eigen::Vector3d::UnitY()) *
                                   Eigen::AngleAxisd(attitude.roll_rad, Eigen::Vector3d::UnitX())) *
                                  m_robot;
  // A horizontal field weaker than 1 % of the whole (near a magnetic pole, or a saturated sensor) gives no
  // heading.
  if (m_level.head<2>().norm() < 0.01 * m_level.norm()) return false;
  HeadingSample s;
  s.t_us = t_us;
  s.heading_rad = wrapTwoPi(std::atan2(m_level.y(), m_level.x()));
  s.is_true = false;
  *out = s;
  return true;
}

}  // namespace deepnav::foreign
