#pragma once
#include <Eigen/Geometry>

#include "drivers/cdr/ros_msgs.h"
#include "drivers/foreign/topic_map.h"
#include "nav/types/attitude_sample.h"
#include "nav/types/depth_sample.h"
#include "nav/types/dvl_sample.h"
#include "nav/types/heading_sample.h"
#include "nav/types/imu_sample.h"

// ROS messages into the loop's samples, in deepnav's frames (ENU odometry, FLU sensors, REP-103), for a
// topic of the map. t_us is the sample time the caller chose (header stamp or log time). Each returns
// false when the message holds no usable value of that kind (e.g. an Imu without orientation asked
// for an attitude: orientation_covariance[0] = -1, REP-145).
namespace deepnav::foreign {

// Header stamp in microseconds (truncated toward zero).
TimeUs stampUs(const ros::Time& t);

// False when the rates or the specific force are not provided (REP-145: their covariance[0] = -1).
bool imuSampleFromRos(const ros::Imu& m, const TopicMapping& map, TimeUs t_us, ImuSample* out);

// The robot's attitude from the sensor's orientation: q_odom_robot = q_odom_sensor * q_robot_sensor^-1
// (mounting q_robot_sensor). Roll and pitch as the EKF's attitude update reads them from q_odom_robot;
// sigma from the larger of the roll and pitch variances when given.
bool attitudeSampleFromRos(const ros::Imu& m, const TopicMapping& map, const Eigen::Quaterniond& q_robot_sensor,
                           TimeUs t_us, AttitudeSample* out);

// The robot's heading from the same orientation: yaw = atan2(R10, R00) of q_odom_robot (ENU, from east,
// counter-clockwise), heading = pi/2 - yaw wrapped to [0, 2 pi); sigma from the yaw variance.
bool headingSampleFromRos(const ros::Imu& m, const TopicMapping& map, const Eigen::Quaterniond& q_robot_sensor,
                          TimeUs t_us, HeadingSample* out);

// A DVL's velocity over the bottom, in its own frame. covariance: the twist's 6x6 (row-major, linear
// first) or nullptr (TwistStamped); a non-finite or negative variance means unknown (the board's
// ekf.dvl_sigma_mps then applies). Beams and altitude are not in these messages (left zero).
bool dvlSampleFromRos(const ros::Vector3& v_mps, const std::array<double, 36>* covariance, const TopicMapping& map,
                      TimeUs t_us, DvlSample* out);

// depth = (p - atmospheric_pa) / (water_density g); sigma = sqrt(variance) / (rho g) when variance > 0.
bool depthSampleFromRos(const ros::FluidPressure& m, const TopicMapping& map, TimeUs t_us, DepthSample* out);

// Tilt-compensated magnetic heading: the field (less the hard-iron offset) rotated into the robot frame
// by the mounting, then levelled with the robot's roll and pitch, m_level = Ry(pitch) Rx(roll) m_robot;
// heading = atan2(m_level_y, m_level_x) clockwise from magnetic north (x forward, y left: FLU).
bool compassHeadingFromRos(const ros::MagneticField& m, const TopicMapping& map,
                           const Eigen::Quaterniond& q_robot_sensor, const AttitudeSample& attitude, TimeUs t_us,
                           HeadingSample* out);

}  // namespace deepnav::foreign
