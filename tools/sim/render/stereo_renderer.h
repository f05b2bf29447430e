#pragma once
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <Eigen/Core>

#include "nav/markers/panel_description.h"
#include "tools/sim/camera_tick.h"
#include "tools/sim/render/camera_sensor.h"
#include "tools/sim/render/flat_port.h"
#include "tools/sim/render/marine_snow.h"
#include "tools/sim/render/marker_layout.h"
#include "tools/sim/render/motion_blur.h"
#include "tools/sim/render/render_truth.h"
#include "tools/sim/render/scene.h"
#include "tools/sim/render/sediment_plume.h"
#include "tools/sim/render/view_renderer.h"
#include "tools/sim/render/water_optics.h"
#include "tools/sim/scenario.h"
#include "vision/types/stereo_frame.h"

namespace deepnav::sim {

// Renders the rectified stereo pair a CameraTick sees (panel, seabed, fish in the scenario's water),
// and its ground truth. Deterministic: the same scenario, seed and tick give the same images.
// Everything is allocated in init(); render() writes into the caller's preallocated frame
// (allocateStereoFrame(frame, width, height, channels)) and truth (allocateTruth()).
//
//   StereoRenderer renderer;
//   if (!renderer.init(scenario, seed, /*channels=*/1, &error)) die(error);
//   renderer.allocateTruth(&truth);
//   renderer.render(sim.cameraAt(t_us), &frame, &truth);
class StereoRenderer {
 public:
  StereoRenderer() = default;
  StereoRenderer(const StereoRenderer&) = delete;  // owns the optional second thread
  StereoRenderer& operator=(const StereoRenderer&) = delete;
  ~StereoRenderer();  // stops the second thread
  // channels: 1 (grey, CV_8UC1) or 3 (BGR, CV_8UC3), as the board's camera.channels.
  bool init(const Scenario& scenario, std::uint64_t seed, int channels, std::string* error);
  bool init(const Scenario& scenario, const MarkerLayout& layout, std::uint64_t seed, int channels,
            std::string* error);
  void allocateTruth(RenderTruth* truth) const;

  // Draws the pair seen from the tick's camera poses (odometry frame) into *frame (t_us, sequence =
  // frame_index, rectified = true) and, when truth is not null, fills it. False when the frame or the
  // truth does not have the configured size and type.
  bool render(const CameraTick& tick, StereoFrame* frame, RenderTruth* truth);

  // Renders the right view on a second thread while the calling thread renders the left one (the two
  // views share only the read-only scene): the same images, bit for bit, in about half the wall time
  // on two free cores. The thread is started here (call after init()) and lives with the renderer;
  // render() still allocates nothing. False if the renderer is not initialised.
  bool useSecondThread();

  // The knowledge base of the rendered panel (same as makePanelDescription(scenario, layout)).
  const PanelDescription& panel() const { return panel_; }
  const Scene& scene() const { return scene_; }
  const WaterOptics& optics() const { return optics_; }
  const WaterEffects& waterEffects() const { return effects_; }
  // Marine snow after the last render() (tests).
  const MarineSnow& snow() const { return snow_; }
  // Camera poses of a tick in the panel frame.
  ViewPose leftView(const CameraTick& tick) const;
  ViewPose rightView(const CameraTick& tick) const;
  // The lamps: two, water.lamp_outside_m (0.25 m) outside each camera, lamp_above_m (0.2 m) above and
  // lamp_forward_m (0) ahead of the optical centres, aimed along the left optical axis.
  LampSet lamps(const ViewPose& left) const;
  // The auto-exposure gain of the last frame (camera_sensor.h).
  float lastGain() const { return last_gain_; }
  // Markers visible in the left camera (see RenderTruth), ascending ids, into *ids (cleared first).
  void visibleMarkers(const ViewPose& left, std::vector<int>* ids) const;

 private:
  bool checkFrame(const StereoFrame& frame) const;
  std::uint64_t frameKey(const CameraTick& tick, int camera) const;

  Scenario scenario_;
  PanelDescription panel_;
  Scene scene_;
  WaterOptics optics_;
  WaterEffects effects_;  // deep-sea terms of the water keys, all off by default
  SedimentPlumes plumes_;
  MarineSnow snow_;
  ViewRenderer view_left_, view_right_;  // rendered band by band alternately (ViewRenderer::begin)
  CameraSensor sensor_;
  std::uint64_t seed_ = 0;
  int channels_ = 1;
  std::vector<float> radiance_left_, radiance_right_;
  std::vector<float> depth_scratch_left_, depth_scratch_right_;  // when the caller wants no truth
  float last_gain_ = 1.0f;
  bool initialised_ = false;
  // camera.port flat: the view is rendered as a pinhole of focal x n_water, then resampled through the
  // port (render/flat_port.h) before the sensor.
  bool has_port_ = false;
  FlatPortResampler port_;
  cv::Mat port_radiance_;
  cv::Mat pinhole_depth_left_m_, pinhole_depth_right_m_;

  void throughPort(float* radiance, const cv::Mat& pinhole_depth_m, float* depth_m);

  // camera.motion_blur (motion_blur.h), camera.arm (scene.h): the robot's pose from the left camera's.
  bool has_blur_ = false;
  MotionBlur blur_left_, blur_right_;
  CameraRig rig_;
  void placeArm(const ViewPose& left, const CameraTick& tick);
  // The deep-sea terms drawn after both views' bands: forward-scatter blur, then marine snow.
  void finishWater(double t_s, const ViewPose& left, const ViewPose& right, const LampSet& lamps,
                   const float* depth_left, const float* depth_right);

  // The second thread: renders view_right_ (already begun) each time render() posts a frame.
  struct RightViewThread {
    std::thread thread;
    std::mutex mutex;
    std::condition_variable wake;
    std::uint64_t posted = 0, done = 0;  // frames handed over and finished
    bool stop = false;
  };
  std::unique_ptr<RightViewThread> right_thread_;
  void rightViewLoop();
};

}  // namespace deepnav::sim
