#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "nav/types/time.h"

// What each topic of a foreign recording is to deepnav (parsed from the --topics YAML by
// board/config/topic_map_file.h; keys and meaning in docs/foreign-recordings.md).
namespace deepnav::foreign {

// The deepnav input a topic feeds. One sensor_msgs/Imu topic may feed several (imu, attitude, heading).
enum class ForeignSensor : std::uint8_t {
  kImu,          // sensor_msgs/Imu rates and specific force -> ImuSample
  kAttitude,     // sensor_msgs/Imu orientation -> AttitudeSample (roll, pitch of the robot)
  kHeading,      // sensor_msgs/Imu orientation -> HeadingSample (yaw of the robot as a heading)
  kDvl,          // geometry_msgs/TwistWithCovarianceStamped or TwistStamped -> DvlSample
  kDepth,        // sensor_msgs/FluidPressure -> DepthSample
  kCompass,      // sensor_msgs/MagneticField, tilt-compensated with the attitude topic -> HeadingSample
  kCameraLeft,   // sensor_msgs/Image or CompressedImage -> StereoFrame::left
  kCameraRight,  // -> StereoFrame::right
  kCount
};
inline constexpr unsigned sensorBit(ForeignSensor s) { return 1u << static_cast<unsigned>(s); }
std::string_view sensorName(ForeignSensor s);  // "imu", "attitude", ... as the map writes them

// Axes the topic's vectors and orientations are written in. kEnuFlu: REP-103 (world x east, y north, z
// up; body x forward, y left, z up), used as is. kNedFrd: world x north, y east, z down; body x forward,
// y right, z down; converted at the input boundary (frame_conventions.h).
enum class FrameConvention : std::uint8_t { kEnuFlu, kNedFrd };

// Which time a sample carries: the message's header.stamp (the sensor's time) or the recorder's log
// time (for drivers that leave the stamp empty).
enum class StampSource : std::uint8_t { kHeader, kLogTime };

struct TopicMapping {
  std::string topic;
  unsigned sensors = 0;  // sensorBit() mask
  FrameConvention convention = FrameConvention::kEnuFlu;
  StampSource stamp = StampSource::kHeader;
  TimeUs stamp_tolerance_us = 0;  // how far a stamp may go back from the topic's latest before it is an error
  // Mounting of the sensor (its FLU frame after the convention) in the robot frame for the conversions
  // that need it (attitude, heading, compass); nullopt: the board's ekf.imu_rotation_deg.
  std::optional<Eigen::Quaterniond> q_robot_sensor;
  bool heading_is_true = false;            // heading: true north (else magnetic)
  double atmospheric_pa = 101325.0;        // depth = (p - atmospheric) / (rho g)
  double water_density_kgpm3 = 1025.0;
  double gravity_mps2 = 9.80665;
  Eigen::Vector3d hard_iron_t = Eigen::Vector3d::Zero();  // compass: offset subtracted (sensor FLU, tesla)
  TimeUs max_attitude_age_us = 100'000;    // compass: newest attitude at most this old, else skipped
  int mono16_bits = 16;                    // camera mono16: significant bits (12-bit cameras: 12)

  bool has(ForeignSensor s) const { return (sensors & sensorBit(s)) != 0; }
};

struct TopicMap {
  std::string name;  // the file, for messages
  std::vector<TopicMapping> topics;
  std::optional<TimeUs> pair_tolerance_us;  // stereo pairing; nullopt: the board's camera.pair_tolerance_ms

  const TopicMapping* find(std::string_view topic) const {
    for (const auto& t : topics) {
      if (t.topic == topic) return &t;
    }
    return nullptr;
  }
};

}  // namespace deepnav::foreign
