// Heap allocations of the vision worker per stereo pair in its steady state (issue 20, item 6), counted
// the way loop_alloc_test counts the nav thread's: rendered murky sea-trial pairs go through
// VisionPipeline::process (the call the worker makes per pair) with the sea board's configuration and
// both VOs on every pair (vision.vo_mode=all), after a warm-up in each stage. The pipeline's per-stage
// test hook (run at the start of every stage) splits the count per part; ELAS with its cloud, the plane
// VO and the stage-1 map are also counted alone on the same pairs. Our own parts that allocate nothing
// are asserted to stay so; the counts of the parts that allocate inside OpenCV are printed
// (docs/benchmarks.md, "Heap allocations in the vision worker").
#include <algorithm>
#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "board/config/board_overrides.h"
#include "board/config/vehicle_setup.h"
#include "tests/support/alloc_counter.h"
#include "tests/support/source_paths.h"
#include "tools/sim/render/stereo_renderer.h"
#include "tools/sim/scenario_loader.h"
#include "tools/sim/sensor_simulator.h"
#include "vision/cloud/area_halving.h"
#include "vision/pipeline/vision_pipeline.h"

namespace deepnav {
namespace {

constexpr std::size_t kStages = static_cast<std::size_t>(VisionStage::kCount);
constexpr std::size_t kGlue = kStages;  // before the first stage: the result reset and the frame check

// Per-part attribution: the hook closes the running part at every stage start (a plain function pointer,
// so the state is file-static; the test is single-threaded).
struct PartCounts {
  std::array<long, kStages + 1> allocations{};
};
PartCounts g_parts;
std::size_t g_running = kGlue;
long g_mark = 0;

void closeRunningPart() {
  const long now = g_allocations.load();
  g_parts.allocations[g_running] += now - g_mark;
  g_mark = now;
}

void onStage(VisionStage stage) {
  closeRunningPart();
  g_running = static_cast<std::size_t>(stage);
}

Eigen::Isometry3d leftCameraInOdom(const CameraTick& tick) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = tick.q_odom_left_cam.toRotationMatrix();
  T.translation() = tick.p_left_cam_in_odom_m;
  return T;
}

struct RenderedPair {
  StereoFrame frame;
  Eigen::Isometry3d T_odom_cam;
};

class VisionWorkerAlloc : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::string error;
    sim::Scenario scenario;
    ASSERT_TRUE(sim::loadScenario(deepnav::testing::sourceDir() + "/tools/sim/scenarios/sea-trial-murky.yaml",
                                  &scenario, &error))
        << error;
    ASSERT_TRUE(loadVehicleSetup(deepnav::testing::sourceDir() + "/board/sim-sea/board.yaml", &setup_, &error))
        << error;
    ASSERT_TRUE(applyBoardOverrides({"vision.vo_mode=all"}, &setup_, &error)) << error;
    sim::SensorSimulator simulator;
    sim::StereoRenderer renderer;
    ASSERT_TRUE(simulator.init(scenario, 7, &error)) << error;
    ASSERT_TRUE(renderer.init(scenario, 7, setup_.config.camera.channels, &error)) << error;
    sim::RenderTruth truth;
    renderer.allocateTruth(&truth);
    // 40 s into the dive: the end of the approach, the valves face 1.5-2 m ahead in murky water; 10 Hz.
    pairs_ = new std::vector<RenderedPair>(kPairs);
    for (int i = 0; i < kPairs; ++i) {
      const CameraTick tick = simulator.cameraAt(40 * kUsPerS + i * 100000);
      RenderedPair& p = (*pairs_)[static_cast<std::size_t>(i)];
      ASSERT_TRUE(allocateStereoFrame(p.frame, scenario.camera.width_px, scenario.camera.height_px,
                                      setup_.config.camera.channels));
      ASSERT_TRUE(renderer.render(tick, &p.frame, &truth));
      p.frame.rectified = true;  // the sim board names no calibration: the pairs are taken as rectified
      p.T_odom_cam = leftCameraInOdom(tick);
    }
  }
  static void TearDownTestSuite() {
    delete pairs_;
    pairs_ = nullptr;
  }

  static VisionContext contextOf(const RenderedPair& p, NavStage stage) {
    VisionContext c;
    c.stage = stage;
    c.has_pose = true;
    c.T_odom_cam = p.T_odom_cam;
    return c;
  }

  static constexpr int kPairs = 60;
  static constexpr int kStage1Pairs = 30;  // then stage 2
  static constexpr int kWarmupPairs = 10;  // of each stage
  static VehicleSetup setup_;
  static std::vector<RenderedPair>* pairs_;
};

VehicleSetup VisionWorkerAlloc::setup_;
std::vector<RenderedPair>* VisionWorkerAlloc::pairs_ = nullptr;

struct StageRun {
  PartCounts parts;
  long pairs = 0;
  long max_per_pair = 0;
};

void printRun(const char* title, const StageRun& run) {
  std::printf("%s: %ld steady pairs, at most %ld allocations in one pair; per pair by part:\n", title, run.pairs,
              run.max_per_pair);
  for (std::size_t s = 0; s <= kStages; ++s) {
    const char* name = s == kGlue ? "pipeline glue" : visionStageName(static_cast<VisionStage>(s));
    const double per_pair = static_cast<double>(run.parts.allocations[s]) / static_cast<double>(run.pairs);
    std::printf("  %-14s %8.1f\n", name, per_pair);
  }
}

TEST_F(VisionWorkerAlloc, SteadyStateAllocationsPerPart) {
  ASSERT_NE(pairs_, nullptr);
  VisionPipelineConfig config = visionConfig(setup_);
  ASSERT_EQ(config.modality.mode, VoMode::kAll);
  config.stage_probe_for_test = onStage;
  VisionPipeline vision;
  std::string error;
  ASSERT_TRUE(vision.init(config, &error)) << error;
  VisionResult result;
  // WHEN the murky pairs run through the pipeline, stage 1 (the map being built) then stage 2, each warmed up
  StageRun stage1, stage2;
  int planes_pairs = 0, orb_pairs = 0, map_pairs = 0;
  for (int i = 0; i < kPairs; ++i) {
    const bool first_stage = i < kStage1Pairs;
    const RenderedPair& p = (*pairs_)[static_cast<std::size_t>(i)];
    const VisionContext context = contextOf(p, first_stage ? NavStage::kWorkspace : NavStage::kOptimised);
    const bool counted = (first_stage ? i : i - kStage1Pairs) >= kWarmupPairs;
    StageRun& run = first_stage ? stage1 : stage2;
    g_parts = PartCounts{};
    g_running = kGlue;
    long in_pair = 0;
    {
      Counting counting;
      g_mark = g_allocations.load();
      vision.process(p.frame, context, &result);
      closeRunningPart();
      in_pair = counting.count();
    }
    ASSERT_TRUE(result.frame_ok) << "pair " << i;
    ASSERT_EQ(vision.failedPairs(), 0u) << vision.lastFailure().what;
    if (!counted) continue;
    ++run.pairs;
    run.max_per_pair = std::max(run.max_per_pair, in_pair);
    for (std::size_t s = 0; s <= kStages; ++s) run.parts.allocations[s] += g_parts.allocations[s];
    map_pairs += result.map_us > 0 || (first_stage && result.map_frames > 0);
    orb_pairs += result.orb_tracked > 0;
    planes_pairs += !first_stage && result.planes > 0;
  }
  printRun("stage 1 (workspace map)", stage1);
  printRun("stage 2 (adaptive VO, vo_mode=all)", stage2);
  // THEN the pipeline did its work on these pairs (the counts below are of real work)
  EXPECT_GT(orb_pairs, 0);
  EXPECT_GT(planes_pairs, 0);
  EXPECT_GT(result.map_frames, 0);
  // AND our own parts allocate nothing per pair: the glue, the frame check and MDM, the markers
  const auto per = [](const StageRun& r, VisionStage s) { return r.parts.allocations[static_cast<std::size_t>(s)]; };
  for (const StageRun* run : {&stage1, &stage2}) {
    EXPECT_EQ(run->parts.allocations[kGlue], 0);
    EXPECT_EQ(per(*run, VisionStage::kRectify), 0);
    EXPECT_EQ(per(*run, VisionStage::kQuality), 0);
  }
}

// ELAS with its cloud (the dense part of the map and of the plane VO), the plane VO (extraction and
// registration) and the stage-1 map (insertion, then the stage-2 filter), each alone on the same murky
// pairs with the buffers of their init(). ELAS with its cloud allocates nothing per pair.
TEST_F(VisionWorkerAlloc, DenseStereoPlanesAndMapAllocationsPerPair) {
  ASSERT_NE(pairs_, nullptr);
  VisionPipelineConfig config = visionConfig(setup_);
  VisionPipeline vision;  // its StereoCloud, initialised as the worker's is
  std::string error;
  ASSERT_TRUE(vision.init(config, &error)) << error;
  StereoCloud& dense = vision.dense();
  OrganizedCloud cloud;
  ASSERT_TRUE(dense.allocateCloud(&cloud));
  PlaneOdometry plane_vo;
  ASSERT_TRUE(plane_vo.init(config.planes, dense.geometry(), dense.rows(), dense.cols(), config.dense.cloud_step_px,
                            &error))
      << error;
  WorkspaceModel map;
  ASSERT_TRUE(map.init(config.workspace, &error)) << error;
  PlaneOdometryOutput out;
  long dense_allocations = 0, plane_allocations = 0, insert_allocations = 0, filter_allocations = 0;
  int counted = 0, with_planes = 0, with_vo = 0, inserted = 0, filtered = 0;
  for (int i = 0; i < kPairs; ++i) {
    const RenderedPair& p = (*pairs_)[static_cast<std::size_t>(i)];
    const bool first_stage = i < kStage1Pairs;
    long d = 0, q = 0, m = 0;
    bool vo = false;
    {
      Counting counting;
      ASSERT_TRUE(dense.compute(p.frame.left, p.frame.right, &cloud));
      d = counting.count();
      if (first_stage && i % config.workspace.insert_every_n_frames == 0) {
        ASSERT_TRUE(map.insert(cloud, p.T_odom_cam));
      } else if (!first_stage) {
        ASSERT_GE(map.filter(p.T_odom_cam, false, Eigen::Isometry3d::Identity(), &cloud), 0);
      }
      m = counting.count() - d;
      vo = plane_vo.process(p.frame.t_us, cloud, &out);
      q = counting.count() - d - m;
    }
    if ((first_stage ? i : i - kStage1Pairs) < kWarmupPairs) continue;  // each stage warms up
    ++counted;
    dense_allocations += d;
    plane_allocations += q;
    if (first_stage && i % config.workspace.insert_every_n_frames == 0) {
      insert_allocations += m;
      ++inserted;
    } else if (!first_stage) {
      filter_allocations += m;
      ++filtered;
    }
    with_planes += out.planes > 0;
    with_vo += vo;
  }
  const auto per = [](long n, int pairs) { return pairs ? static_cast<double>(n) / pairs : 0.0; };
  std::printf("ELAS + cloud: %.2f allocations per pair; plane VO: %.2f (%d pairs, %d with planes, %d with VO)\n",
              per(dense_allocations, counted), per(plane_allocations, counted), counted, with_planes, with_vo);
  std::printf("map: %.2f allocations per insertion (%d), %.2f per stage-2 filter (%d)\n",
              per(insert_allocations, inserted), inserted, per(filter_allocations, filtered), filtered);
  EXPECT_GT(with_planes, 0);
  EXPECT_GT(inserted, 0);
  EXPECT_EQ(dense_allocations, 0);
}

// vision.planes_growing=tiles (PlaneTileGrower, the default): on the same murky stage-2 clouds the plane VO
// finds planes and registers about as often as with the pixel grower, and allocates nothing per pair either.
TEST_F(VisionWorkerAlloc, TileGrowingPlaneVoFindsPlanesWithoutAllocating) {
  ASSERT_NE(pairs_, nullptr);
  VisionPipelineConfig config = visionConfig(setup_);
  VisionPipeline vision;
  std::string error;
  ASSERT_TRUE(vision.init(config, &error)) << error;
  StereoCloud& dense = vision.dense();
  OrganizedCloud cloud;
  ASSERT_TRUE(dense.allocateCloud(&cloud));
  std::array<PlaneOdometry, 2> plane_vo;  // pixels, tiles
  for (int m = 0; m < 2; ++m) {
    PlaneOdometryConfig planes = config.planes;
    planes.extraction.growing = m == 0 ? PlaneGrowingMethod::kPixels : PlaneGrowingMethod::kTiles;
    ASSERT_TRUE(plane_vo[m].init(planes, dense.geometry(), dense.rows(), dense.cols(), config.dense.cloud_step_px,
                                 &error))
        << error;
  }
  std::array<int, 2> with_planes{}, with_vo{};
  long tile_allocations = 0;
  int counted = 0;
  PlaneOdometryOutput out;
  for (int i = kStage1Pairs; i < kPairs; ++i) {
    const RenderedPair& p = (*pairs_)[static_cast<std::size_t>(i)];
    ASSERT_TRUE(dense.compute(p.frame.left, p.frame.right, &cloud));
    const bool counted_pair = i - kStage1Pairs >= kWarmupPairs;
    for (int m = 0; m < 2; ++m) {
      long n = 0;
      bool vo = false;
      {
        Counting counting;
        vo = plane_vo[m].process(p.frame.t_us, cloud, &out);
        n = counting.count();
      }
      if (!counted_pair) continue;
      if (m == 1) tile_allocations += n;
      with_planes[m] += out.planes > 0;
      with_vo[m] += vo;
    }
    counted += counted_pair;
  }
  std::printf("pixels: %d pairs with planes, %d with VO; tiles: %d with planes, %d with VO, %.2f allocations per pair "
              "(%d pairs)\n",
              with_planes[0], with_vo[0], with_planes[1], with_vo[1],
              counted ? static_cast<double>(tile_allocations) / counted : 0.0, counted);
  EXPECT_GT(with_planes[1], 0);
  EXPECT_GE(with_vo[1], with_vo[0] / 2);
  EXPECT_EQ(tile_allocations, 0);
}

// The dense part's halving (vision/cloud/area_halving.h) gives cv::resize's INTER_AREA values bit for bit,
// on the murky pairs and on noise, grey and colour.
TEST_F(VisionWorkerAlloc, HalvingEqualsOpenCvAreaResize) {
  ASSERT_NE(pairs_, nullptr);
  cv::Mat noise_grey(516, 688, CV_8UC1), noise_bgr(516, 688, CV_8UC3);
  cv::randu(noise_grey, 0, 256);
  cv::randu(noise_bgr, 0, 256);
  const std::array<const cv::Mat*, 4> images = {&(*pairs_)[0].frame.left, &(*pairs_)[kPairs - 1].frame.right,
                                                &noise_grey, &noise_bgr};
  for (const cv::Mat* full : images) {
    cv::Mat ours(full->rows / 2, full->cols / 2, full->type()), opencv;
    ASSERT_TRUE(halveByArea(*full, &ours));
    cv::resize(*full, opencv, ours.size(), 0.0, 0.0, cv::INTER_AREA);
    EXPECT_EQ(cv::norm(ours, opencv, cv::NORM_INF), 0.0) << full->channels() << " channel(s)";
  }
  cv::Mat odd(5, 8, CV_8UC1), wrong_size(2, 4, CV_8UC1);
  EXPECT_FALSE(halveByArea(odd, &wrong_size));
}

}  // namespace
}  // namespace deepnav
