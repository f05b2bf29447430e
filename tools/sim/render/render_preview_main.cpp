// deepnav-render-preview: renders the stereo pair of one instant of a scenario once per turbidity
// preset and writes each pair side by side (left | right) as <out-dir>/render_<preset>.png.
//   deepnav-render-preview [--scenario FILE] [--seed N] [--channels 1|3] [--out-dir DIR]
//                          [--time-s T | --face F --distance-m D [--pitch-deg P]]
// --time-s: the rig's pose in the dive at T; --face: the rig D metres in front of face F (0 valves,
// 1 grasping, 2 plain), cameras 1.3 m above the seabed, centred on the face, pitched down P degrees.
#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tools/sim/render/stereo_renderer.h"
#include "tools/sim/render/view_tick.h"
#include "tools/sim/scenario_loader.h"
#include "tools/sim/sensor_simulator.h"

namespace {

struct View {
  double time_s = 36.0;  // the dwell in front of the valves face
  int face = -1;         // >= 0: a fixed view of this face instead
  double distance_m = 1.5;
  double pitch_deg = 0.0;
};

bool renderPreset(deepnav::sim::Scenario scenario, deepnav::sim::WaterPreset preset, std::uint64_t seed,
                  const View& view, int channels, const std::string& out_dir) {
  using namespace deepnav::sim;
  scenario.water.preset = preset;
  std::string error;
  SensorSimulator sim;
  StereoRenderer renderer;
  if (!sim.init(scenario, seed, &error) || !renderer.init(scenario, seed, channels, &error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return false;
  }
  deepnav::StereoFrame frame;
  deepnav::allocateStereoFrame(frame, scenario.camera.width_px, scenario.camera.height_px, channels);
  RenderTruth truth;
  renderer.allocateTruth(&truth);
  const auto t_us = static_cast<deepnav::TimeUs>(view.time_s * 1e6);
  const deepnav::CameraTick tick =
      view.face >= 0 ? tickFacingFace(scenario, view.face, view.distance_m, -0.5 * scenario.camera.baseline_m, 1.3, 0.0,
                                      view.pitch_deg, t_us)
                     : sim.cameraAt(t_us);
  renderer.render(tick, &frame, &truth);
  cv::Mat pair;
  cv::hconcat(frame.left, frame.right, pair);
  const std::string path = out_dir + "/render_" + std::string(waterPresetName(preset)) + ".png";
  if (!cv::imwrite(path, pair, {cv::IMWRITE_PNG_COMPRESSION, 9})) {
    std::fprintf(stderr, "%s: cannot write\n", path.c_str());
    return false;
  }
  std::printf("%s: t = %.2f s, exposure gain %.2f, visible markers:", path.c_str(), view.time_s, renderer.lastGain());
  for (int id : truth.visible_marker_ids) std::printf(" %d", id);
  std::printf("\n");
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Render one stereo pair per turbidity preset (left | right PNGs)"};
  std::string scenario_path = std::string(DEEPNAV_SOURCE_DIR) + "/tools/sim/scenarios/default.yaml";
  std::string out_dir = std::string(DEEPNAV_SOURCE_DIR) + "/docs";
  std::uint64_t seed = 1;
  View view;
  int channels = 3;
  app.add_option("--scenario", scenario_path, "scenario YAML");
  app.add_option("--seed", seed, "seed");
  app.add_option("--time-s", view.time_s, "instant of the dive, s (default: the valves-face dwell)");
  app.add_option("--face", view.face, "fixed view of face 0 (valves), 1 (grasping) or 2 (plain)")->check(CLI::Range(0, 2));
  app.add_option("--distance-m", view.distance_m, "with --face: camera distance to the face, m");
  app.add_option("--pitch-deg", view.pitch_deg, "with --face: nose-down pitch, deg");
  app.add_option("--channels", channels, "1 (grey) or 3 (BGR)")->check(CLI::IsMember({1, 3}));
  app.add_option("--out-dir", out_dir, "where render_<preset>.png go");
  CLI11_PARSE(app, argc, argv);
  deepnav::sim::Scenario scenario;
  std::string error;
  if (!deepnav::sim::loadScenario(scenario_path, &scenario, &error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 2;
  }
  using deepnav::sim::WaterPreset;
  for (WaterPreset p : {WaterPreset::kClear, WaterPreset::kModerate, WaterPreset::kMurky}) {
    if (!renderPreset(scenario, p, seed, view, channels, out_dir)) return 1;
  }
  return 0;
}
