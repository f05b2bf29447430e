#pragma once
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "vision/cloud/stereo_cloud.h"
#include "vision/iqa/mdm.h"
#include "vision/orbvo/grid_orb_extractor.h"
#include "vision/orbvo/orb_stereo_odometry.h"
#include "vision/orbvo/stereo_rig.h"

namespace deepnav::sim {

// The statistics the navigation pipeline decides on (vision/pipeline/vision_pipeline.cpp), for one
// frame of a sequence: MDM f1, f2, f3 of the left image (vision/iqa), its ORB keypoints (the VO's
// bucketed extractor, vision/orbvo), the tracked count and m_I, and the ELAS dense coverage (the
// board's dense chain: ELAS at half size, 128 disparities; vision/stereo). For renderer-versus-real
// comparisons (deepnav-frame-stats, tools/sim/README.md).
struct FrameStatistics {
  MdmScore mdm;
  int orb_keypoints = 0;
  // Stereo: the ORB VO's tracked features (as the pipeline counts them); -1 for a monocular sequence.
  int orb_tracked_stereo = -1;
  // Both: ORB features matched to the previous frame's (mutual nearest Hamming neighbours, distance
  // <= kMaxHamming) that are inliers of a RANSAC fundamental matrix (kRansacPx): a 2-D stand-in for the
  // tracked count that a monocular sequence also has. -1 on the first frame.
  int orb_tracked_2d = -1;
  // m_I = mean(f1, f2, f3, min(1, tracked / 300)) with the stereo count (monocular: the 2-D count).
  double image_quality = 0.0;
  double elas_coverage = -1.0;  // fraction of the left image with a disparity; -1 monocular
};

// Runs the chain over a sequence, frame after frame (the trackers keep their state between calls).
class FrameStatisticsRunner {
 public:
  static constexpr int kMaxHamming = 50;
  static constexpr double kRansacPx = 1.5;
  static constexpr int kOrbMaxTracked = 300;  // the board's vision.orb_max_tracked

  // rig: the rectified intrinsics of stereo pairs (unused for monocular images, which only need the size).
  bool init(const StereoRig& rig, std::string* error);
  // One rectified pair (CV_8UC1 or CV_8UC3 of the rig's size).
  bool stereo(TimeUs t_us, const cv::Mat& left, const cv::Mat& right, FrameStatistics* out);
  // One image of a monocular sequence (of the rig's size).
  bool mono(const cv::Mat& image, FrameStatistics* out);

 private:
  bool common(const cv::Mat& image, FrameStatistics* out);
  int trackedAgainstPrevious();

  StereoRig rig_;
  GridOrbExtractor extractor_;
  OrbStereoOdometry vo_;
  OrbVoOutput vo_out_;
  StereoCloud dense_;
  OrganizedCloud cloud_;
  MdmWorkspace mdm_ws_{};
  cv::Mat grey_;
  std::vector<OrbFeature> features_, previous_features_;
  std::vector<OrbDescriptor> descriptors_, previous_descriptors_;
  bool has_previous_ = false;
};

// A real frame brought to the rig's size for the comparison: the centre cut to the rig's aspect ratio,
// resized (area) to width x height, grey.
cv::Mat toRigFormat(const cv::Mat& image, int width_px, int height_px);

// Mean, standard deviation, median of a column of statistics (values < 0, "not available", skipped);
// count 0 when none.
struct StatisticSummary {
  int count = 0;
  double mean = 0.0, stddev = 0.0, median = 0.0;
};
StatisticSummary summarise(std::vector<double> values);

}  // namespace deepnav::sim
