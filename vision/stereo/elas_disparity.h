#pragma once
#include <opencv2/core.hpp>

#include "vision/stereo/disparity_edge_refiner.h"
#include "vision/stereo/disparity_estimator.h"
#include "vision/stereo/disparity_speckle_filter.h"
#include "vision/stereo/elas_candidates.h"
#include "vision/stereo/elas_dense.h"
#include "vision/stereo/elas_descriptor.h"
#include "vision/stereo/elas_params.h"
#include "vision/stereo/elas_prior.h"
#include "vision/stereo/elas_support.h"

namespace deepnav {

// ELAS, Efficient Large-Scale Stereo (Geiger, Roser & Urtasun, ACCV 2010), implemented from the
// paper: Sobel descriptors -> robust support points on a grid -> Delaunay mesh as a
// piecewise-planar prior -> per-pixel MAP over descriptor cost + prior, for both views ->
// left-right check -> speckle removal -> gap interpolation. Two additions of ours: the descriptor
// gain follows the image contrast (descriptorGain), and an edge-aware weighted median undoes the
// foreground fattening at depth edges (DisparityEdgeRefiner). Without the latter the Middlebury
// D1 rates are 2.4 % (tsukuba) and 1.1 % (venus) instead of 1.7 % and 0.4 %.
// Every buffer is sized in init() for one image size and disparity range; compute() does not
// allocate (the Delaunay mesh is our own DelaunayTriangulation rather than cv::Subdiv2D, which
// allocates on every call).
class ElasDisparity final : public DisparityEstimator {
 public:
  // Returns false for sizes below 16x16 or invalid parameters (num_disparities in [2, 256]).
  bool init(const ElasParams& params, int width_px, int height_px);
  bool compute(const cv::Mat& left, const cv::Mat& right, cv::Mat* disparity_px) override;

  // Diagnostics of the last compute().
  int supportPointCount() const { return static_cast<int>(support_.points().size()); }
  int triangleCount() const { return prior_left_.triangleCount(); }

 private:
  bool toGrey(const cv::Mat& image, cv::Mat* grey) const;
  void postprocess(const cv::Mat& left, cv::Mat* disparity_px);

  bool ready_ = false;
  ElasParams params_;
  int width_px_ = 0;
  int height_px_ = 0;
  cv::Mat grey_left_, grey_right_;
  ElasDescriptorImage desc_left_, desc_right_;
  SobelHistogram sobel_histogram_{};
  float descriptor_gain_ = 0.0f;
  ElasSupport support_;
  ElasPrior prior_left_, prior_right_;
  ElasCandidates candidates_left_, candidates_right_;
  ElasDenseMatcher dense_;
  cv::Mat disparity_right_px_;
  cv::Mat subpixel_px_;  // sub-pixel corrections of the left map
  DisparitySpeckleFilter speckle_;
  DisparityEdgeRefiner refiner_;
};

}  // namespace deepnav
