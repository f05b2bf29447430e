#include "vision/orbvo/orb_stereo_odometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <utility>

#include "base/so3.h"
#include "vision/orbvo/guided_stereo.h"
#include "vision/orbvo/relative_camera_pose.h"

namespace deepnav {
namespace {

using Start = FramePoseEstimator::Start;

// The grey image of `image` (CV_8UC1 as is, CV_8UC3 converted into the preallocated *grey).
const cv::Mat* greyOf(const cv::Mat& image, cv::Mat* grey) {
  if (image.type() == CV_8UC1) return &image;
  if (image.type() != CV_8UC3) return nullptr;
  cv::cvtColor(image, *grey, cv::COLOR_BGR2GRAY);
  return grey;
}

}  // namespace

bool OrbStereoOdometry::init(const OrbVoConfig& config, const StereoRig& rig, std::string* error) {
  ready_ = false;
  const char* bad = config.validate();
  if (bad[0] != '\0') {
    *error = std::string("orbvo config: ") + bad;
    return false;
  }
  if (rig.fx_px <= 0.0 || rig.fy_px <= 0.0 || rig.baseline_m <= 0.0 || rig.width_px < 64 ||
      rig.height_px < 64) {
    *error = "orbvo rig: fx, fy, baseline must be > 0 and the image at least 64x64";
    return false;
  }
  config_ = config;
  rig_ = rig;
  if (!extractor_.init(config.extractor, rig.width_px, rig.height_px)) {
    *error = "orbvo extractor: bad grid, pyramid or FAST thresholds for this image size";
    return false;
  }
  OrbExtractorConfig right_config = config.extractor;
  right_config.max_features_per_cell = static_cast<int>(
      std::lround(config.extractor.max_features_per_cell * config.right_budget_factor));
  if (!right_extractor_.init(right_config, rig.width_px, rig.height_px)) {
    *error = "orbvo right extractor: bad configuration";
    return false;
  }
  const int capacity = extractor_.capacity();
  if (!stereo_.init(config.stereo, rig, right_extractor_.capacity(),
                    config.extractor.scale_factor)) {
    *error = "orbvo stereo: bad band, depth range, ratio or SAD window";
    return false;
  }
  std::vector<double> level_scale(extractor_.levels(), 1.0);
  level_sigma_px_.assign(extractor_.levels(), config.pixel_sigma_px);
  for (int l = 0; l < extractor_.levels(); ++l) {
    level_scale[l] = extractor_.levelScale(l);
    level_sigma_px_[l] = config.pixel_sigma_px * level_scale[l];
  }
  if (!search_.init(rig, level_scale, config.local_keyframes, config.frame_search,
                    config.map_search, capacity) ||
      !pose_estimator_.init(rig, config.pnp, config.refiner, level_sigma_px_, capacity) ||
      !window_adjustment_.init(rig, config.bundle, config.local_keyframes, level_sigma_px_,
                               capacity) ||
      !relocaliser_.init(config.reloc, config.max_keyframes, capacity) ||
      !map_.init(config.max_keyframes, capacity, config.max_map_points)) {
    *error = "orbvo: buffer sizes";
    return false;
  }
  grey_left_.create(rig.height_px, rig.width_px, CV_8UC1);
  grey_right_.create(rig.height_px, rig.width_px, CV_8UC1);
  right_features_.reserve(right_extractor_.capacity());
  right_descriptors_.reserve(right_extractor_.capacity());
  cur_.reserve(capacity);
  prev_.reserve(capacity);
  saved_map_point_.reserve(capacity);
  saved_match_distance_.reserve(capacity);
  ready_ = true;
  reset();
  return true;
}

void OrbStereoOdometry::reset() {
  map_.clear();
  initialised_ = false;
  lost_ = false;
  lost_frames_ = 0;
  frames_since_keyframe_ = 0;
  has_velocity_ = false;
  search_.clearAnchor();
  last_tracked_.has_prior = false;
  prev_.features.clear();
  prev_.map_point.clear();
}

bool OrbStereoOdometry::process(const StereoFrame& frame, OrbVoOutput* out) {
  if (!frame.rectified) {
    *out = OrbVoOutput();
    out->t_us = frame.t_us;
    return false;
  }
  return process(frame.t_us, frame.left, frame.right, out);
}

bool OrbStereoOdometry::process(TimeUs t_us, const cv::Mat& left, const cv::Mat& right,
                                OrbVoOutput* out) {
  *out = OrbVoOutput();
  out->t_us = t_us;
  keyframe_inserted_ = false;
  prior_cur_ = prior_next_;
  prior_cur_T_odom_cam_ = prior_next_T_odom_cam_;
  prior_next_ = false;
  prior_reselected_ = false;
  if (!ready_ || !detect(t_us, left, right)) {
    fillOutput(out);
    return false;
  }
  bool tracked = false;
  bool relocalised = false;
  if (!initialised_) {
    if (startMap(out)) return true;
  } else if (!lost_) {
    tracked = trackFrame();
    if (tracked) reselectWithPrior();
  } else {
    relocalised = relocalise();
    tracked = relocalised;
  }
  if (!tracked) {
    if (initialised_ && !lost_) {
      lost_ = true;
      lost_frames_ = 0;
    }
    ++lost_frames_;
    has_velocity_ = false;
    if (initialised_ && config_.reset_after_lost_frames > 0 &&
        lost_frames_ >= config_.reset_after_lost_frames && startMap(out)) {
      return true;
    }
    out->status = OrbVoStatus::kLost;
    out->tracked_features = cur_.tracked;
    fillOutput(out);
    return true;
  }
  if (keyframeNeeded()) insertKeyframe();
  ++frames_since_keyframe_;
  // The relative pose uses the final poses (after a bundle adjustment), so that chaining the
  // outputs gives the odometry's trajectory exactly; its covariance is the tracking one.
  const RelativeCameraPose rel = relativeCameraPose(last_tracked_.pose, cur_.pose);
  out->status = relocalised ? OrbVoStatus::kRelocalised : OrbVoStatus::kOk;
  out->t_reference_us = last_tracked_.t_us;
  out->q_cama_camb = rel.q_cama_camb;
  out->p_camb_in_cama_m = rel.p_camb_in_cama_m;
  out->cov = rel.cov;
  out->tracked_features = cur_.tracked;
  out->reprojection_rms_px = cur_.pose.rms_px;
  out->prior_reselected = prior_reselected_;
  if (relocalised) {
    has_velocity_ = false;
  } else {
    R_velocity_ = cur_.pose.R_cam_world * prev_.pose.R_cam_world.transpose();
    t_velocity_ = cur_.pose.p_world_in_cam_m - R_velocity_ * prev_.pose.p_world_in_cam_m;
    has_velocity_ = true;
  }
  rememberTracked();
  lost_ = false;
  lost_frames_ = 0;
  fillOutput(out);
  std::swap(prev_, cur_);
  return true;
}

bool OrbStereoOdometry::detect(TimeUs t_us, const cv::Mat& left, const cv::Mat& right) {
  cur_.t_us = t_us;
  cur_.features.clear();
  cur_.tracked = 0;
  cur_.stereo_points = 0;
  if (left.cols != rig_.width_px || left.rows != rig_.height_px || right.size() != left.size())
    return false;
  const cv::Mat* grey_left = greyOf(left, &grey_left_);
  const cv::Mat* grey_right = greyOf(right, &grey_right_);
  if (grey_left == nullptr || grey_right == nullptr) return false;
  cur_left_ = *grey_left;
  cur_right_ = *grey_right;
  if (extractor_.extract(*grey_left, &cur_.features, &cur_.descriptors) < 0) return false;
  if (right_extractor_.extract(*grey_right, &right_features_, &right_descriptors_) < 0)
    return false;
  cur_.stereo_points =
      stereo_.match(*grey_left, *grey_right, cur_.features, cur_.descriptors, right_features_,
                    right_descriptors_, &cur_.u_right_px, &cur_.p_in_cam_m);
  const std::size_t n = cur_.features.size();
  cur_.map_point.assign(n, -1);
  cur_.match_distance.assign(n, std::numeric_limits<int>::max());
  cur_.available.assign(n, 1);
  return true;
}

void OrbStereoOdometry::fillOutput(OrbVoOutput* out) const {
  out->left_features = static_cast<int>(cur_.features.size());
  out->stereo_points = cur_.stereo_points;
  out->keyframe_inserted = keyframe_inserted_;
  out->keyframes = map_.keyframeCount();
  out->map_points = map_.mapPointCount();
  const TrackedPose& pose = last_tracked_;
  const Eigen::Matrix3d R_world_cam = pose.pose.R_cam_world.transpose();
  out->q_world_cam = Eigen::Quaterniond(R_world_cam).normalized();
  out->p_cam_in_world_m = -R_world_cam * pose.pose.p_world_in_cam_m;
}

// A new map whose world frame is this frame's left camera; every stereo point becomes a map point.
bool OrbStereoOdometry::startMap(OrbVoOutput* out) {
  if (cur_.stereo_points < config_.min_init_points) return false;
  map_.clear();
  cur_.pose = CameraPoseEstimate();
  cur_.pose.cov_xi.setZero();  // the map is defined by this frame
  initialised_ = true;
  lost_ = false;
  lost_frames_ = 0;
  has_velocity_ = false;
  search_.clearAnchor();
  insertKeyframe();
  cur_.tracked = map_.mapPointCount();
  rememberTracked();
  out->status = OrbVoStatus::kInitialised;
  out->tracked_features = cur_.tracked;
  fillOutput(out);
  std::swap(prev_, cur_);
  return true;
}

void OrbStereoOdometry::rememberTracked() {
  last_tracked_.t_us = cur_.t_us;
  last_tracked_.pose = cur_.pose;
  last_tracked_.has_prior = prior_cur_;
  last_tracked_.T_odom_cam_prior = prior_cur_T_odom_cam_;
}

bool OrbStereoOdometry::trackFrame() {
  CameraPoseEstimate predicted = prev_.pose;
  if (has_velocity_) {
    predicted.R_cam_world = R_velocity_ * prev_.pose.R_cam_world;
    predicted.p_world_in_cam_m = R_velocity_ * prev_.pose.p_world_in_cam_m + t_velocity_;
  }
  search_.index(cur_);
  const double radius_px = config_.frame_search.radius_px;
  if (search_.searchPreviousFrame(prev_, predicted, radius_px, &map_, &cur_) <
      config_.min_frame_matches) {
    cur_.clearAssociations();
    search_.searchPreviousFrame(prev_, predicted, radius_px * config_.frame_search_widen, &map_,
                                &cur_);
  }
  CameraPoseEstimate pose = predicted;
  if (!estimatePose(Start::kRansacOrGiven, &pose)) {
    // The previous frame alone is not enough (e.g. after a jerk): try the local map around the
    // prediction.
    cur_.clearAssociations();
    pose = predicted;
    if (search_.searchLocalMap(pose, &map_, &cur_) < config_.refiner.min_inliers ||
        !estimatePose(Start::kRansacOrGiven, &pose)) {
      return false;
    }
  }
  search_.searchLocalMap(pose, &map_, &cur_);
  completeStereo(pose);
  if (!estimatePose(Start::kGiven, &pose)) return false;
  cur_.pose = pose;
  return cur_.tracked >= config_.min_tracked;
}

// When the tracked pose disagrees with the navigation's predicted motion since the last tracked pair,
// the associations are made again around the prediction and only those within its gate are kept
// (motion_prior.h: coherently drifting points such as marine snow fall outside it); the re-selected
// pose replaces the tracked one if it is well supported and agrees with the prediction, else the
// tracked pose stands (and the filter's gate judges it). Returns true when re-selected.
bool OrbStereoOdometry::reselectWithPrior() {
  const OrbMotionPriorConfig& c = config_.motion_prior;
  if (!c.enabled || !prior_cur_ || !last_tracked_.has_prior) return false;
  const Eigen::Isometry3d T_a_b = last_tracked_.T_odom_cam_prior.inverse() * prior_cur_T_odom_cam_;
  if (priorDisagreement(relativeCameraPose(last_tracked_.pose, cur_.pose), T_a_b, c) <=
      c.consistency_chi2) {
    return false;
  }
  saved_map_point_.assign(cur_.map_point.begin(), cur_.map_point.end());
  saved_match_distance_.assign(cur_.match_distance.begin(), cur_.match_distance.end());
  const CameraPoseEstimate saved_pose = cur_.pose;
  const int saved_tracked = cur_.tracked;
  const CameraPoseEstimate predicted = predictCameraPose(last_tracked_.pose, T_a_b);
  cur_.clearAssociations();
  search_.searchPreviousFrame(prev_, predicted, config_.frame_search.radius_px, &map_, &cur_);
  search_.searchLocalMap(predicted, &map_, &cur_);
  for (std::size_t j = 0; j < cur_.map_point.size(); ++j) {
    const int m = cur_.map_point[j];
    if (m < 0) continue;
    const OrbFeature& f = cur_.features[j];
    if (!withinPriorGate(rig_, predicted, map_.point(m).p_in_world_m, {f.u_px, f.v_px},
                         level_sigma_px_[f.level], c)) {
      cur_.map_point[j] = -1;
      cur_.match_distance[j] = std::numeric_limits<int>::max();
    }
  }
  completeStereo(predicted);
  CameraPoseEstimate pose = predicted;
  if (estimatePose(Start::kGiven, &pose) && cur_.tracked >= config_.min_tracked &&
      priorDisagreement(relativeCameraPose(last_tracked_.pose, pose), T_a_b, c) <=
          c.consistency_chi2) {
    cur_.pose = pose;
    prior_reselected_ = true;
    return true;
  }
  cur_.map_point.assign(saved_map_point_.begin(), saved_map_point_.end());
  cur_.match_distance.assign(saved_match_distance_.begin(), saved_match_distance_.end());
  for (std::size_t j = 0; j < cur_.map_point.size(); ++j) cur_.available[j] = cur_.map_point[j] < 0;
  cur_.pose = saved_pose;
  cur_.tracked = saved_tracked;
  return false;
}

int OrbStereoOdometry::completeStereo(const CameraPoseEstimate& pose) {
  return deepnav::completeStereo(stereo_, rig_, config_.stereo, cur_left_, cur_right_, map_, pose,
                                 &cur_);
}

bool OrbStereoOdometry::keyframeNeeded() const {
  if (map_.keyframeCount() == 0) return true;
  const Keyframe& kf = map_.keyframe(0);
  int kf_points = 0;
  for (const int m : kf.map_point) kf_points += m >= 0;
  KeyframePolicyInput in;
  in.tracked = cur_.tracked;
  in.keyframe_points = kf_points;
  const Eigen::Matrix3d R_kf_cur = kf.R_cam_world * cur_.pose.R_cam_world.transpose();
  const Eigen::Vector3d p_cur_in_kf = kf.p_world_in_cam_m - R_kf_cur * cur_.pose.p_world_in_cam_m;
  in.translation_m = p_cur_in_kf.norm();
  in.rotation_deg = logSo3(R_kf_cur).norm() * 180.0 / std::numbers::pi;
  in.frames_since_keyframe = frames_since_keyframe_;
  return needKeyframe(config_.keyframe, in);
}

void OrbStereoOdometry::insertKeyframe() {
  // References first: pushing may evict the oldest keyframe, which must not free the tracked
  // points.
  const int n = static_cast<int>(cur_.features.size());
  for (int j = 0; j < n; ++j) {
    const int m = cur_.map_point[j];
    if (m < 0) continue;
    map_.addReference(m);
    MapPoint& point = map_.point(m);
    point.descriptor = cur_.descriptors[j];  // the newest appearance matches the next frames best
    point.level = cur_.features[j].level;
  }
  Keyframe& kf = map_.pushKeyframe();
  kf.t_us = cur_.t_us;
  kf.R_cam_world = cur_.pose.R_cam_world;
  kf.p_world_in_cam_m = cur_.pose.p_world_in_cam_m;
  kf.features.assign(cur_.features.begin(), cur_.features.end());
  kf.descriptors.assign(cur_.descriptors.begin(), cur_.descriptors.end());
  kf.u_right_px.assign(cur_.u_right_px.begin(), cur_.u_right_px.end());
  kf.tracked = cur_.tracked;
  const Eigen::Matrix3d R_world_cam = cur_.pose.R_cam_world.transpose();
  const Eigen::Vector3d p_cam_in_world_m = -R_world_cam * cur_.pose.p_world_in_cam_m;
  for (int j = 0; j < n; ++j) {
    if (cur_.map_point[j] >= 0 || cur_.u_right_px[j] < 0.0f) continue;
    cur_.map_point[j] = map_.createPoint(R_world_cam * cur_.p_in_cam_m[j] + p_cam_in_world_m,
                                         cur_.descriptors[j], cur_.features[j].level);
  }
  kf.map_point.assign(cur_.map_point.begin(), cur_.map_point.end());
  relocaliser_.makeThumbnailOf(cur_left_, kf.thumbnail.data());
  frames_since_keyframe_ = 0;
  keyframe_inserted_ = true;
  if (map_.keyframeCount() >= 2) window_adjustment_.adjust(&map_, &cur_);
}

bool OrbStereoOdometry::relocalise() {
  const int n_kf = map_.keyframeCount();
  const int n = static_cast<int>(cur_.features.size());
  if (n_kf == 0 || n < config_.reloc.min_inliers) return false;
  search_.index(cur_);
  const int stride = relocaliser_.rank(cur_left_, cur_, map_);
  for (int attempt = 0; attempt < std::min(config_.reloc.candidates, n_kf); ++attempt) {
    const int age = relocaliser_.nextCandidate(n_kf, stride);
    if (age < 0) break;
    const Keyframe& kf = map_.keyframe(age);
    if (relocaliser_.matchKeyframe(kf, map_, &cur_) < config_.reloc.min_inliers) continue;
    CameraPoseEstimate pose;
    pose.R_cam_world = kf.R_cam_world;
    pose.p_world_in_cam_m = kf.p_world_in_cam_m;
    // RANSAC must succeed here: there is no motion prior to fall back on.
    if (!estimatePose(Start::kRansacOnly, &pose)) continue;
    search_.anchorAt(kf.id, map_.keyframe(0).id + config_.local_keyframes);
    search_.searchLocalMap(pose, &map_, &cur_);
    completeStereo(pose);
    if (!estimatePose(Start::kGiven, &pose) ||
        cur_.tracked < config_.reloc.min_inliers)
      continue;
    cur_.pose = pose;
    return true;
  }
  search_.clearAnchor();
  cur_.clearAssociations();
  return false;
}

}  // namespace deepnav
