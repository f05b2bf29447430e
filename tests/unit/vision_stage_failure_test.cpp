// A vision stage that throws (issue 21: OpenCV's StereoSGBM asserting on a disparity range as wide as the
// matched image aborted `deepnav replay` and `deepnav run`) fails its pair, not the process: the pair is
// counted, its result carries nothing to fuse, and the next pair is processed as usual. Such a range is
// also refused at start-up.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

#include "vision/pipeline/vision_pipeline.h"
#include "vision/stereo/sgbm_disparity.h"

namespace deepnav {
namespace {

constexpr int kWidth = 128, kHeight = 96;

// The failure itself: OpenCV's StereoSGBM given a range as wide as the matched image (64 px)
// in 3-way mode (as SgbmDisparity runs it) throws cv::Exception from compute() (buffer_area, count > 0). SgbmDisparity now refuses such a range
// at init() and the board check refuses such a board, so the test probe makes the workspace stage run
// the bare OpenCV matcher: a real library exception, raised inside the stage.
bool g_sgbm_in_workspace = false;
void openCvSgbmWithTooWideARange(VisionStage stage) {
  if (!g_sgbm_in_workspace || stage != VisionStage::kWorkspace) return;
  const cv::Mat left(48, 64, CV_8UC1, cv::Scalar(100)), right(48, 64, CV_8UC1, cv::Scalar(90));
  cv::Mat disparity;
  cv::StereoSGBM::create(0, 64, 5, 0, 0, 0, 0, 0, 0, 0, cv::StereoSGBM::MODE_SGBM_3WAY)
      ->compute(left, right, disparity);
}

VisionPipelineConfig throwingWorkspaceConfig() {
  VisionPipelineConfig c;
  c.width_px = kWidth;
  c.height_px = kHeight;
  c.rig.cx_px = 63.5;
  c.rig.cy_px = 47.5;
  c.run_orb = false;
  c.dense.method = DenseStereoMethod::kSgbm;
  c.dense.scale_down = 2;
  c.dense.num_disparities = 32;
  c.workspace.insert_every_n_frames = 1;
  c.stage_probe_for_test = &openCvSgbmWithTooWideARange;
  return c;
}

StereoFrame texturedPair(std::uint64_t sequence) {
  StereoFrame f;
  EXPECT_TRUE(allocateStereoFrame(f, kWidth, kHeight, 1));
  cv::RNG rng(static_cast<std::uint64_t>(7 + sequence));
  rng.fill(f.left, cv::RNG::UNIFORM, 0, 255);
  f.left(cv::Rect(4, 0, kWidth - 4, kHeight)).copyTo(f.right(cv::Rect(0, 0, kWidth - 4, kHeight)));
  f.rectified = true;
  f.sequence = sequence;
  f.t_us = static_cast<TimeUs>(sequence) * 100'000;
  return f;
}

VisionContext stage1Context() {
  VisionContext c;
  c.stage = NavStage::kWorkspace;
  c.has_pose = true;
  return c;
}

TEST(VisionStageFailure, AnOpenCvExceptionInAStageFailsThePairNotTheProcess) {
  // GIVEN a pipeline whose workspace stage throws inside OpenCV on every pair
  VisionPipeline pipeline;
  std::string error;
  ASSERT_TRUE(pipeline.init(throwingWorkspaceConfig(), &error)) << error;
  // WHEN three stage-1 pairs go through it
  VisionResult r;
  g_sgbm_in_workspace = true;
  for (std::uint64_t seq = 1; seq <= 3; ++seq) {
    pipeline.process(texturedPair(seq), stage1Context(), &r);
    // THEN each pair is skipped: nothing of it is fused, its time and sequence stay for the record
    EXPECT_FALSE(r.frame_ok);
    EXPECT_EQ(r.sequence, seq);
    EXPECT_EQ(r.t_us, static_cast<TimeUs>(seq) * 100'000);
    EXPECT_LT(r.image_quality, 0.0);
    EXPECT_EQ(r.map_frames, 0);
  }
  // AND counted against the stage that threw, with OpenCV's message
  EXPECT_EQ(pipeline.failedPairs(), 3u);
  EXPECT_EQ(pipeline.stageFailures(VisionStage::kWorkspace), 3u);
  EXPECT_EQ(pipeline.stageFailures(VisionStage::kOrb), 0u);
  EXPECT_EQ(pipeline.lastFailure().stage, VisionStage::kWorkspace);
  EXPECT_EQ(pipeline.lastFailure().sequence, 3u);
  EXPECT_NE(std::string(pipeline.lastFailure().what).find("OpenCV"), std::string::npos) << pipeline.lastFailure().what;
  EXPECT_STREQ(visionStageName(VisionStage::kWorkspace), "workspace map");
  // AND once the stage no longer throws, the next pair is processed as usual
  g_sgbm_in_workspace = false;
  pipeline.process(texturedPair(4), stage1Context(), &r);
  EXPECT_TRUE(r.frame_ok);
  EXPECT_GE(r.image_quality, 0.0);
  EXPECT_EQ(r.map_frames, 1);
  EXPECT_EQ(pipeline.failedPairs(), 3u);
}

TEST(VisionStageFailure, AnSgbmRangeAsWideAsTheMatchedImageIsRefusedAtInit) {
  // GIVEN the board at a small size: SGBM matched at half size (64 px) with a 64 px range
  VisionPipelineConfig c = throwingWorkspaceConfig();
  c.stage_probe_for_test = nullptr;
  c.dense.num_disparities = 64;
  VisionPipeline pipeline;
  std::string error;
  // THEN the pipeline refuses to start (OpenCV would throw on every pair), and 48 px (below 64) is taken
  EXPECT_FALSE(pipeline.init(c, &error));
  EXPECT_NE(error.find("dense stereo"), std::string::npos) << error;
  c.dense.num_disparities = 48;
  EXPECT_TRUE(pipeline.init(c, &error)) << error;
  EXPECT_EQ(sgbmLargestDisparities(64), 48);
  EXPECT_EQ(sgbmLargestDisparities(65), 64);
  EXPECT_EQ(sgbmLargestDisparities(16), 0);
}

bool g_throw_in_orb = false;
void throwInOrb(VisionStage stage) {
  if (g_throw_in_orb && stage == VisionStage::kOrb) throw std::runtime_error("injected ORB failure");
}

TEST(VisionStageFailure, AFailedOrbStageRestartsTheOrbChainAtTheNextPair) {
  // GIVEN a pipeline with ORB tracking whose ORB stage throws on one pair (test probe)
  VisionPipelineConfig c = throwingWorkspaceConfig();
  c.run_orb = true;
  c.stage_probe_for_test = &throwInOrb;
  VisionPipeline pipeline;
  std::string error;
  ASSERT_TRUE(pipeline.init(c, &error)) << error;
  VisionResult r;
  pipeline.process(texturedPair(1), VisionContext{}, &r);
  ASSERT_TRUE(r.frame_ok);
  // WHEN the ORB stage throws
  g_throw_in_orb = true;
  pipeline.process(texturedPair(2), VisionContext{}, &r);
  g_throw_in_orb = false;
  // THEN that pair is skipped and counted against ORB, with the exception's message
  EXPECT_FALSE(r.frame_ok);
  EXPECT_EQ(r.orb_tracked, 0);
  EXPECT_EQ(pipeline.stageFailures(VisionStage::kOrb), 1u);
  EXPECT_STREQ(pipeline.lastFailure().what, "injected ORB failure");
  // AND the next pair is processed
  pipeline.process(texturedPair(3), VisionContext{}, &r);
  EXPECT_TRUE(r.frame_ok);
  EXPECT_EQ(pipeline.failedPairs(), 1u);
}

}  // namespace
}  // namespace deepnav
