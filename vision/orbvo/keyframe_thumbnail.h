#pragma once
#include <opencv2/core.hpp>

namespace deepnav {

// A keyframe's whole image shrunk to 80 x 60 and blurred, zero mean and unit norm, so that the
// similarity of two views is one dot product (normalised cross-correlation). Relocalisation ranks
// the stored keyframes with it before any descriptor matching, after PTAM's small-blurry-image
// relocaliser (Klein & Murray, ISMAR 2007 / ECCV 2008): a view close to a keyframe's looks like it.
constexpr int kThumbnailWidthPx = 80;
constexpr int kThumbnailHeightPx = 60;
constexpr int kThumbnailSize = kThumbnailWidthPx * kThumbnailHeightPx;

// Fills out[0 .. kThumbnailSize) from `grey` (CV_8UC1); *scratch is a reusable CV_8UC1 buffer.
void makeThumbnail(const cv::Mat& grey, cv::Mat* scratch, float* out);

// Normalised cross-correlation of two thumbnails, in [-1, 1] (0 for a flat image).
float thumbnailSimilarity(const float* a, const float* b);

}  // namespace deepnav
