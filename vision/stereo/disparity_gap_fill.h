#pragma once
#include <opencv2/core.hpp>

namespace deepnav {

// Gap interpolation (post-processing of Geiger et al. 2010), along rows then along columns: an
// invalid run of at most max_gap_px between two valid disparities d0, d1 is filled with their
// linear interpolation when they agree within 3 px (the gap lies on one surface) and otherwise with
// min(d0, d1): a hole between two surfaces is usually the occluded background.
// fill_borders: runs touching the image border take the one valid end (dense output).
void fillDisparityGaps(int max_gap_px, bool fill_borders, cv::Mat* disparity_px);

}  // namespace deepnav
