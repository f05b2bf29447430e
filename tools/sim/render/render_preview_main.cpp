// deepnav-render-preview: renders the stereo pair of one instant of a scenario once per turbidity
// preset and writes each pair side by side (left | right) as <out-dir>/render_<preset>.png.
//   deepnav-render-preview [--scenario FILE] [--seed N] [--time-s T] [--channels 1|3] [--out-dir DIR]
#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tools/sim/render/stereo_renderer.h"
#include "tools/sim/scenario_loader.h"
#include "tools/sim/sensor_simulator.h"

namespace {

bool renderPreset(deepnav::sim::Scenario scenario, deepnav::sim::WaterPreset preset, std::uint64_t seed,
                  double time_s, int channels, const std::string& out_dir) {
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
  const auto t_us = static_cast<deepnav::TimeUs>(time_s * 1e6);
  renderer.render(sim.cameraAt(t_us), &frame, &truth);
  cv::Mat pair;
  cv::hconcat(frame.left, frame.right, pair);
  const std::string path = out_dir + "/render_" + std::string(waterPresetName(preset)) + ".png";
  if (!cv::imwrite(path, pair)) {
    std::fprintf(stderr, "%s: cannot write\n", path.c_str());
    return false;
  }
  std::printf("%s: t = %.2f s, visible markers:", path.c_str(), time_s);
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
  double time_s = 36.0;  // the dwell in front of the valves face
  int channels = 3;
  app.add_option("--scenario", scenario_path, "scenario YAML");
  app.add_option("--seed", seed, "seed");
  app.add_option("--time-s", time_s, "instant of the dive, s");
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
    if (!renderPreset(scenario, p, seed, time_s, channels, out_dir)) return 1;
  }
  return 0;
}
