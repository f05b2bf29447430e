#include "vision/orbvo/orb_stereo_odometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <utility>

#include "base/so3.h"
#include "vision/orbvo/keyframe_thumbnail.h"
#include "vision/orbvo/projection_search.h"
#include "vision/orbvo/relative_camera_pose.h"
#include "vision/orbvo/stereo_projection.h"

namespace deepnav {
namespace {

constexpr double kMinProjectionDepthM = 0.05;

bool insideImage(const StereoRig& rig, const Eigen::Vector2d& uv_px) {
  return uv_px.x() >= 0.0 && uv_px.y() >= 0.0 && uv_px.x() <= rig.width_px - 1.0 &&
         uv_px.y() <= rig.height_px - 1.0;
}

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
  capacity_ = extractor_.capacity();
  if (!stereo_.init(config.stereo, rig, right_extractor_.capacity(),
                    config.extractor.scale_factor)) {
    *error = "orbvo stereo: bad band, depth range, ratio or SAD window";
    return false;
  }
  const int window = config.local_keyframes;
  if (!grid_.init(rig.width_px, rig.height_px, 16, capacity_) || !pnp_.init(capacity_) ||
      !bundle_adjuster_.init(window, window * capacity_, window * capacity_) ||
      !map_.init(config.max_keyframes, capacity_, config.max_map_points)) {
    *error = "orbvo: buffer sizes";
    return false;
  }
  grey_left_.create(rig.height_px, rig.width_px, CV_8UC1);
  grey_right_.create(rig.height_px, rig.width_px, CV_8UC1);
  right_features_.reserve(right_extractor_.capacity());
  right_descriptors_.reserve(right_extractor_.capacity());
  reserveFrame(&cur_, capacity_);
  reserveFrame(&prev_, capacity_);
  level_scale_.assign(extractor_.levels(), 1.0);
  level_sigma_px_.assign(extractor_.levels(), config.pixel_sigma_px);
  for (int l = 0; l < extractor_.levels(); ++l) {
    level_scale_[l] = extractor_.levelScale(l);
    level_sigma_px_[l] = config.pixel_sigma_px * level_scale_[l];
  }
  observations_.reserve(capacity_);
  saved_map_point_.reserve(capacity_);
  saved_match_distance_.reserve(capacity_);
  observation_feature_.reserve(capacity_);
  inlier_.assign(capacity_, 0);
  ba_R_.assign(window, Eigen::Matrix3d::Identity());
  ba_t_.assign(window, Eigen::Vector3d::Zero());
  ba_points_.assign(window * capacity_, Eigen::Vector3d::Zero());
  ba_point_id_.assign(window * capacity_, -1);
  ba_observations_.assign(window * capacity_, BaObservation());
  ba_source_age_.assign(window * capacity_, 0);
  ba_source_feature_.assign(window * capacity_, 0);
  ba_outlier_.assign(window * capacity_, 0);
  thumbnail_scratch_.create(kThumbnailHeightPx, kThumbnailWidthPx, CV_8UC1);
  thumbnail_.assign(kThumbnailSize, 0.0f);
  reloc_similarity_.assign(config.max_keyframes, 0.0f);
  reloc_score_.assign(config.max_keyframes, 0);
  reloc_owner_.assign(capacity_, -1);
  reloc_owner_distance_.assign(capacity_, 0);
  ready_ = true;
  reset();
  return true;
}

void OrbStereoOdometry::reserveFrame(FrameState* frame, int capacity) const {
  frame->features.reserve(capacity);
  frame->descriptors.reserve(capacity);
  frame->u_right_px.reserve(capacity);
  frame->p_in_cam_m.reserve(capacity);
  frame->map_point.reserve(capacity);
  frame->match_distance.reserve(capacity);
  frame->available.reserve(capacity);
}

void OrbStereoOdometry::reset() {
  map_.clear();
  initialised_ = false;
  lost_ = false;
  lost_frames_ = 0;
  frames_since_keyframe_ = 0;
  has_velocity_ = false;
  anchor_keyframe_id_ = -1;
  anchor_until_keyframe_id_ = -1;
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
  last_tracked_.t_us = t_us;
  last_tracked_.pose = cur_.pose;
  last_tracked_.has_prior = prior_cur_;
  last_tracked_.T_odom_cam_prior = prior_cur_T_odom_cam_;
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
  anchor_keyframe_id_ = -1;
  insertKeyframe();
  cur_.tracked = map_.mapPointCount();
  last_tracked_.t_us = cur_.t_us;
  last_tracked_.pose = cur_.pose;
  last_tracked_.has_prior = prior_cur_;
  last_tracked_.T_odom_cam_prior = prior_cur_T_odom_cam_;
  out->status = OrbVoStatus::kInitialised;
  out->tracked_features = cur_.tracked;
  fillOutput(out);
  std::swap(prev_, cur_);
  return true;
}

bool OrbStereoOdometry::trackFrame() {
  CameraPoseEstimate predicted = prev_.pose;
  if (has_velocity_) {
    predicted.R_cam_world = R_velocity_ * prev_.pose.R_cam_world;
    predicted.p_world_in_cam_m = R_velocity_ * prev_.pose.p_world_in_cam_m + t_velocity_;
  }
  grid_.build(cur_.features);
  int matches = searchPreviousFrame(predicted, config_.frame_search.radius_px);
  if (matches < config_.min_frame_matches) {
    clearAssociations();
    matches =
        searchPreviousFrame(predicted, config_.frame_search.radius_px * config_.frame_search_widen);
  }
  CameraPoseEstimate pose = predicted;
  if (!estimatePose(PoseStart::kRansacOrGiven, &pose)) {
    // The previous frame alone is not enough (e.g. after a jerk): try the local map around the
    // prediction.
    clearAssociations();
    pose = predicted;
    if (searchLocalMap(pose) < config_.refiner.min_inliers ||
        !estimatePose(PoseStart::kRansacOrGiven, &pose)) {
      return false;
    }
  }
  searchLocalMap(pose);
  completeStereo(pose);
  if (!estimatePose(PoseStart::kGiven, &pose)) return false;
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
  if (priorDisagreement(relativeCameraPose(last_tracked_.pose, cur_.pose), T_a_b, c) <= c.consistency_chi2) {
    return false;
  }
  saved_map_point_.assign(cur_.map_point.begin(), cur_.map_point.end());
  saved_match_distance_.assign(cur_.match_distance.begin(), cur_.match_distance.end());
  const CameraPoseEstimate saved_pose = cur_.pose;
  const int saved_tracked = cur_.tracked;
  const CameraPoseEstimate predicted = predictCameraPose(last_tracked_.pose, T_a_b);
  clearAssociations();
  searchPreviousFrame(predicted, config_.frame_search.radius_px);
  searchLocalMap(predicted);
  for (std::size_t j = 0; j < cur_.map_point.size(); ++j) {
    const int m = cur_.map_point[j];
    if (m < 0) continue;
    const OrbFeature& f = cur_.features[j];
    if (!withinPriorGate(rig_, predicted, map_.point(m).p_in_world_m, {f.u_px, f.v_px}, sigmaOfLevel(f.level), c)) {
      cur_.map_point[j] = -1;
      cur_.match_distance[j] = std::numeric_limits<int>::max();
    }
  }
  completeStereo(predicted);
  CameraPoseEstimate pose = predicted;
  if (estimatePose(PoseStart::kGiven, &pose) && cur_.tracked >= config_.min_tracked &&
      priorDisagreement(relativeCameraPose(last_tracked_.pose, pose), T_a_b, c) <= c.consistency_chi2) {
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

// Guided stereo: a tracked corner without a right match gets one from the ZSAD search around the
// disparity d = fx b / z its map point predicts (the descriptor matching along the whole row loses
// many corners in low-contrast images; here the search spans a few pixels). Returns the count.
int OrbStereoOdometry::completeStereo(const CameraPoseEstimate& pose) {
  int added = 0;
  for (std::size_t j = 0; j < cur_.map_point.size(); ++j) {
    const int m = cur_.map_point[j];
    if (m < 0 || cur_.u_right_px[j] >= 0.0f) continue;
    const Eigen::Vector3d p_in_cam_m =
        pose.R_cam_world * map_.point(m).p_in_world_m + pose.p_world_in_cam_m;
    if (p_in_cam_m.z() < config_.stereo.min_depth_m || p_in_cam_m.z() > config_.stereo.max_depth_m)
      continue;
    const OrbFeature& f = cur_.features[j];
    const double predicted_disparity_px = rig_.fx_px * rig_.baseline_m / p_in_cam_m.z();
    double u_right = 0.0;
    if (!stereo_.refineRightColumn(cur_left_, cur_right_, f.u_px, f.v_px,
                                   f.u_px - predicted_disparity_px, &u_right)) {
      continue;
    }
    const double disparity_px = f.u_px - u_right;
    if (disparity_px <= 0.0) continue;
    cur_.u_right_px[j] = static_cast<float>(u_right);
    cur_.p_in_cam_m[j] = triangulateStereo(rig_, f.u_px, f.v_px, disparity_px);
    ++added;
  }
  return added;
}

void OrbStereoOdometry::clearAssociations() {
  std::fill(cur_.map_point.begin(), cur_.map_point.end(), -1);
  std::fill(cur_.match_distance.begin(), cur_.match_distance.end(),
            std::numeric_limits<int>::max());
  std::fill(cur_.available.begin(), cur_.available.end(), std::uint8_t{1});
}

int OrbStereoOdometry::searchPreviousFrame(const CameraPoseEstimate& predicted, double radius_px) {
  const int stamp = map_.nextStamp();
  ProjectionSearchConfig search = config_.frame_search;
  search.radius_px = radius_px;
  for (std::size_t i = 0; i < prev_.map_point.size(); ++i) {
    const int m = prev_.map_point[i];
    if (m < 0) continue;
    MapPoint& point = map_.point(m);
    if (!point.alive || point.visit_stamp == stamp) continue;
    point.visit_stamp = stamp;
    const Eigen::Vector3d p_in_cam_m =
        predicted.R_cam_world * point.p_in_world_m + predicted.p_world_in_cam_m;
    if (p_in_cam_m.z() < kMinProjectionDepthM) continue;
    const Eigen::Vector2d uv = projectLeft(rig_, p_in_cam_m);
    if (!insideImage(rig_, uv)) continue;
    const ProjectionMatch match = searchNearProjection(
        grid_, cur_.features, cur_.descriptors, cur_.available, level_scale_.data(), uv,
        prev_.features[i].level, prev_.descriptors[i], search);
    if (match.index < 0 || match.distance >= cur_.match_distance[match.index]) continue;
    cur_.map_point[match.index] = m;
    cur_.match_distance[match.index] = match.distance;
  }
  int matches = 0;
  for (std::size_t j = 0; j < cur_.map_point.size(); ++j) matches += cur_.map_point[j] >= 0;
  return matches;
}

// Projects the points of the local keyframes (and of the relocalisation anchor) not matched yet.
int OrbStereoOdometry::searchLocalMap(const CameraPoseEstimate& pose) {
  const int stamp = map_.nextStamp();
  for (std::size_t j = 0; j < cur_.map_point.size(); ++j) {
    const int m = cur_.map_point[j];
    cur_.available[j] = m < 0;
    if (m >= 0) map_.point(m).visit_stamp = stamp;
  }
  const int local = std::min(config_.local_keyframes, map_.keyframeCount());
  for (int age = 0; age < local; ++age) searchKeyframePoints(map_.keyframe(age), pose, stamp);
  if (anchor_keyframe_id_ >= 0 && map_.keyframeCount() > 0) {
    const int newest_id = map_.keyframe(0).id;
    if (newest_id >= anchor_until_keyframe_id_) {
      anchor_keyframe_id_ = -1;
    } else {
      constexpr int kAnchorNeighbours = 2;
      for (int id = anchor_keyframe_id_ - kAnchorNeighbours;
           id <= anchor_keyframe_id_ + kAnchorNeighbours; ++id) {
        const int age = newest_id - id;
        if (age < local || age >= map_.keyframeCount() || map_.keyframe(age).id != id) continue;
        searchKeyframePoints(map_.keyframe(age), pose, stamp);
      }
    }
  }
  int matches = 0;
  for (std::size_t j = 0; j < cur_.map_point.size(); ++j) matches += cur_.map_point[j] >= 0;
  return matches;
}

void OrbStereoOdometry::searchKeyframePoints(const Keyframe& kf, const CameraPoseEstimate& pose,
                                             int stamp) {
  for (const int m : kf.map_point) {
    if (m < 0) continue;
    MapPoint& point = map_.point(m);
    if (!point.alive || point.visit_stamp == stamp) continue;
    point.visit_stamp = stamp;
    const Eigen::Vector3d p_in_cam_m =
        pose.R_cam_world * point.p_in_world_m + pose.p_world_in_cam_m;
    if (p_in_cam_m.z() < kMinProjectionDepthM) continue;
    const Eigen::Vector2d uv = projectLeft(rig_, p_in_cam_m);
    if (!insideImage(rig_, uv)) continue;
    const ProjectionMatch match = searchNearProjection(
        grid_, cur_.features, cur_.descriptors, cur_.available, level_scale_.data(), uv,
        point.level, point.descriptor, config_.map_search);
    if (match.index < 0 || match.distance >= cur_.match_distance[match.index]) continue;
    cur_.map_point[match.index] = m;
    cur_.match_distance[match.index] = match.distance;
  }
}

// Pose from the current associations; drops the associations that end as outliers.
bool OrbStereoOdometry::estimatePose(PoseStart start, CameraPoseEstimate* pose) {
  observations_.clear();
  observation_feature_.clear();
  for (std::size_t j = 0; j < cur_.map_point.size(); ++j) {
    const int m = cur_.map_point[j];
    if (m < 0) continue;
    const OrbFeature& f = cur_.features[j];
    PoseObservation o;
    o.p_in_world_m = map_.point(m).p_in_world_m;
    o.uv_px = {f.u_px, f.v_px};
    o.u_right_px = cur_.u_right_px[j];
    o.sigma_px = sigmaOfLevel(f.level);
    observations_.push_back(o);
    observation_feature_.push_back(static_cast<int>(j));
  }
  int n = static_cast<int>(observations_.size());
  if (n < config_.refiner.min_inliers) return false;
  CameraPoseEstimate estimate = *pose;
  if (start != PoseStart::kGiven) {
    pnp_.clear();
    for (const PoseObservation& o : observations_) pnp_.add(o.p_in_world_m, o.uv_px);
    if (pnp_.solve(rig_, config_.pnp, &estimate, inlier_.data())) {
      // Keep the RANSAC inliers only.
      int kept = 0;
      for (int k = 0; k < n; ++k) {
        if (inlier_[k]) {
          observations_[kept] = observations_[k];
          observation_feature_[kept] = observation_feature_[k];
          ++kept;
        } else {
          cur_.map_point[observation_feature_[k]] = -1;
        }
      }
      n = kept;
    } else if (start == PoseStart::kRansacOnly) {
      return false;
    }  // else RANSAC failed: start from the given pose, the Huber loss and the gates must cope
  }
  if (!refineCameraPose(rig_, config_.refiner, observations_.data(), n, inlier_.data(), &estimate))
    return false;
  for (int k = 0; k < n; ++k) {
    const int j = observation_feature_[k];
    if (!inlier_[k]) cur_.map_point[j] = -1;
  }
  for (std::size_t j = 0; j < cur_.map_point.size(); ++j) {
    if (cur_.map_point[j] < 0) cur_.match_distance[j] = std::numeric_limits<int>::max();
  }
  *pose = estimate;
  cur_.tracked = estimate.inliers;
  return true;
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
  makeThumbnail(cur_left_, &thumbnail_scratch_, kf.thumbnail.data());
  frames_since_keyframe_ = 0;
  keyframe_inserted_ = true;
  if (map_.keyframeCount() >= 2) bundleAdjustLocalWindow();
}

void OrbStereoOdometry::bundleAdjustLocalWindow() {
  const int window = std::min(config_.local_keyframes, map_.keyframeCount());
  const int stamp = map_.nextStamp();
  int n_points = 0;
  int n_obs = 0;
  const int max_entries = static_cast<int>(ba_observations_.size());
  for (int c = 0; c < window; ++c) {
    const int age = window - 1 - c;  // camera 0 is the oldest keyframe of the window: fixed
    const Keyframe& kf = map_.keyframe(age);
    ba_R_[c] = kf.R_cam_world;
    ba_t_[c] = kf.p_world_in_cam_m;
    for (std::size_t f = 0; f < kf.map_point.size() && n_obs < max_entries; ++f) {
      const int m = kf.map_point[f];
      if (m < 0) continue;
      MapPoint& point = map_.point(m);
      if (!point.alive) continue;
      if (point.visit_stamp != stamp) {
        point.visit_stamp = stamp;
        point.ba_index = n_points;
        ba_points_[n_points] = point.p_in_world_m;
        ba_point_id_[n_points] = m;
        ++n_points;
      }
      BaObservation& o = ba_observations_[n_obs];
      o.camera = c;
      o.point = point.ba_index;
      o.uv_px = {kf.features[f].u_px, kf.features[f].v_px};
      o.u_right_px = kf.u_right_px[f];
      o.sigma_px = sigmaOfLevel(kf.features[f].level);
      ba_source_age_[n_obs] = age;
      ba_source_feature_[n_obs] = static_cast<int>(f);
      ++n_obs;
    }
  }
  BundleAdjusterSummary summary;
  if (!bundle_adjuster_.optimise(rig_, config_.bundle, window, 1, ba_R_.data(), ba_t_.data(),
                                 n_points, ba_points_.data(), n_obs, ba_observations_.data(),
                                 ba_outlier_.data(), &summary)) {
    return;
  }
  for (int c = 1; c < window; ++c) {
    Keyframe& kf = map_.keyframe(window - 1 - c);
    kf.R_cam_world = ba_R_[c];
    kf.p_world_in_cam_m = ba_t_[c];
  }
  for (int j = 0; j < n_points; ++j) map_.point(ba_point_id_[j]).p_in_world_m = ba_points_[j];
  for (int k = 0; k < n_obs; ++k) {
    if (!ba_outlier_[k]) continue;
    Keyframe& kf = map_.keyframe(ba_source_age_[k]);
    const int f = ba_source_feature_[k];
    const int m = kf.map_point[f];
    if (m < 0) continue;
    kf.map_point[f] = -1;
    if (ba_source_age_[k] == 0) cur_.map_point[f] = -1;  // the newest keyframe is the current frame
    map_.releaseReference(m);
  }
  const Keyframe& newest = map_.keyframe(0);
  cur_.pose.R_cam_world = newest.R_cam_world;
  cur_.pose.p_world_in_cam_m = newest.p_world_in_cam_m;
}

// Number of query features (every stride-th) with a ratio-test match among the keyframe's map
// points.
int OrbStereoOdometry::rankKeyframe(const Keyframe& kf, int stride) const {
  int score = 0;
  for (std::size_t j = 0; j < cur_.features.size(); j += stride) {
    int best = std::numeric_limits<int>::max();
    int second = std::numeric_limits<int>::max();
    for (std::size_t f = 0; f < kf.map_point.size(); ++f) {
      if (kf.map_point[f] < 0) continue;
      const int d = hammingDistance(cur_.descriptors[j], kf.descriptors[f]);
      if (d < best) {
        second = best;
        best = d;
      } else if (d < second) {
        second = d;
      }
    }
    score += best <= config_.reloc_max_hamming && best < config_.reloc_ratio * second;
  }
  return score;
}

// Brute-force ratio-test matching of every current feature against the keyframe's map points; each
// keyframe feature keeps its best current feature. Returns the number of associations made.
int OrbStereoOdometry::matchKeyframe(const Keyframe& kf) {
  clearAssociations();
  const int nk = static_cast<int>(kf.map_point.size());
  std::fill_n(reloc_owner_.begin(), nk, -1);
  for (std::size_t j = 0; j < cur_.features.size(); ++j) {
    int best = std::numeric_limits<int>::max();
    int second = std::numeric_limits<int>::max();
    int best_f = -1;
    for (int f = 0; f < nk; ++f) {
      const int m = kf.map_point[f];
      if (m < 0 || !map_.point(m).alive) continue;
      const int d = hammingDistance(cur_.descriptors[j], kf.descriptors[f]);
      if (d < best) {
        second = best;
        best = d;
        best_f = f;
      } else if (d < second) {
        second = d;
      }
    }
    if (best_f < 0 || best > config_.reloc_max_hamming || best >= config_.reloc_ratio * second)
      continue;
    if (reloc_owner_[best_f] < 0 || best < reloc_owner_distance_[best_f]) {
      reloc_owner_[best_f] = static_cast<int>(j);
      reloc_owner_distance_[best_f] = best;
    }
  }
  int matches = 0;
  for (int f = 0; f < nk; ++f) {
    const int j = reloc_owner_[f];
    if (j < 0) continue;
    cur_.map_point[j] = kf.map_point[f];
    cur_.match_distance[j] = reloc_owner_distance_[f];
    ++matches;
  }
  return matches;
}

bool OrbStereoOdometry::relocalise() {
  const int n_kf = map_.keyframeCount();
  const int n = static_cast<int>(cur_.features.size());
  if (n_kf == 0 || n < config_.reloc_min_inliers) return false;
  grid_.build(cur_.features);
  // Thumbnails rank every keyframe cheaply; descriptors rank the most similar few.
  makeThumbnail(cur_left_, &thumbnail_scratch_, thumbnail_.data());
  for (int age = 0; age < n_kf; ++age) {
    reloc_similarity_[age] =
        thumbnailSimilarity(thumbnail_.data(), map_.keyframe(age).thumbnail.data());
    reloc_score_[age] = -1;
  }
  const int stride = std::max(1, n / config_.reloc_query_features);
  for (int k = 0; k < std::min(config_.reloc_thumbnail_candidates, n_kf); ++k) {
    const int age = static_cast<int>(
        std::max_element(reloc_similarity_.begin(), reloc_similarity_.begin() + n_kf) -
        reloc_similarity_.begin());
    reloc_similarity_[age] = -2.0f;
    reloc_score_[age] = rankKeyframe(map_.keyframe(age), stride);
  }
  for (int attempt = 0; attempt < std::min(config_.reloc_candidates, n_kf); ++attempt) {
    const int age = static_cast<int>(
        std::max_element(reloc_score_.begin(), reloc_score_.begin() + n_kf) - reloc_score_.begin());
    if (reloc_score_[age] * stride < config_.reloc_min_inliers / 2) break;
    reloc_score_[age] = -1;
    const Keyframe& kf = map_.keyframe(age);
    if (matchKeyframe(kf) < config_.reloc_min_inliers) continue;
    CameraPoseEstimate pose;
    pose.R_cam_world = kf.R_cam_world;
    pose.p_world_in_cam_m = kf.p_world_in_cam_m;
    // RANSAC must succeed here: there is no motion prior to fall back on.
    if (!estimatePose(PoseStart::kRansacOnly, &pose)) continue;
    anchor_keyframe_id_ = kf.id;
    anchor_until_keyframe_id_ = map_.keyframe(0).id + config_.local_keyframes;
    searchLocalMap(pose);
    completeStereo(pose);
    if (!estimatePose(PoseStart::kGiven, &pose) || cur_.tracked < config_.reloc_min_inliers)
      continue;
    cur_.pose = pose;
    return true;
  }
  anchor_keyframe_id_ = -1;
  clearAssociations();
  return false;
}

}  // namespace deepnav
