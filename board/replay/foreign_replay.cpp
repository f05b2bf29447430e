#include "board/replay/foreign_replay.h"

#include "board/config/topic_map_file.h"
#include "drivers/foreign/foreign_replay_reader.h"

namespace deepnav {
namespace {

foreign::ForeignVehicle foreignVehicle(const VehicleSetup& setup) {
  const BoardConfig& c = setup.config;
  foreign::ForeignVehicle v;
  v.q_robot_imu = c.ekf.q_robot_imu;
  v.width_px = c.camera.width_px;
  v.height_px = c.camera.height_px;
  v.channels = c.camera.channels;
  v.pair_tolerance_us = static_cast<TimeUs>(c.camera.source.pair_tolerance_ms * 1000.0);
  return v;
}

}  // namespace

bool runForeignBenchReplay(const ReplayOptions& o, ReplaySummary* summary, std::string* error) {
  if (o.realtime) {
    *error = "--topics replays on the bench only (not --realtime): replay its output recording with --realtime";
    return false;
  }
  TopicMapFile map;
  if (!loadTopicMapFile(o.topics_path, &map, error)) return false;
  foreign::ForeignReplayReader reader;
  if (!reader.open(o.input_path, map.map, error)) return false;
  ReplayOptions with_map = o;
  with_map.overrides.insert(with_map.overrides.begin(), map.board_overrides.begin(), map.board_overrides.end());
  const ReplayPrepare prepare = [&reader](const VehicleSetup& setup, std::string*) {
    reader.setVehicle(foreignVehicle(setup));
    return true;
  };
  const ReplayMetadata metadata = {{"deepnav.foreign", {{"recording", o.input_path}, {"topic_map", map.text}}}};
  return runBenchReplayFrom(with_map, reader, prepare, metadata, summary, error);
}

}  // namespace deepnav
