#include "board/config/board_config.h"

#include <fstream>

#include <yaml-cpp/yaml.h>

namespace deepnav {
namespace {

using P = ParamSpec<BoardConfig>;
constexpr double kBig = 1e9;

#define DEEPNAV_FIELD(expr) [](BoardConfig& c) -> void* { return &c.expr; }

const std::array kBoardParams = {
    P{"loop.rate_hz", ParamType::kInt, "Hz", 10, 1000, "100", "", "nav loop tick rate",
      DEEPNAV_FIELD(loop.rate_hz)},
    P{"loop.budget_us", ParamType::kInt, "us", 100, 100000, "2000", "",
      "time budget of one nav tick; a longer tick counts as an overrun", DEEPNAV_FIELD(loop.budget_us)},
    P{"loop.output_rate_hz", ParamType::kInt, "Hz", 1, 1000, "50", "",
      "rate at which NavSolution is published to the outputs", DEEPNAV_FIELD(loop.output_rate_hz)},
    P{"loop.vision_budget_us", ParamType::kInt, "us", 1000, 5000000, "100000", "",
      "vision worker budget per stereo pair; longer counts as a vision overrun",
      DEEPNAV_FIELD(loop.vision_budget_us)},
    P{"loop.vision_latency_ms", ParamType::kInt, "ms", 0, 500, "150", "",
      "replay: delay between a frame's capture and the arrival of its vision result",
      DEEPNAV_FIELD(loop.vision_latency_ms)},
    P{"loop.late_tick_tolerance", ParamType::kDouble, "period", 0.05, 10.0, "0.5", "",
      "a tick that starts later than this fraction of the period counts as late",
      DEEPNAV_FIELD(loop.late_tick_tolerance)},
    P{"buffers.imu", ParamType::kInt, "samples", 8, 65536, "512", "", "IMU ring capacity",
      DEEPNAV_FIELD(buffers.imu)},
    P{"buffers.dvl", ParamType::kInt, "samples", 4, 65536, "64", "", "DVL ring capacity",
      DEEPNAV_FIELD(buffers.dvl)},
    P{"buffers.heading", ParamType::kInt, "samples", 4, 65536, "64", "", "compass ring capacity",
      DEEPNAV_FIELD(buffers.heading)},
    P{"buffers.attitude", ParamType::kInt, "samples", 4, 65536, "64", "", "AHRS attitude ring capacity",
      DEEPNAV_FIELD(buffers.attitude)},
    P{"buffers.depth", ParamType::kInt, "samples", 4, 65536, "64", "", "depth ring capacity",
      DEEPNAV_FIELD(buffers.depth)},
    P{"buffers.frames", ParamType::kInt, "pairs", 2, 64, "6", "", "stereo frames in the preallocated pool",
      DEEPNAV_FIELD(buffers.frames)},
    P{"buffers.vision_results", ParamType::kInt, "results", 4, 4096, "32", "", "vision result ring capacity",
      DEEPNAV_FIELD(buffers.vision_results)},
    P{"buffers.record", ParamType::kInt, "records", 64, 1048576, "8192", "",
      "recorder queue between the loop and the MCAP writer thread", DEEPNAV_FIELD(buffers.record)},
    P{"recording.enabled", ParamType::kBool, "-", 0, 0, "true", "", "record every consumed sample and output",
      DEEPNAV_FIELD(recording.enabled)},
    P{"recording.compression", ParamType::kChoice, "-", 0, 0, "zstd", "zstd|lz4|none",
      "MCAP chunk compression", DEEPNAV_FIELD(recording.compression)},
    P{"recording.chunk_max_duration_s", ParamType::kDouble, "s", 0.01, 1.0, "1.0", "",
      "a chunk closes (and is flushed to disk) at least this often, bounding what a crash loses",
      DEEPNAV_FIELD(recording.chunk_max_duration_s)},
    P{"recording.chunk_size_kib", ParamType::kInt, "KiB", 16, 65536, "4096", "",
      "a chunk closes when its uncompressed size exceeds this", DEEPNAV_FIELD(recording.chunk_size_kib)},
    P{"recording.record_images", ParamType::kBool, "-", 0, 0, "true", "",
      "record stereo images (large) besides the navigation samples", DEEPNAV_FIELD(recording.record_images)},
    P{"camera.width_px", ParamType::kInt, "px", 16, 8192, "688", "", "image width of each camera",
      DEEPNAV_FIELD(camera.width_px)},
    P{"camera.height_px", ParamType::kInt, "px", 16, 8192, "516", "", "image height of each camera",
      DEEPNAV_FIELD(camera.height_px)},
    P{"camera.channels", ParamType::kInt, "-", 1, 3, "1", "", "1 = grey, 3 = colour (BGR)",
      DEEPNAV_FIELD(camera.channels)},
    P{"camera.rate_hz", ParamType::kDouble, "Hz", 0.1, 100, "10", "", "stereo pair rate",
      DEEPNAV_FIELD(camera.rate_hz)},
};

#undef DEEPNAV_FIELD

}  // namespace

BoardConfig defaultBoardConfig() {
  BoardConfig config{};
  std::string error;
  applyDefaults(bindParams(kBoardParams, config), &error);
  return config;
}

bool loadBoardConfig(const std::string& path, BoardConfig* config, std::string* error) {
  *config = defaultBoardConfig();
  std::ifstream in(path);
  if (!in) {
    if (error) *error = path + ": cannot open the board file";
    return false;
  }
  YAML::Node root;
  try {
    root = YAML::Load(in);
  } catch (const YAML::Exception& e) {
    if (error) *error = path + ": not valid YAML (line " + std::to_string(e.mark.line + 1) + "): " + e.msg;
    return false;
  }
  return applyParams(bindParams(kBoardParams, *config), root, path, error);
}

std::string describeBoardParams() {
  BoardConfig config{};
  return describeParams(bindParams(kBoardParams, config));
}

}  // namespace deepnav
