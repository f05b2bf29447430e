#pragma once
#include <string>
#include <vector>

#include "drivers/foreign/topic_map.h"

namespace deepnav {

// A topic map file (`deepnav replay --topics map.yaml`, docs/foreign-recordings.md): which topic of a
// foreign recording feeds which deepnav sensor, in which frame convention, from which time, with which
// mounting. Mountings that the board declares (ekf.imu_rotation_deg, ekf.p_imu_in_robot_m,
// ekf.dvl_rotation_deg, ekf.p_dvl_in_robot_m, ekf.p_depth_in_robot_m, camera.rotation_deg,
// camera.p_cam_in_robot_m) become board overrides, so the board's own validation applies and the output
// recording stores the board that ran.
struct TopicMapFile {
  foreign::TopicMap map;
  std::vector<std::string> board_overrides;  // "key=value", applied before the command line's --set
  std::string text;                          // the file as read (kept in the output recording)
};

bool loadTopicMapFile(const std::string& path, TopicMapFile* out, std::string* error);
bool parseTopicMapText(const std::string& text, const std::string& name, TopicMapFile* out, std::string* error);

// A Markdown table of every key of a topic entry (docs/foreign-recordings.md, checked by a test).
std::string describeTopicMapParams();

}  // namespace deepnav
