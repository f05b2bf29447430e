// deepnav-frame-stats' statistics (tools/sim/render/frame_statistics.h) on rendered pairs and, when the
// shared data is there, on the real underwater frames.
#include <filesystem>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "tools/sim/render/frame_statistics.h"
#include "tools/sim/render/stereo_renderer.h"
#include "tools/sim/sensor_simulator.h"
#include "vision/iqa/image_quality_score.h"

namespace deepnav::sim {
namespace {

TEST(SimRenderCameraFrameStats, RenderedPairsGiveThePipelineStatistics) {
  // GIVEN three pairs of the default dive's valves-face dwell, 0.1 s apart
  const Scenario s;
  SensorSimulator sim;
  StereoRenderer renderer;
  std::string error;
  ASSERT_TRUE(sim.init(s, 1, &error) && renderer.init(s, 1, 1, &error)) << error;
  StereoRig rig;  // the simulated rig's defaults
  FrameStatisticsRunner runner;
  ASSERT_TRUE(runner.init(rig, &error)) << error;
  StereoFrame frame;
  allocateStereoFrame(frame, 688, 516, 1);
  FrameStatistics st[3];
  for (int i = 0; i < 3; ++i) {
    const TimeUs t_us = 36'000'000 + 100'000 * i;
    ASSERT_TRUE(renderer.render(sim.cameraAt(t_us), &frame, nullptr));
    ASSERT_TRUE(runner.stereo(t_us, frame.left, frame.right, &st[i]));
  }
  // THEN MDM is in range, the first frame has no previous one, later ones track most of their corners
  for (const FrameStatistics& f : st) {
    EXPECT_GT(f.mdm.f1, 0.0);
    EXPECT_LE(f.mdm.f1, 1.0);
    EXPECT_GT(f.mdm.f3, 0.3);
    EXPECT_GT(f.orb_keypoints, 100);
    EXPECT_GT(f.elas_coverage, 0.3);
    EXPECT_LE(f.elas_coverage, 1.0);
    EXPECT_NEAR(f.image_quality, imageQualityScore(f.mdm, f.orb_tracked_stereo, 300), 1e-12);
  }
  EXPECT_EQ(st[0].orb_tracked_2d, -1);
  EXPECT_GT(st[2].orb_tracked_2d, 50);
  EXPECT_GT(st[2].orb_tracked_stereo, 50);
  // AND the image and a copy shifted 3 px, as a monocular sequence, give a 2-D count (most corners
  // found again) and no stereo figures
  FrameStatisticsRunner mono;
  ASSERT_TRUE(mono.init(rig, &error));
  FrameStatistics m;
  cv::Mat shifted;
  cv::warpAffine(frame.left, shifted, cv::Matx23d(1, 0, 3, 0, 1, 0), frame.left.size(), cv::INTER_NEAREST,
                 cv::BORDER_REPLICATE);
  ASSERT_TRUE(mono.mono(frame.left, &m));
  ASSERT_TRUE(mono.mono(shifted, &m));
  EXPECT_EQ(m.orb_tracked_stereo, -1);
  EXPECT_EQ(m.elas_coverage, -1.0);
  EXPECT_GT(m.orb_tracked_2d, m.orb_keypoints / 2);
}

TEST(SimRenderCameraFrameStats, SummaryAndRealFramesWhenPresent) {
  const StatisticSummary s = summarise({1.0, -1.0, 3.0, 2.0});
  EXPECT_EQ(s.count, 3);
  EXPECT_DOUBLE_EQ(s.mean, 2.0);
  EXPECT_DOUBLE_EQ(s.median, 2.0);
  EXPECT_DOUBLE_EQ(s.stddev, 1.0);
  const std::filesystem::path dir = "../shared/data/underwater-frames/subvo-pool";
  if (!std::filesystem::is_directory(dir)) GTEST_SKIP() << dir << " absent";
  const cv::Mat image = cv::imread((dir / "frame_00_00_21.000.jpg").string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  const cv::Mat rig_image = toRigFormat(image, 688, 516);
  EXPECT_EQ(rig_image.cols, 688);
  EXPECT_EQ(rig_image.rows, 516);
  EXPECT_EQ(rig_image.channels(), 1);
}

}  // namespace
}  // namespace deepnav::sim
