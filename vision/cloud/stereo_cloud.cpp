#include "vision/cloud/stereo_cloud.h"

#include "vision/cloud/area_halving.h"
#include "vision/stereo/elas_disparity.h"
#include "vision/stereo/sgbm_disparity.h"

namespace deepnav {

StereoCloud::StereoCloud() = default;
StereoCloud::~StereoCloud() = default;

namespace {

// Pixel centres at integer coordinates: full-size u maps to (u + 0.5) / s - 0.5 at scale 1/s.
StereoGeometry reducedGeometry(const StereoGeometry& g, int s) {
  StereoGeometry r = g;
  r.fx_px = g.fx_px / s;
  r.fy_px = g.fy_px / s;
  r.cx_px = (g.cx_px + 0.5) / s - 0.5;
  r.cy_px = (g.cy_px + 0.5) / s - 0.5;
  return r;
}

std::unique_ptr<DisparityEstimator> makeBackend(const StereoCloudConfig& c, int w, int h) {
  if (c.method == DenseStereoMethod::kElas) {
    auto elas = std::make_unique<ElasDisparity>();
    ElasParams p = ElasParams::robotics();
    p.num_disparities = c.num_disparities;
    if (!elas->init(p, w, h)) return nullptr;
    return elas;
  }
  auto sgbm = std::make_unique<SgbmDisparity>();
  SgbmParams p;
  p.num_disparities = c.num_disparities;
  p.wls = c.method == DenseStereoMethod::kSgbmWls;
  if (!sgbm->init(p, w, h)) return nullptr;
  return sgbm;
}

}  // namespace

bool StereoCloud::init(const StereoCloudConfig& config, const StereoGeometry& geometry, int width_px, int height_px,
                       std::string* error) {
  auto fail = [&](const char* what) {
    if (error) *error = what;
    return false;
  };
  if (config.scale_down != 1 && config.scale_down != 2) return fail("vision.dense_scale_down must be 1 or 2");
  if (config.num_disparities < 16 || config.num_disparities > 256) return fail("vision.dense_disparities must be in [16, 256]");
  if (width_px % config.scale_down != 0 || height_px % config.scale_down != 0) return fail("camera size not divisible by vision.dense_scale_down");
  config_ = config;
  width_px_ = width_px;
  height_px_ = height_px;
  const int w = width_px / config.scale_down;
  const int h = height_px / config.scale_down;
  backend_ = makeBackend(config, w, h);
  if (!backend_) return fail("vision: dense stereo backend rejected its parameters");
  CloudConfig cc = config.cloud;
  cc.step_px = config.cloud_step_px;
  if (!builder_.init(reducedGeometry(geometry, config.scale_down), cc, w, h)) return fail("vision: bad cloud geometry or range");
  if (!mixed_.init(config.mixed, builder_.gridRows(), builder_.gridCols())) return fail("vision: bad mixed-pixel filter angle");
  disparity_px_.create(h, w, CV_32FC1);
  if (config.scale_down > 1) {
    left_small_.create(h, w, CV_8UC(config.channels));
    right_small_.create(h, w, CV_8UC(config.channels));
  }
  return true;
}

bool StereoCloud::reduce(const cv::Mat& full, cv::Mat* reduced) const {
  if (full.cols != width_px_ || full.rows != height_px_) return false;
  if (config_.scale_down == 1) {
    *reduced = full;
    return true;
  }
  return halveByArea(full, reduced);  // scale_down is 1 or 2 (init)
}

bool StereoCloud::compute(const cv::Mat& left, const cv::Mat& right, OrganizedCloud* cloud) {
  if (!backend_ || !reduce(left, &left_small_) || !reduce(right, &right_small_)) return false;
  const cv::Mat& l = config_.scale_down == 1 ? left : left_small_;
  const cv::Mat& r = config_.scale_down == 1 ? right : right_small_;
  if (!backend_->compute(l, r, &disparity_px_)) return false;
  return computeFromDisparity(disparity_px_, cloud);
}

bool StereoCloud::computeFromDisparity(const cv::Mat& disparity_px, OrganizedCloud* cloud) {
  if (!builder_.compute(disparity_px, cloud)) return false;
  return mixed_.apply(cloud) >= 0;
}

}  // namespace deepnav
