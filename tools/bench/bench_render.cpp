// Stereo renderer speed: one 688 x 516 pair (both images, ground truth included) on one core.
// Target: <= 50 ms per pair at the dive's dwell in front of a face (the panel fills the view) and during
// the approach (seabed and water); grey (the sim board) and BGR.
#include <benchmark/benchmark.h>

#include <string>

#include "tools/sim/render/stereo_renderer.h"
#include "tools/sim/render/view_tick.h"
#include "tools/sim/sensor_simulator.h"

namespace {

using deepnav::sim::Scenario;
using deepnav::sim::SensorSimulator;
using deepnav::sim::StereoRenderer;

void renderTick(benchmark::State& state, const Scenario& scenario, const deepnav::CameraTick& tick, int channels,
                bool second_thread = false) {
  std::string error;
  StereoRenderer renderer;
  if (!renderer.init(scenario, 1, channels, &error)) {
    state.SkipWithError(error.c_str());
    return;
  }
  if (second_thread) renderer.useSecondThread();
  deepnav::StereoFrame frame;
  deepnav::allocateStereoFrame(frame, scenario.camera.width_px, scenario.camera.height_px, channels);
  deepnav::sim::RenderTruth truth;
  renderer.allocateTruth(&truth);
  for (auto _ : state) {
    renderer.render(tick, &frame, &truth);
    benchmark::DoNotOptimize(frame.left.data);
  }
}

// The deep-sea terms as tools/sim/scenarios/murky-snow-plume.yaml sets them: murky water, lamp backscatter
// with 45 deg beams, marine snow (500 per m^3) in a 5 cm/s current, a plume raised at the valves face at
// 26 s, forward-scatter blur.
void deepSea(Scenario* s) {
  s->water.preset = deepnav::sim::WaterPreset::kMurky;
  s->water.lamp_beam_half_angle_deg = 45.0;
  s->water.lamp_backscatter = true;
  s->water.current_mps = {0.05, 0.0, 0.0};
  s->water.snow_density_per_m3 = 500.0;
  s->water.forward_scatter_mrad_per_m = 5.0;
  deepnav::sim::SedimentPlumeConfig plume;
  plume.t_start_s = 26.0;
  plume.centre_in_odom_m = {-0.2, 1.7};
  plume.radius_m = 0.8;
  plume.height_m = 0.6;
  s->water.plumes = {plume};
}

void renderPair(benchmark::State& state, double t_s, int channels, int fish, bool deep_sea = false) {
  Scenario scenario;
  scenario.water.fish_count = fish;
  if (deep_sea) deepSea(&scenario);
  std::string error;
  SensorSimulator sim;
  StereoRenderer renderer;
  if (!sim.init(scenario, 1, &error) || !renderer.init(scenario, 1, channels, &error)) {
    state.SkipWithError(error.c_str());
    return;
  }
  deepnav::StereoFrame frame;
  deepnav::allocateStereoFrame(frame, scenario.camera.width_px, scenario.camera.height_px, channels);
  deepnav::sim::RenderTruth truth;
  renderer.allocateTruth(&truth);
  const deepnav::CameraTick tick = sim.cameraAt(static_cast<deepnav::TimeUs>(t_s * 1e6));
  for (auto _ : state) {
    renderer.render(tick, &frame, &truth);
    benchmark::DoNotOptimize(frame.left.data);
  }
}

// t = 36 s: dwell at the valves face; 57 s: around the front-left corner; 12 s: approach, 6 m out.
void BM_RenderDwellGrey(benchmark::State& s) { renderPair(s, 36.0, 1, 0); }
void BM_RenderCornerGrey(benchmark::State& s) { renderPair(s, 57.0, 1, 0); }
void BM_RenderApproachGrey(benchmark::State& s) { renderPair(s, 12.0, 1, 0); }
void BM_RenderDwellBgr(benchmark::State& s) { renderPair(s, 36.0, 3, 0); }
void BM_RenderCornerGreyWithFish(benchmark::State& s) { renderPair(s, 57.0, 1, 8); }
// The same dive poses with every deep-sea term on (murky-snow-plume.yaml).
void BM_RenderDwellGreyDeepSea(benchmark::State& s) { renderPair(s, 36.0, 1, 0, true); }
void BM_RenderCornerGreyDeepSea(benchmark::State& s) { renderPair(s, 57.0, 1, 0, true); }
void BM_RenderApproachGreyDeepSea(benchmark::State& s) { renderPair(s, 12.0, 1, 0, true); }
void BM_RenderDwellBgrDeepSea(benchmark::State& s) { renderPair(s, 36.0, 3, 0, true); }

// The worst case for the seabed march: 3 m from the front face, pitched 35 deg down, mostly seabed.
void BM_RenderSeabedGrey(benchmark::State& s) {
  const Scenario scenario;
  renderTick(s, scenario, deepnav::sim::tickFacingFace(scenario, 1, 3.0, -0.15, 1.3, 0.0, 35.0), 1);
}

// The same view with the right camera on a second thread (StereoRenderer::useSecondThread, as
// deepnav-sim renders): wall time per pair on the 2 cores.
void BM_RenderSeabedGreyTwoThreads(benchmark::State& s) {
  const Scenario scenario;
  renderTick(s, scenario, deepnav::sim::tickFacingFace(scenario, 1, 3.0, -0.15, 1.3, 0.0, 35.0), 1, true);
}

void BM_RendererInit(benchmark::State& state) {
  const Scenario scenario;
  std::string error;
  for (auto _ : state) {
    StereoRenderer renderer;
    benchmark::DoNotOptimize(renderer.init(scenario, 1, 1, &error));
  }
}

BENCHMARK(BM_RenderDwellGrey)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderCornerGrey)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderApproachGrey)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderDwellBgr)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderCornerGreyWithFish)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderDwellGreyDeepSea)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderCornerGreyDeepSea)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderApproachGreyDeepSea)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderDwellBgrDeepSea)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderSeabedGrey)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderSeabedGreyTwoThreads)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RendererInit)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
