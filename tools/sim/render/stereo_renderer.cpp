#include "tools/sim/render/stereo_renderer.h"

#include <algorithm>
#include <cmath>

#include "tools/sim/render/panel_knowledge.h"
#include "tools/sim/render/procedural_noise.h"

namespace deepnav::sim {

namespace {
constexpr double kMarkerCornerInset = 0.02;
constexpr float kCornerHitTolerance_m = 0.002f;

Eigen::Vector3d squareCorner(int k, double size_m) {
  const double h = 0.5 * size_m;
  const double xs[4] = {-h, h, h, -h}, ys[4] = {h, h, -h, -h};
  return Eigen::Vector3d(xs[k], ys[k], 0.0);
}
}  // namespace

bool StereoRenderer::init(const Scenario& scenario, std::uint64_t seed, int channels, std::string* error) {
  return init(scenario, defaultMarkerLayout(), seed, channels, error);
}

bool StereoRenderer::init(const Scenario& scenario, const MarkerLayout& layout, std::uint64_t seed, int channels,
                          std::string* error) {
  initialised_ = false;
  if (channels != 1 && channels != 3) {
    if (error) *error = "renderer: channels must be 1 (grey) or 3 (BGR), got " + std::to_string(channels);
    return false;
  }
  if (scenario.panel.markers_enabled && !validateMarkerLayout(layout, scenario.panel, error)) return false;
  scenario_ = scenario;
  seed_ = seed;
  channels_ = channels;
  panel_ = makePanelDescription(scenario, layout);
  optics_ = waterOptics(scenario.water.preset);
  if (!scene_.init(scenario, panel_, layout.quiet_zone_m, seed, error)) return false;
  effects_ = deepnav::sim::waterEffects(scenario.water, optics_);
  plumes_.init(scenario.water.plumes, scene_.T_odom_panel(), scenario.water.current_mps);
  snow_.init(scenario.water, scene_.T_odom_panel(), seed);
  const int w = scenario.camera.width_px, h = scenario.camera.height_px;
  has_port_ = scenario.camera.flat_port;
  if (has_port_) {
    if (!port_.init(scenario.camera, scenario.camera.port, error)) return false;
    port_radiance_.create(h, w, CV_32FC(channels));
    pinhole_depth_left_m_.create(h, w, CV_32F);
    pinhole_depth_right_m_.create(h, w, CV_32F);
  }
  const CameraConfig& view_camera = has_port_ ? port_.pinhole() : scenario.camera;
  if (!view_left_.init(view_camera, channels, optics_, &scene_, error) ||
      !view_right_.init(view_camera, channels, optics_, &scene_, error))
    return false;
  if (effects_.any()) {
    view_left_.setWater(effects_, &plumes_);
    view_right_.setWater(effects_, &plumes_);
  }
  if (!sensor_.init(w, h, channels, optics_, seed)) {
    if (error) *error = "renderer: camera sensor init failed";
    return false;
  }
  sensor_.setSensor(scenario.camera.noise_model, scenario.camera.sensor);
  has_blur_ = scenario.camera.motion_blur;
  if (has_blur_ && (!blur_left_.init(view_camera, channels) || !blur_right_.init(view_camera, channels))) {
    if (error) *error = "renderer: motion blur init failed";
    return false;
  }
  if (!rig_.init(scenario.camera, error)) return false;
  radiance_left_.assign(static_cast<std::size_t>(w) * h * channels, 0.0f);
  radiance_right_.assign(static_cast<std::size_t>(w) * h * channels, 0.0f);
  depth_scratch_left_.assign(static_cast<std::size_t>(w) * h, 0.0f);
  depth_scratch_right_.assign(static_cast<std::size_t>(w) * h, 0.0f);
  initialised_ = true;
  return true;
}

void StereoRenderer::allocateTruth(RenderTruth* truth) const {
  const int w = scenario_.camera.width_px, h = scenario_.camera.height_px;
  truth->depth_m.create(h, w, CV_32F);
  truth->disparity_px.create(h, w, CV_32F);
  truth->right_depth_m.create(h, w, CV_32F);
  truth->visible_marker_ids.reserve(panel_.markers.size());
}

ViewPose StereoRenderer::leftView(const CameraTick& tick) const {
  const Eigen::Isometry3d T_panel_odom = scene_.T_odom_panel().inverse();
  ViewPose v;
  v.R_panel_cam = (T_panel_odom.linear() * tick.q_odom_left_cam.toRotationMatrix()).cast<float>();
  v.p_cam_in_panel_m = (T_panel_odom * tick.p_left_cam_in_odom_m).cast<float>();
  return v;
}

ViewPose StereoRenderer::rightView(const CameraTick& tick) const {
  const Eigen::Isometry3d T_panel_odom = scene_.T_odom_panel().inverse();
  ViewPose v;
  v.R_panel_cam = (T_panel_odom.linear() * tick.q_odom_right_cam.toRotationMatrix()).cast<float>();
  v.p_cam_in_panel_m = (T_panel_odom * tick.p_right_cam_in_odom_m).cast<float>();
  return v;
}

LampSet StereoRenderer::lamps(const ViewPose& left) const {
  const float b = static_cast<float>(scenario_.camera.baseline_m);
  const WaterConfig& w = scenario_.water;
  const float outside = static_cast<float>(w.lamp_outside_m), above = static_cast<float>(w.lamp_above_m);
  const float forward = static_cast<float>(w.lamp_forward_m);
  const Eigen::Vector3f in_cam[2] = {Eigen::Vector3f(-outside, -above, forward),
                                     Eigen::Vector3f(b + outside, -above, forward)};
  LampSet lamps;
  for (int k = 0; k < 2; ++k) lamps.p_lamp_in_panel_m[k] = left.p_cam_in_panel_m + left.R_panel_cam * in_cam[k];
  lamps.axis_in_panel = left.R_panel_cam.col(2);
  return lamps;
}

std::uint64_t StereoRenderer::frameKey(const CameraTick& tick, int camera) const {
  const std::uint32_t t_lo = static_cast<std::uint32_t>(tick.t_us), t_hi = static_cast<std::uint32_t>(tick.t_us >> 32);
  const std::uint64_t a = hashU32(static_cast<std::uint32_t>(seed_), t_lo, static_cast<std::uint32_t>(camera));
  const std::uint64_t b = hashU32(static_cast<std::uint32_t>(seed_ >> 32), t_hi, static_cast<std::uint32_t>(a));
  return (a << 32) | b;
}

bool StereoRenderer::checkFrame(const StereoFrame& frame) const {
  const int type = channels_ == 1 ? CV_8UC1 : CV_8UC3;
  const cv::Size size(scenario_.camera.width_px, scenario_.camera.height_px);
  return frame.left.type() == type && frame.right.type() == type && frame.left.size() == size &&
         frame.right.size() == size && frame.left.isContinuous() && frame.right.isContinuous();
}

bool StereoRenderer::render(const CameraTick& tick, StereoFrame* frame, RenderTruth* truth) {
  if (!initialised_ || frame == nullptr || !checkFrame(*frame)) return false;
  const cv::Size size(scenario_.camera.width_px, scenario_.camera.height_px);
  if (truth && (truth->depth_m.size() != size || truth->depth_m.type() != CV_32F || truth->disparity_px.size() != size ||
                truth->disparity_px.type() != CV_32F || truth->right_depth_m.size() != size ||
                truth->right_depth_m.type() != CV_32F))
    return false;
  const double t_s = static_cast<double>(tick.t_us) * 1e-6;
  scene_.setTime(t_s);
  if (effects_.plumes) plumes_.setTime(t_s);
  const ViewPose left = leftView(tick), right = rightView(tick);
  const LampSet lamp_set = lamps(left);
  if (scene_.hasArm()) placeArm(left, tick);
  float* depth_left = truth ? truth->depth_m.ptr<float>() : depth_scratch_left_.data();
  float* depth_right = truth ? truth->right_depth_m.ptr<float>() : depth_scratch_right_.data();
  view_left_.begin(left, lamp_set, radiance_left_.data(), has_port_ ? pinhole_depth_left_m_.ptr<float>() : depth_left);
  view_right_.begin(right, lamp_set, radiance_right_.data(),
                    has_port_ ? pinhole_depth_right_m_.ptr<float>() : depth_right);
  if (right_thread_) {
    RightViewThread& worker = *right_thread_;
    {
      const std::lock_guard<std::mutex> lock(worker.mutex);
      ++worker.posted;
    }
    worker.wake.notify_all();
    for (int row = 0; row < view_left_.tileRows(); ++row) view_left_.renderTileRow(row);
    std::unique_lock<std::mutex> lock(worker.mutex);
    worker.wake.wait(lock, [&] { return worker.done == worker.posted; });
  } else {
    for (int row = 0; row < view_left_.tileRows(); ++row) {
      view_left_.renderTileRow(row);
      view_right_.renderTileRow(row);
    }
  }
  if (effects_.any() || snow_.enabled())
    finishWater(t_s, left, right, lamp_set, has_port_ ? pinhole_depth_left_m_.ptr<float>() : depth_left,
                has_port_ ? pinhole_depth_right_m_.ptr<float>() : depth_right);
  if (has_port_) {
    throughPort(radiance_left_.data(), pinhole_depth_left_m_, depth_left);
    throughPort(radiance_right_.data(), pinhole_depth_right_m_, depth_right);
  }
  const float gain = sensor_.autoExposureGain(radiance_left_.data());
  if (has_blur_) {
    const float exposure_s = sensor_.exposureFor(gain).time_s;
    blur_left_.apply(radiance_left_.data(), depth_left, tick.v_left_cam_mps, tick.w_cam_radps, exposure_s);
    blur_right_.apply(radiance_right_.data(), depth_right, tick.v_right_cam_mps, tick.w_cam_radps, exposure_s);
  }
  if (has_blur_ || scenario_.camera.noise_model != SensorNoiseModel::kWaterPreset)
    frame->exposure_us = static_cast<std::uint32_t>(std::lround(1e6 * sensor_.exposureFor(gain).time_s));
  sensor_.expose(radiance_left_.data(), gain, frameKey(tick, 0), &frame->left);
  sensor_.expose(radiance_right_.data(), gain, frameKey(tick, 1), &frame->right);
  frame->t_us = tick.t_us;
  frame->sequence = tick.frame_index;
  frame->rectified = !has_port_;
  last_gain_ = gain;
  if (truth) {
    const float fb = static_cast<float>(scenario_.camera.fx_px * scenario_.camera.baseline_m);
    const std::size_t n = static_cast<std::size_t>(size.area());
    float* disparity = truth->disparity_px.ptr<float>();
    // Raw flat-port images have no disparity of their own: 0 (unknown) throughout.
    for (std::size_t i = 0; i < n; ++i) disparity[i] = depth_left[i] > 0.0f && !has_port_ ? fb / depth_left[i] : 0.0f;
    visibleMarkers(left, &truth->visible_marker_ids);
  }
  return true;
}

bool StereoRenderer::useSecondThread() {
  if (!initialised_) return false;
  if (right_thread_) return true;
  right_thread_ = std::make_unique<RightViewThread>();
  right_thread_->thread = std::thread([this] { rightViewLoop(); });
  return true;
}

void StereoRenderer::rightViewLoop() {
  RightViewThread& worker = *right_thread_;
  std::unique_lock<std::mutex> lock(worker.mutex);
  for (;;) {
    worker.wake.wait(lock, [&] { return worker.stop || worker.posted != worker.done; });
    if (worker.stop) return;
    lock.unlock();
    for (int row = 0; row < view_right_.tileRows(); ++row) view_right_.renderTileRow(row);
    lock.lock();
    worker.done = worker.posted;
    worker.wake.notify_all();
  }
}

StereoRenderer::~StereoRenderer() {
  if (!right_thread_) return;
  {
    const std::lock_guard<std::mutex> lock(right_thread_->mutex);
    right_thread_->stop = true;
  }
  right_thread_->wake.notify_all();
  right_thread_->thread.join();
}

void StereoRenderer::finishWater(double t_s, const ViewPose& left, const ViewPose& right, const LampSet& lamps,
                                 const float* depth_left, const float* depth_right) {
  view_left_.finishWater();
  view_right_.finishWater();
  if (!snow_.enabled()) return;
  const Eigen::Vector3f rig = 0.5f * (left.p_cam_in_panel_m + right.p_cam_in_panel_m);
  snow_.update(t_s, rig, left.R_panel_cam.col(2), lamps.p_lamp_in_panel_m, lamps.axis_in_panel, optics_,
               effects_.beam);
  const CameraConfig& camera = view_left_.camera();
  snow_.draw(left.R_panel_cam, left.p_cam_in_panel_m, camera, optics_, channels_, radiance_left_.data(), depth_left);
  snow_.draw(right.R_panel_cam, right.p_cam_in_panel_m, camera, optics_, channels_, radiance_right_.data(),
             depth_right);
}

void StereoRenderer::placeArm(const ViewPose& left, const CameraTick& tick) {
  // R_panel_robot = R_panel_cam R_cam_robot; the robot origin is the left camera's lever arm back.
  const Eigen::Matrix3f R_panel_robot = left.R_panel_cam * rig_.R_robot_cam().transpose().cast<float>();
  const Eigen::Vector3f p_robot = left.p_cam_in_panel_m - R_panel_robot * rig_.p_left_cam_in_robot_m().cast<float>();
  scene_.placeArm(R_panel_robot, p_robot, static_cast<double>(tick.t_us) * 1e-6);
}

void StereoRenderer::throughPort(float* radiance_data, const cv::Mat& pinhole_depth_m, float* depth_m) {
  const int w = scenario_.camera.width_px, h = scenario_.camera.height_px;
  cv::Mat radiance(h, w, CV_32FC(channels_), radiance_data);
  cv::Mat depth(h, w, CV_32F, depth_m);
  port_.resample(radiance, pinhole_depth_m, port_radiance_, depth);
  port_radiance_.copyTo(radiance);
}

void StereoRenderer::visibleMarkers(const ViewPose& left, std::vector<int>* ids) const {
  ids->clear();
  const CameraConfig& cam = scenario_.camera;
  const Eigen::Matrix3d R_cam_panel = left.R_panel_cam.transpose().cast<double>();
  const Eigen::Vector3d o = left.p_cam_in_panel_m.cast<double>();
  for (const PanelMarker& m : panel_.markers) {
    const Eigen::Matrix3d R_panel_marker = m.q_panel_marker.toRotationMatrix();
    if (R_panel_marker.col(2).dot(o - m.p_marker_in_panel_m) <= 0.0) continue;  // seen from behind
    bool visible = true;
    for (int k = 0; k < 4 && visible; ++k) {
      const Eigen::Vector3d corner = m.p_marker_in_panel_m + R_panel_marker * squareCorner(k, panel_.marker_size_m);
      const Eigen::Vector3d p_cam = R_cam_panel * (corner - o);
      if (p_cam.z() <= 0.0) {
        visible = false;
        break;
      }
      const double u = cam.fx_px * p_cam.x() / p_cam.z() + cam.cx_px, v = cam.fy_px * p_cam.y() / p_cam.z() + cam.cy_px;
      if (u < 0.0 || v < 0.0 || u > cam.width_px - 1.0 || v > cam.height_px - 1.0) {
        visible = false;
        break;
      }
      const Eigen::Vector3d inset = corner + kMarkerCornerInset * (m.p_marker_in_panel_m - corner);
      const Eigen::Vector3f d = (inset - o).cast<float>();
      SceneHit hit;
      const bool reached = scene_.intersect(o.cast<float>(), d, 1e-4f, 1.0f + 1e-3f, &hit) &&
                           hit.primitive == Scene::faceRect(m.face) &&
                           (1.0f - hit.t) * d.norm() < kCornerHitTolerance_m;
      visible = reached;
    }
    if (visible) ids->push_back(m.id);
  }
  std::sort(ids->begin(), ids->end());
}

}  // namespace deepnav::sim
