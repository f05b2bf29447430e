// After warm-up, the steady-state nav loop performs no heap allocation. Every allocation made on the
// test thread is counted by replacing operator new and, outside sanitizer builds, malloc itself.
#include <vector>

#include <gtest/gtest.h>

#include "board/config/vehicle_setup.h"
#include "board/loop/live_loop.h"
#include "tests/support/alloc_counter.h"
#include "tools/sim/scenario_loader.h"
#include "tools/sim/sensor_simulator.h"
#include "vision/pipeline/vision_pipeline.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

std::vector<sim::SimEvent> simulate(double duration_s) {
  sim::Scenario scenario;
  std::string error;
  EXPECT_TRUE(sim::loadScenario(deepnav::testing::sourceDir() + "/tools/sim/scenarios/default.yaml", &scenario,
                                &error))
      << error;
  scenario.duration_s = duration_s;
  sim::SensorSimulator simulator;
  EXPECT_TRUE(simulator.init(scenario, 3, &error)) << error;
  std::vector<sim::SimEvent> events;
  sim::SimEvent e;
  while (simulator.next(&e)) events.push_back(e);
  return events;
}

// The test thread plays the drivers (pushing into the rings) and the loop (runTick), tick by tick.
void pushDue(LiveInputs& in, const std::vector<sim::SimEvent>& events, std::size_t* next, TimeUs t_us) {
  for (; *next < events.size() && events[*next].t_us <= t_us; ++*next) {
    const auto& s = events[*next].sample;
    std::visit(
        [&in](const auto& v) {
          using T = std::decay_t<decltype(v)>;
          if constexpr (kHasLiveRing<T>) in.ring<T>().push(v);  // sensors only, not truth or camera ticks
        },
        s);
  }
}

TEST(LoopAllocations, SteadyStateLoopDoesNotAllocate) {
  // GIVEN the vehicle runtime initialised from the sim board, recording through its queued recorder
  const auto events = simulate(20.0);
  VehicleSetup setup;
  std::string error;
  ASSERT_TRUE(loadVehicleSetup(deepnav::testing::sourceDir() + "/board/sim/board.yaml", &setup, &error)) << error;
  LiveLoop loop;
  ASSERT_TRUE(loop.init(setup, ::testing::TempDir() + "alloc.mcap", &error)) << error;
  std::size_t next = 0;
  TimeUs t_us = 0;
  // WHEN 5 s of ticks warm it up (alignment, first fusions, history filling)
  for (; t_us <= 5 * kUsPerS; t_us += 10000) {
    pushDue(loop.inputs(), events, &next, t_us);
    loop.runTick(t_us);
  }
  // THEN the next 15 s of ticks, with every sensor fused and recorded, allocate nothing on the loop thread
  long allocations = 0;
  {
    Counting counting;
    for (; t_us <= 20 * kUsPerS; t_us += 10000) {
      pushDue(loop.inputs(), events, &next, t_us);
      loop.runTick(t_us);
    }
    allocations = counting.count();
  }
  EXPECT_EQ(allocations, 0);
  EXPECT_GT(loop.latest().t_us, 19 * kUsPerS);
  EXPECT_GT(loop.counters().accepted, 100u);
  ASSERT_TRUE(loop.stop(&error)) << error;
}

// The vision worker's own stages (frame check, MDM, modality bookkeeping) allocate nothing per pair. The
// ORB VO and dense stereo call OpenCV functions that allocate internally (solvePnPRansac, StereoSGBM:
// vision/orbvo/README.md); they run on the worker thread, never on the nav loop's.
TEST(LoopAllocations, VisionPipelineDoesNotAllocatePerFrame) {
  VisionPipeline vision;
  std::string error;
  VisionPipelineConfig config;
  config.run_orb = false;
  ASSERT_TRUE(vision.init(config, &error)) << error;
  const VisionContext stage1;
  StereoFrame frame;
  ASSERT_TRUE(allocateStereoFrame(frame, 688, 516, 1));
  cv::randu(frame.left, 0, 255);
  cv::randu(frame.right, 0, 255);
  VisionResult result;
  vision.process(frame, stage1, &result);
  long allocations = 0;
  {
    Counting counting;
    for (int i = 0; i < 10; ++i) vision.process(frame, stage1, &result);
    allocations = counting.count();
  }
  EXPECT_EQ(allocations, 0);
  EXPECT_TRUE(result.frame_ok);
}

TEST(LoopAllocations, TheCounterSeesAllocations) {
  // The hook is live: an allocation on the counted thread is seen (so a zero above means something).
  long allocations = 0;
  {
    Counting counting;
    std::vector<int> v(1000);
    v[0] = 1;
    allocations = counting.count();
  }
  EXPECT_GE(allocations, 1);
}

}  // namespace
}  // namespace deepnav
