#include "board/config/topic_map_file.h"

#include <array>
#include <set>

#include <yaml-cpp/yaml.h>

#include "board/config/param_table.h"
#include "board/config/text_file.h"
#include "board/config/yaml_document.h"

namespace deepnav {
namespace {

using foreign::ForeignSensor;
using foreign::sensorBit;

// One topic entry as written, before it becomes a TopicMapping.
struct TopicEntry {
  std::string sensor;  // documented here, read by readSensors() (a name or a list of names)
  std::string convention;
  std::string stamp;
  double stamp_tolerance_ms = 0;
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  std::string north;
  double atmospheric_pa = 0;
  double water_density_kgpm3 = 0;
  double gravity_mps2 = 0;
  Eigen::Vector3d hard_iron_t = Eigen::Vector3d::Zero();
  double max_attitude_age_ms = 0;
  int mono16_bits = 0;
};

#define TOPIC_FIELD(expr) [](TopicEntry& e) -> void* { return &e.expr; }
using P = ParamSpec<TopicEntry>;
constexpr unsigned kImuLike = sensorBit(ForeignSensor::kImu) | sensorBit(ForeignSensor::kAttitude) |
                              sensorBit(ForeignSensor::kHeading);
constexpr unsigned kVectors = kImuLike | sensorBit(ForeignSensor::kDvl) | sensorBit(ForeignSensor::kCompass);
constexpr unsigned kCameras = sensorBit(ForeignSensor::kCameraLeft) | sensorBit(ForeignSensor::kCameraRight);
constexpr unsigned kAll = (1u << static_cast<unsigned>(ForeignSensor::kCount)) - 1;

const std::array kTopicParams = {
    P{"sensor", ParamType::kString, "-", 0, 0, "''", "",
      "required: what the topic feeds, a name or a list of names: imu, attitude, heading (sensor_msgs/Imu), dvl "
      "(TwistWithCovarianceStamped, TwistStamped), depth (FluidPressure), compass (MagneticField), camera_left, "
      "camera_right (Image, CompressedImage)",
      TOPIC_FIELD(sensor)},
    P{"convention", ParamType::kChoice, "-", 0, 0, "enu_flu", "enu_flu|ned_frd",
      "axes of the topic's vectors and orientation: enu_flu (REP-103) used as is; ned_frd converted at the input "
      "(body v_flu = diag(1,-1,-1) v_frd; world v_enu = [[0,1,0],[1,0,0],[0,0,-1]] v_ned)",
      TOPIC_FIELD(convention)},
    P{"stamp", ParamType::kChoice, "-", 0, 0, "header", "header|log_time",
      "the sample's time: header.stamp (sensor time) or the recorder's log time (drivers that leave the stamp 0)",
      TOPIC_FIELD(stamp)},
    P{"stamp_tolerance_ms", ParamType::kDouble, "ms", 0, 10000, "0", "",
      "how far a stamp may go back from the topic's latest before the replay stops with an error (unsorted)",
      TOPIC_FIELD(stamp_tolerance_ms)},
    P{"rotation_deg", ParamType::kRotation, "deg", -180, 180, "[0, 0, 0]", "",
      "mounting sensor (FLU after the convention) -> robot, [roll, pitch, yaw] ZYX; replaces the board's "
      "(imu: ekf.imu_rotation_deg, dvl: ekf.dvl_rotation_deg, camera_left: camera.rotation_deg); attitude, heading "
      "and compass topics without imu use it for their conversion only; absent: the board's",
      TOPIC_FIELD(rotation)},
    P{"position_m", ParamType::kVec3, "m", -10, 10, "[0, 0, 0]", "",
      "lever arm in the robot frame; replaces the board's (imu: ekf.p_imu_in_robot_m, dvl: ekf.p_dvl_in_robot_m, "
      "depth: ekf.p_depth_in_robot_m, camera_left: camera.p_cam_in_robot_m); absent: the board's",
      TOPIC_FIELD(position_m)},
    P{"north", ParamType::kChoice, "-", 0, 0, "magnetic", "magnetic|true",
      "heading: the AHRS's yaw is from magnetic north (the board's ekf.magnetic_declination_rad is added) or true",
      TOPIC_FIELD(north)},
    P{"atmospheric_pa", ParamType::kDouble, "Pa", 0, 200000, "101325", "",
      "depth: surface pressure, depth = (p - atmospheric_pa) / (water_density_kgpm3 gravity_mps2)",
      TOPIC_FIELD(atmospheric_pa)},
    P{"water_density_kgpm3", ParamType::kDouble, "kg/m^3", 990, 1100, "1025", "", "depth: water density",
      TOPIC_FIELD(water_density_kgpm3)},
    P{"gravity_mps2", ParamType::kDouble, "m/s^2", 9.7, 9.9, "9.80665", "", "depth: gravity of the depth model",
      TOPIC_FIELD(gravity_mps2)},
    P{"hard_iron_t", ParamType::kVec3, "T", -0.001, 0.001, "[0, 0, 0]", "",
      "compass: hard-iron offset subtracted from the field (sensor FLU); soft iron is not modelled (the EKF's "
      "compass deviation states take what is left)",
      TOPIC_FIELD(hard_iron_t)},
    P{"max_attitude_age_ms", ParamType::kDouble, "ms", 0, 1000, "100", "",
      "compass: the newest attitude sample must be this close in time to level the field, else the reading is "
      "skipped",
      TOPIC_FIELD(max_attitude_age_ms)},
    P{"mono16_bits", ParamType::kInt, "bits", 8, 16, "16", "",
      "camera mono16/16UC1 (or a 16-bit PNG): significant bits; 8-bit value = value >> (mono16_bits - 8), saturated",
      TOPIC_FIELD(mono16_bits)},
};

// The sensors each key applies to: writing it on another topic is an error, not a silent no-op.
unsigned keyApplies(const std::string& key) {
  if (key == "convention") return kVectors;
  if (key == "rotation_deg") return kVectors | sensorBit(ForeignSensor::kCameraLeft);
  if (key == "position_m") {
    return sensorBit(ForeignSensor::kImu) | sensorBit(ForeignSensor::kDvl) | sensorBit(ForeignSensor::kDepth) |
           sensorBit(ForeignSensor::kCameraLeft);
  }
  if (key == "north") return sensorBit(ForeignSensor::kHeading);
  if (key == "atmospheric_pa" || key == "water_density_kgpm3" || key == "gravity_mps2") {
    return sensorBit(ForeignSensor::kDepth);
  }
  if (key == "hard_iron_t" || key == "max_attitude_age_ms") return sensorBit(ForeignSensor::kCompass);
  if (key == "mono16_bits") return kCameras;
  return kAll;
}

std::string appliesText(unsigned mask) {
  std::string s;
  for (int i = 0; i < static_cast<int>(ForeignSensor::kCount); ++i) {
    if (mask & (1u << i)) s += (s.empty() ? "" : ", ") + std::string(sensorName(static_cast<ForeignSensor>(i)));
  }
  return s;
}

bool readSensors(const YAML::Node& node, const std::string& where, unsigned* mask, std::string* error) {
  const std::string allowed = appliesText(kAll);
  if (!node.IsDefined() || node.IsNull()) {
    *error = where + ": key 'sensor' is missing; allowed: " + allowed + " (or a list of them)";
    return false;
  }
  std::vector<std::string> names;
  if (node.IsScalar()) names.push_back(node.Scalar());
  if (node.IsSequence()) {
    for (const auto& n : node) names.push_back(n.IsScalar() ? n.Scalar() : std::string("?"));
  }
  if (names.empty()) {
    *error = where + ": key 'sensor' is empty; allowed: " + allowed + " (or a list of them)";
    return false;
  }
  *mask = 0;
  for (const std::string& name : names) {
    unsigned bit = 0;
    for (int i = 0; i < static_cast<int>(ForeignSensor::kCount); ++i) {
      if (sensorName(static_cast<ForeignSensor>(i)) == name) bit = 1u << i;
    }
    if (bit == 0 || (*mask & bit)) {
      *error = where + ": key 'sensor': '" + name + "' is " + (bit ? "repeated" : "not a sensor") +
               "; allowed: " + allowed;
      return false;
    }
    *mask |= bit;
  }
  // One message type per topic: only the three Imu readings share a topic.
  const bool imu_like = (*mask & ~kImuLike) == 0;
  if (!imu_like && (*mask & (*mask - 1)) != 0) {
    *error = where + ": key 'sensor': " + appliesText(*mask) +
             " cannot share a topic (only imu, attitude and heading read the same sensor_msgs/Imu)";
    return false;
  }
  return true;
}

std::string emit(const YAML::Node& n) {
  YAML::Emitter out;
  out << YAML::Flow << n;
  return out.c_str();
}

// The board keys a topic's mounting replaces.
void mountingOverrides(unsigned mask, const YAML::Node& entry, foreign::TopicMapping* m,
                       std::vector<std::pair<std::string, std::string>>* overrides) {
  const YAML::Node rotation = entry["rotation_deg"];
  const YAML::Node position = entry["position_m"];
  const auto add = [&](const char* key, const YAML::Node& n) {
    if (n.IsDefined()) overrides->push_back({key, emit(n)});
  };
  if (mask & sensorBit(ForeignSensor::kImu)) {
    add("ekf.imu_rotation_deg", rotation);
    add("ekf.p_imu_in_robot_m", position);
  } else if (mask & sensorBit(ForeignSensor::kDvl)) {
    add("ekf.dvl_rotation_deg", rotation);
    add("ekf.p_dvl_in_robot_m", position);
  } else if (mask & sensorBit(ForeignSensor::kDepth)) {
    add("ekf.p_depth_in_robot_m", position);
  } else if (mask & sensorBit(ForeignSensor::kCameraLeft)) {
    add("camera.rotation_deg", rotation);
    add("camera.p_cam_in_robot_m", position);
  }
  // Attitude, heading and compass topics convert with their mounting; an imu topic's is the board's
  // ekf.imu_rotation_deg (replaced above), which the reader reads from the setup.
  if (rotation.IsDefined() && !(mask & sensorBit(ForeignSensor::kImu)) && (mask & (kImuLike | sensorBit(ForeignSensor::kCompass)))) {
    m->q_robot_sensor = Eigen::Quaterniond::Identity();
  }
}

bool parseTopic(const std::string& topic, const YAML::Node& node, const std::string& name, foreign::TopicMapping* m,
                std::vector<std::pair<std::string, std::string>>* overrides, std::string* error) {
  const std::string where = name + ": topics." + topic;
  if (!node.IsMap()) {
    *error = where + ": expected a map of keys (sensor: ..., convention: ...)";
    return false;
  }
  m->topic = topic;
  if (!readSensors(node["sensor"], where, &m->sensors, error)) return false;
  for (const auto& kv : node) {
    const std::string key = kv.first.Scalar();
    const unsigned applies = keyApplies(key);
    std::string declared;
    bool known = false;
    for (const auto& p : kTopicParams) {
      declared += (declared.empty() ? "" : ", ") + std::string(p.key);
      known = known || key == p.key;
    }
    if (!known) {
      *error = where + ": unknown key '" + key + "'; allowed: " + declared;
      return false;
    }
    if ((applies & m->sensors) == 0) {
      *error = where + ": key '" + key + "' applies to " + appliesText(applies) + " topics only";
      return false;
    }
  }
  TopicEntry e;
  auto params = bindParams(kTopicParams, e);
  if (!applyDefaults(params, error)) return false;
  YAML::Node rest = YAML::Clone(node);
  rest.remove("sensor");
  if (!applyParams(params, rest, where, error)) return false;
  m->convention = e.convention == "ned_frd" ? foreign::FrameConvention::kNedFrd : foreign::FrameConvention::kEnuFlu;
  m->stamp = e.stamp == "log_time" ? foreign::StampSource::kLogTime : foreign::StampSource::kHeader;
  m->stamp_tolerance_us = static_cast<TimeUs>(e.stamp_tolerance_ms * 1000.0);
  m->heading_is_true = e.north == "true";
  m->atmospheric_pa = e.atmospheric_pa;
  m->water_density_kgpm3 = e.water_density_kgpm3;
  m->gravity_mps2 = e.gravity_mps2;
  m->hard_iron_t = e.hard_iron_t;
  m->max_attitude_age_us = static_cast<TimeUs>(e.max_attitude_age_ms * 1000.0);
  m->mono16_bits = e.mono16_bits;
  mountingOverrides(m->sensors, node, m, overrides);
  if (m->q_robot_sensor) m->q_robot_sensor = e.rotation;
  return true;
}

bool parseStereo(const YAML::Node& node, const std::string& name, foreign::TopicMap* map, std::string* error) {
  if (!node.IsDefined()) return true;
  struct Stereo {
    double pair_tolerance_ms = 0;
  } stereo;
  const std::array table = {ParamSpec<Stereo>{
      "pair_tolerance_ms", ParamType::kDouble, "ms", 0.001, 1000, "10", "",
      "largest stamp difference of a stereo pair's images", [](Stereo& s) -> void* { return &s.pair_tolerance_ms; }}};
  if (!node.IsMap()) {
    *error = name + ": stereo: expected a map (pair_tolerance_ms: ...)";
    return false;
  }
  if (!applyParams(bindParams(table, stereo), node, name + ": stereo", error)) return false;
  if (node["pair_tolerance_ms"].IsDefined()) map->pair_tolerance_us = static_cast<TimeUs>(stereo.pair_tolerance_ms * 1000.0);
  return true;
}

// Across topics: one camera of each side or none, one source per board mounting, a compass needs an attitude.
bool checkWhole(const TopicMapFile& f, const std::vector<std::pair<std::string, std::string>>& overrides,
                const std::string& name, std::string* error) {
  int left = 0, right = 0;
  bool attitude = false, compass = false;
  for (const auto& t : f.map.topics) {
    left += t.has(ForeignSensor::kCameraLeft);
    right += t.has(ForeignSensor::kCameraRight);
    attitude = attitude || t.has(ForeignSensor::kAttitude);
    compass = compass || t.has(ForeignSensor::kCompass);
  }
  if (left > 1 || right > 1 || left != right) {
    *error = name + ": topics: a stereo pair needs one camera_left and one camera_right topic (the map has " +
             std::to_string(left) + " and " + std::to_string(right) + ")";
    return false;
  }
  if (compass && !attitude) {
    *error = name +
             ": topics: a compass heading from a magnetometer needs the vehicle's roll and pitch to level the field "
             "(tilt compensation; at 20 deg of pitch an uncompensated heading is off by up to ~20 deg at mid "
             "latitudes): map a sensor_msgs/Imu orientation as 'attitude' too";
    return false;
  }
  std::set<std::string> keys;
  for (const auto& [key, value] : overrides) {
    if (!keys.insert(key).second) {
      *error = name + ": topics: two topics give the mounting " + key + "; one sensor, one mounting";
      return false;
    }
  }
  return true;
}

}  // namespace

bool parseTopicMapText(const std::string& text, const std::string& name, TopicMapFile* out, std::string* error) {
  YAML::Node root;
  if (!parseYamlDocument(text, name, &root, error)) return false;
  TopicMapFile f;
  f.text = text;
  f.map.name = name;
  if (!root.IsMap()) {
    *error = name + ": expected a map with 'topics' (and optionally 'stereo') at the top level";
    return false;
  }
  for (const auto& kv : root) {
    const std::string key = kv.first.Scalar();
    if (key != "topics" && key != "stereo") {
      *error = name + ": unknown key '" + key + "'; allowed: topics, stereo";
      return false;
    }
  }
  const YAML::Node topics = root["topics"];
  if (!topics.IsDefined() || !topics.IsMap() || topics.size() == 0) {
    *error = name + ": key 'topics' must map each foreign topic to its sensor (e.g. /imu/data: {sensor: imu})";
    return false;
  }
  std::vector<std::pair<std::string, std::string>> overrides;
  for (const auto& kv : topics) {
    foreign::TopicMapping m;
    if (!parseTopic(kv.first.Scalar(), kv.second, name, &m, &overrides, error)) return false;
    f.map.topics.push_back(std::move(m));
  }
  if (!parseStereo(root["stereo"], name, &f.map, error) || !checkWhole(f, overrides, name, error)) return false;
  for (const auto& [key, value] : overrides) f.board_overrides.push_back(key + "=" + value);
  *out = std::move(f);
  return true;
}

bool loadTopicMapFile(const std::string& path, TopicMapFile* out, std::string* error) {
  std::string text;
  return readTextFile(path, "the topic map", &text, error) && parseTopicMapText(text, path, out, error);
}

std::string describeTopicMapParams() {
  TopicEntry e;
  return describeParams(bindParams(kTopicParams, e));
}

}  // namespace deepnav
