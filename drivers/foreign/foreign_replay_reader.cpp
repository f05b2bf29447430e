#include "drivers/foreign/foreign_replay_reader.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "drivers/foreign/decode_foreign.h"
#include "drivers/foreign/image_conversion.h"
#include "drivers/foreign/open_foreign_container.h"
#include "drivers/foreign/sample_conversion.h"

namespace deepnav::foreign {
namespace {

constexpr ForeignSensor kImuSensors[] = {ForeignSensor::kImu, ForeignSensor::kAttitude, ForeignSensor::kHeading};

std::string msText(TimeUs us) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.3f ms", static_cast<double>(us) / 1000.0);
  return buf;
}

// The ROS 2 names of the types a sensor reads, for messages.
const char* typesRead(ForeignSensor s) {
  switch (s) {
    case ForeignSensor::kImu:
    case ForeignSensor::kAttitude:
    case ForeignSensor::kHeading: return "sensor_msgs/msg/Imu";
    case ForeignSensor::kDvl: return "geometry_msgs/msg/TwistWithCovarianceStamped or geometry_msgs/msg/TwistStamped";
    case ForeignSensor::kDepth: return "sensor_msgs/msg/FluidPressure";
    case ForeignSensor::kCompass: return "sensor_msgs/msg/MagneticField";
    case ForeignSensor::kCameraLeft:
    case ForeignSensor::kCameraRight: return "sensor_msgs/msg/Image or sensor_msgs/msg/CompressedImage";
    case ForeignSensor::kCount: break;
  }
  return "?";
}

std::string withoutValueReason(ForeignSensor sensor) {
  switch (sensor) {
    case ForeignSensor::kImu:
      return " (rates or specific force not provided: their covariance[0] = -1, REP-145; or not finite)";
    case ForeignSensor::kAttitude:
    case ForeignSensor::kHeading:
      return " (no orientation: orientation_covariance[0] = -1, REP-145; or not a unit quaternion)";
    case ForeignSensor::kCompass:
      return " (no attitude within max_attitude_age_ms to level the field, or no horizontal field)";
    default:
      return " (a non-finite value)";
  }
}

}  // namespace

bool ForeignReplayReader::open(const std::string& path, const TopicMap& map, std::string* error) {
  path_ = path;
  map_ = map;
  topics_.clear();
  warnings_.clear();
  stats_ = ReplayReadStats{};
  pairing_ = StereoPairing(map_.pair_tolerance_us.value_or(vehicle_.pair_tolerance_us));
  have_attitude_ = false;
  container_ = openForeignContainer(path, error);
  if (!container_) return false;
  for (const TopicMapping& mapping : map_.topics) {
    if (!checkTopic(mapping, error)) return false;
  }
  return true;
}

bool ForeignReplayReader::checkTopic(const TopicMapping& mapping, std::string* error) {
  const ForeignTopic* found = nullptr;
  std::string held;
  for (const ForeignTopic& t : container_->topics()) {
    if (t.name == mapping.topic) found = &t;
    held += (held.empty() ? "" : ", ") + t.name + " (" + t.type + ")";
  }
  const std::string head = path_ + ": topic '" + mapping.topic + "' (in " + map_.name + ")";
  if (found == nullptr) {
    *error = head + " is not in the recording; it holds: " + (held.empty() ? "no topic" : held);
    return false;
  }
  if (!found->unsupported.empty()) {
    *error = head + " cannot be read: " + found->unsupported;
    return false;
  }
  const struct {
    MsgKind kind;
    const char* ros2_name;
  } kKinds[] = {{MsgKind::kImu, ros::Imu::kTypeName.data()},
                {MsgKind::kTwistWithCovariance, ros::TwistWithCovarianceStamped::kTypeName.data()},
                {MsgKind::kTwist, ros::TwistStamped::kTypeName.data()},
                {MsgKind::kPressure, ros::FluidPressure::kTypeName.data()},
                {MsgKind::kMagneticField, ros::MagneticField::kTypeName.data()},
                {MsgKind::kImage, ros::Image::kTypeName.data()},
                {MsgKind::kCompressedImage, ros::CompressedImage::kTypeName.data()}};
  TopicState state;
  state.map = &mapping;
  state.type = found->type;
  for (const auto& k : kKinds) {
    if (sameRosType(found->type, k.ros2_name)) state.kind = k.kind;
  }
  for (int i = 0; i < static_cast<int>(ForeignSensor::kCount); ++i) {
    const auto sensor = static_cast<ForeignSensor>(i);
    if (!mapping.has(sensor)) continue;
    bool reads = false;
    switch (sensor) {
      case ForeignSensor::kImu:
      case ForeignSensor::kAttitude:
      case ForeignSensor::kHeading: reads = state.kind == MsgKind::kImu; break;
      case ForeignSensor::kDvl: reads = state.kind == MsgKind::kTwistWithCovariance || state.kind == MsgKind::kTwist; break;
      case ForeignSensor::kDepth: reads = state.kind == MsgKind::kPressure; break;
      case ForeignSensor::kCompass: reads = state.kind == MsgKind::kMagneticField; break;
      case ForeignSensor::kCameraLeft:
      case ForeignSensor::kCameraRight: reads = state.kind == MsgKind::kImage || state.kind == MsgKind::kCompressedImage; break;
      case ForeignSensor::kCount: break;
    }
    if (!reads) {
      *error = head + " is " + (found->type.empty() ? std::string("of no type") : found->type) + "; sensor '" +
               std::string(sensorName(sensor)) + "' reads " + typesRead(sensor);
      return false;
    }
  }
  topics_[mapping.topic] = std::move(state);
  return true;
}

void ForeignReplayReader::setVehicle(const ForeignVehicle& vehicle) {
  vehicle_ = vehicle;
  pairing_ = StereoPairing(map_.pair_tolerance_us.value_or(vehicle.pair_tolerance_us));
}

const ForeignTopicCounts* ForeignReplayReader::counts(const std::string& topic) const {
  const auto it = topics_.find(topic);
  return it == topics_.end() ? nullptr : &it->second.counts;
}

std::string ForeignReplayReader::where(const TopicState& s) const {
  return path_ + ": topic '" + s.map->topic + "'";
}

bool ForeignReplayReader::forEach(bool, const Callback& callback, std::string* error) {
  bool stop = false;
  bool failed = false;
  const bool ok = container_->forEach(
      [&](const ForeignMessage& m) {
        if (!handle(m, callback, &stop, error)) failed = true;
        return !stop && !failed;
      },
      error);
  summarise();
  return ok && !failed;
}

bool ForeignReplayReader::handle(const ForeignMessage& m, const Callback& callback, bool* stop, std::string* error) {
  const auto it = topics_.find(std::string(m.topic));
  if (it == topics_.end()) {
    ++stats_.unknown_topic;
    return true;
  }
  TopicState& s = it->second;
  ++stats_.messages;
  ++s.counts.messages;
  switch (s.kind) {
    case MsgKind::kImu: return handleImu(s, m, callback, stop, error);
    case MsgKind::kTwistWithCovariance:
    case MsgKind::kTwist: return handleDvl(s, m, callback, stop, error);
    case MsgKind::kPressure: return handleDepth(s, m, callback, stop, error);
    case MsgKind::kMagneticField: return handleCompass(s, m, callback, stop, error);
    case MsgKind::kImage:
    case MsgKind::kCompressedImage: return handleImage(s, m, callback, stop, error);
    case MsgKind::kOther: break;
  }
  return true;
}

// Counted and skipped, as deepnav's own reader does with a damaged message; the first is named.
bool ForeignReplayReader::undecodable(TopicState& s) {
  if (s.counts.undecodable++ == 0) {
    warnings_.push_back(where(s) + ": message " + std::to_string(s.counts.messages) + " does not decode as " +
                        s.type + " (skipped, as any further ones)");
  }
  ++stats_.bad_messages;
  return true;
}

bool ForeignReplayReader::sampleTime(TopicState& s, const ForeignMessage& m, const ros::Time& stamp, TimeUs* t_us,
                                     std::string* error) {
  if (s.map->stamp == StampSource::kLogTime) {
    *t_us = static_cast<TimeUs>(m.log_time_ns / 1000);
  } else {
    if (stamp.sec == 0 && stamp.nanosec == 0) {
      *error = where(s) + ": header.stamp is 0 in message " + std::to_string(s.counts.messages) +
               " (a driver that does not stamp): set 'stamp: log_time' for this topic in " + map_.name;
      return false;
    }
    *t_us = stampUs(stamp);
  }
  if (s.any && *t_us < s.latest_us - s.map->stamp_tolerance_us) {
    *error = where(s) + ": stamps are not sorted: message " + std::to_string(s.counts.messages) + " goes back " +
             msText(s.latest_us - *t_us) + " (stamp_tolerance_ms allows " + msText(s.map->stamp_tolerance_us) + ")";
    return false;
  }
  s.latest_us = s.any ? std::max(s.latest_us, *t_us) : *t_us;
  s.any = true;
  return true;
}

bool ForeignReplayReader::emit(const InputSample& sample, const Callback& callback) {
  ReplayEvent e;
  e.kind = ReplayEvent::Kind::kInput;
  e.input = sample;
  e.t_us = sampleTimeUs(sample);
  return callback(e);
}

bool ForeignReplayReader::handleImu(TopicState& s, const ForeignMessage& m, const Callback& cb, bool* stop,
                                    std::string* error) {
  ros::Imu msg;
  if (!decodeForeign(m, &msg)) return undecodable(s);
  TimeUs t = 0;
  if (!sampleTime(s, m, msg.header.stamp, &t, error)) return false;
  const Eigen::Quaterniond q_robot = s.map->q_robot_sensor.value_or(vehicle_.q_robot_imu);
  for (const ForeignSensor sensor : kImuSensors) {
    if (!s.map->has(sensor) || *stop) continue;
    InputSample sample;
    bool made = false;
    if (sensor == ForeignSensor::kImu) {
      ImuSample v;
      made = imuSampleFromRos(msg, *s.map, t, &v);
      sample = v;
    } else if (sensor == ForeignSensor::kAttitude) {
      AttitudeSample v;
      made = attitudeSampleFromRos(msg, *s.map, q_robot, t, &v);
      if (made) {
        attitude_ = v;
        have_attitude_ = true;
      }
      sample = v;
    } else {
      HeadingSample v;
      made = headingSampleFromRos(msg, *s.map, q_robot, t, &v);
      sample = v;
    }
    if (!made) {
      ++s.counts.without_value[static_cast<std::size_t>(sensor)];
      continue;
    }
    ++s.counts.samples;
    if (!emit(sample, cb)) *stop = true;
  }
  return true;
}

bool ForeignReplayReader::handleDvl(TopicState& s, const ForeignMessage& m, const Callback& cb, bool* stop,
                                    std::string* error) {
  DvlSample v;
  TimeUs t = 0;
  bool made = false;
  if (s.kind == MsgKind::kTwistWithCovariance) {
    ros::TwistWithCovarianceStamped msg;
    if (!decodeForeign(m, &msg)) return undecodable(s);
    if (!sampleTime(s, m, msg.header.stamp, &t, error)) return false;
    made = dvlSampleFromRos(msg.twist.twist.linear, &msg.twist.covariance, *s.map, t, &v);
  } else {
    ros::TwistStamped msg;
    if (!decodeForeign(m, &msg)) return undecodable(s);
    if (!sampleTime(s, m, msg.header.stamp, &t, error)) return false;
    made = dvlSampleFromRos(msg.twist.linear, nullptr, *s.map, t, &v);
  }
  if (!made) {
    ++s.counts.without_value[static_cast<std::size_t>(ForeignSensor::kDvl)];
    return true;
  }
  ++s.counts.samples;
  if (!emit(v, cb)) *stop = true;
  return true;
}

bool ForeignReplayReader::handleDepth(TopicState& s, const ForeignMessage& m, const Callback& cb, bool* stop,
                                      std::string* error) {
  ros::FluidPressure msg;
  if (!decodeForeign(m, &msg)) return undecodable(s);
  TimeUs t = 0;
  if (!sampleTime(s, m, msg.header.stamp, &t, error)) return false;
  DepthSample v;
  if (!depthSampleFromRos(msg, *s.map, t, &v)) {
    ++s.counts.without_value[static_cast<std::size_t>(ForeignSensor::kDepth)];
    return true;
  }
  ++s.counts.samples;
  if (!emit(v, cb)) *stop = true;
  return true;
}

bool ForeignReplayReader::handleCompass(TopicState& s, const ForeignMessage& m, const Callback& cb, bool* stop,
                                        std::string* error) {
  ros::MagneticField msg;
  if (!decodeForeign(m, &msg)) return undecodable(s);
  TimeUs t = 0;
  if (!sampleTime(s, m, msg.header.stamp, &t, error)) return false;
  const TimeUs age = have_attitude_ ? std::llabs(t - attitude_.t_us) : 0;
  HeadingSample v;
  if (!have_attitude_ || age > s.map->max_attitude_age_us ||
      !compassHeadingFromRos(msg, *s.map, s.map->q_robot_sensor.value_or(vehicle_.q_robot_imu), attitude_, t, &v)) {
    ++s.counts.without_value[static_cast<std::size_t>(ForeignSensor::kCompass)];
    return true;
  }
  ++s.counts.samples;
  if (!emit(v, cb)) *stop = true;
  return true;
}

bool ForeignReplayReader::handleImage(TopicState& s, const ForeignMessage& m, const Callback& cb, bool* stop,
                                      std::string* error) {
  std::string why;
  TimeUs t = 0;
  bool converted = false;
  if (s.kind == MsgKind::kImage) {
    ros::Image msg;
    if (!decodeForeign(m, &msg)) return undecodable(s);
    if (!sampleTime(s, m, msg.header.stamp, &t, error)) return false;
    converted = imageFromRos(msg, vehicle_.channels, s.map->mono16_bits, &image_, &why);
  } else {
    ros::CompressedImage msg;
    if (!decodeForeign(m, &msg)) return undecodable(s);
    if (!sampleTime(s, m, msg.header.stamp, &t, error)) return false;
    converted = imageFromRos(msg, vehicle_.channels, s.map->mono16_bits, &image_, &why);
  }
  if (!converted) {
    *error = where(s) + ": message " + std::to_string(s.counts.messages) + ": " + why;
    return false;
  }
  if (image_.cols != vehicle_.width_px || image_.rows != vehicle_.height_px) {
    *error = where(s) + ": images are " + std::to_string(image_.cols) + "x" + std::to_string(image_.rows) +
             "; the board's camera is " + std::to_string(vehicle_.width_px) + "x" +
             std::to_string(vehicle_.height_px) + " (camera.width_px, camera.height_px)";
    return false;
  }
  ++s.counts.samples;
  if (!pairing_.add(s.map->has(ForeignSensor::kCameraLeft), t, &image_, &frame_)) return true;
  ReplayEvent e;
  e.kind = ReplayEvent::Kind::kFrame;
  e.t_us = frame_.t_us;
  e.frame = &frame_;
  if (!cb(e)) *stop = true;
  return true;
}

void ForeignReplayReader::summarise() {
  stats_.incomplete_frames = pairing_.unpaired();
  if (pairing_.unpaired() > 0) {
    warnings_.push_back(path_ + ": " + std::to_string(pairing_.unpaired()) +
                        " images found no partner within the stereo pairing tolerance (" +
                        std::to_string(pairing_.pairs()) + " pairs made)");
  }
  for (const TopicMapping& mapping : map_.topics) {
    const TopicState& s = topics_.at(mapping.topic);
    if (s.counts.messages == 0) {
      warnings_.push_back(where(s) + ": no message");
      continue;
    }
    for (int i = 0; i < static_cast<int>(ForeignSensor::kCount); ++i) {
      const std::uint64_t missed = s.counts.without_value[static_cast<std::size_t>(i)];
      if (missed == 0) continue;
      const auto sensor = static_cast<ForeignSensor>(i);
      warnings_.push_back(where(s) + ": no " + std::string(sensorName(sensor)) + " sample from " +
                          std::to_string(missed) + " of " + std::to_string(s.counts.messages) + " messages" +
                          withoutValueReason(sensor));
    }
  }
}

}  // namespace deepnav::foreign
