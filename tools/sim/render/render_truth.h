#pragma once
#include <vector>

#include <opencv2/core.hpp>

namespace deepnav::sim {

// Ground truth of one rendered stereo pair, for the left camera unless named otherwise.
struct RenderTruth {
  cv::Mat depth_m;        // CV_32F: depth along the optical axis (z of the optical frame), m; 0 = no surface
                          // within range (open water)
  cv::Mat disparity_px;   // CV_32F: fx * baseline / depth, px; 0 where depth is 0 (as Middlebury: 0 = unknown)
  cv::Mat right_depth_m;  // CV_32F: the same as depth_m for the right camera (occlusion checks)
  // Markers whose 4 corners project inside the left image, on a face turned towards the camera, and
  // whose corners (inset by 2 %) are reached by an unobstructed ray from the camera; ascending ids.
  std::vector<int> visible_marker_ids;
};

}  // namespace deepnav::sim
