#include "tools/sim/render/frame_statistics.h"

#include <algorithm>
#include <cmath>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "vision/iqa/image_quality_score.h"

namespace deepnav::sim {

bool FrameStatisticsRunner::init(const StereoRig& rig, std::string* error) {
  rig_ = rig;
  const OrbVoConfig vo_config;
  if (!extractor_.init(vo_config.extractor, rig.width_px, rig.height_px)) {
    if (error) *error = "frame statistics: ORB extractor init failed";
    return false;
  }
  if (!vo_.init(vo_config, rig, error)) return false;
  StereoCloudConfig dense_config;  // the board's defaults: ELAS, half size, 128 disparities
  StereoGeometry geometry;
  geometry.fx_px = rig.fx_px;
  geometry.fy_px = rig.fy_px;
  geometry.cx_px = rig.cx_px;
  geometry.cy_px = rig.cy_px;
  geometry.baseline_m = rig.baseline_m;
  if (!dense_.init(dense_config, geometry, rig.width_px, rig.height_px, error) || !dense_.allocateCloud(&cloud_)) {
    if (error && error->empty()) *error = "frame statistics: dense stereo init failed";
    return false;
  }
  has_previous_ = false;
  return true;
}

bool FrameStatisticsRunner::common(const cv::Mat& image, FrameStatistics* out) {
  if (image.cols != rig_.width_px || image.rows != rig_.height_px) return false;
  if (!computeMdm(image, &out->mdm, &mdm_ws_)) return false;
  if (image.channels() == 3) {
    cv::cvtColor(image, grey_, cv::COLOR_BGR2GRAY);
  } else {
    image.copyTo(grey_);
  }
  out->orb_keypoints = extractor_.extract(grey_, &features_, &descriptors_);
  out->orb_tracked_2d = has_previous_ ? trackedAgainstPrevious() : -1;
  previous_features_.swap(features_);
  previous_descriptors_.swap(descriptors_);
  has_previous_ = true;
  return true;
}

// Mutual nearest neighbours in Hamming distance, then the inliers of a RANSAC fundamental matrix.
int FrameStatisticsRunner::trackedAgainstPrevious() {
  const auto nearest = [](const OrbDescriptor& d, const std::vector<OrbDescriptor>& set, int* distance) {
    int best = -1;
    *distance = 257;
    for (int j = 0; j < static_cast<int>(set.size()); ++j) {
      const int h = hammingDistance(d, set[static_cast<std::size_t>(j)]);
      if (h < *distance) *distance = h, best = j;
    }
    return best;
  };
  std::vector<cv::Point2f> a, b;
  for (int i = 0; i < static_cast<int>(descriptors_.size()); ++i) {
    int distance = 0, back_distance = 0;
    const int j = nearest(descriptors_[static_cast<std::size_t>(i)], previous_descriptors_, &distance);
    if (j < 0 || distance > kMaxHamming) continue;
    if (nearest(previous_descriptors_[static_cast<std::size_t>(j)], descriptors_, &back_distance) != i) continue;
    a.emplace_back(previous_features_[static_cast<std::size_t>(j)].u_px, previous_features_[static_cast<std::size_t>(j)].v_px);
    b.emplace_back(features_[static_cast<std::size_t>(i)].u_px, features_[static_cast<std::size_t>(i)].v_px);
  }
  if (a.size() < 8) return 0;  // too few for the fundamental matrix: none confirmed
  std::vector<unsigned char> inlier;
  const cv::Mat F = cv::findFundamentalMat(a, b, cv::FM_RANSAC, kRansacPx, 0.999, inlier);
  if (F.empty()) return 0;
  return static_cast<int>(std::count(inlier.begin(), inlier.end(), 1));
}

bool FrameStatisticsRunner::stereo(TimeUs t_us, const cv::Mat& left, const cv::Mat& right, FrameStatistics* out) {
  *out = FrameStatistics{};
  if (right.size() != left.size() || right.type() != left.type() || !common(left, out)) return false;
  vo_.process(t_us, left, right, &vo_out_);
  out->orb_tracked_stereo =
      vo_out_.hasRelativePose() || vo_out_.status == OrbVoStatus::kInitialised ? vo_out_.tracked_features : 0;
  out->image_quality = imageQualityScore(out->mdm, out->orb_tracked_stereo, kOrbMaxTracked);
  if (dense_.compute(left, right, &cloud_)) {
    const cv::Mat& d = dense_.disparity();
    out->elas_coverage = static_cast<double>(cv::countNonZero(d >= 0.0f)) / static_cast<double>(d.total());
  }
  return true;
}

bool FrameStatisticsRunner::mono(const cv::Mat& image, FrameStatistics* out) {
  *out = FrameStatistics{};
  if (!common(image, out)) return false;
  out->image_quality = imageQualityScore(out->mdm, std::max(out->orb_tracked_2d, 0), kOrbMaxTracked);
  return true;
}

cv::Mat toRigFormat(const cv::Mat& image, int width_px, int height_px) {
  const double aspect = static_cast<double>(width_px) / height_px;
  cv::Rect crop(0, 0, image.cols, image.rows);
  if (static_cast<double>(image.cols) / image.rows > aspect) {
    crop.width = static_cast<int>(std::lround(image.rows * aspect));
    crop.x = (image.cols - crop.width) / 2;
  } else {
    crop.height = static_cast<int>(std::lround(image.cols / aspect));
    crop.y = (image.rows - crop.height) / 2;
  }
  cv::Mat resized, grey;
  cv::resize(image(crop), resized, cv::Size(width_px, height_px), 0.0, 0.0, cv::INTER_AREA);
  if (resized.channels() == 3) {
    cv::cvtColor(resized, grey, cv::COLOR_BGR2GRAY);
    return grey;
  }
  return resized;
}

StatisticSummary summarise(std::vector<double> values) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return !(v >= 0.0); }), values.end());
  StatisticSummary s;
  s.count = static_cast<int>(values.size());
  if (values.empty()) return s;
  double sum = 0.0;
  for (double v : values) sum += v;
  s.mean = sum / s.count;
  double sq = 0.0;
  for (double v : values) sq += (v - s.mean) * (v - s.mean);
  s.stddev = s.count > 1 ? std::sqrt(sq / (s.count - 1)) : 0.0;
  std::sort(values.begin(), values.end());
  s.median = s.count % 2 ? values[static_cast<std::size_t>(s.count / 2)]
                         : 0.5 * (values[static_cast<std::size_t>(s.count / 2 - 1)] + values[static_cast<std::size_t>(s.count / 2)]);
  return s;
}

}  // namespace deepnav::sim
