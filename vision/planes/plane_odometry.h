#pragma once
#include <array>
#include <string>

#include "nav/types/time.h"
#include "nav/types/vo_measurement.h"
#include "vision/cloud/organized_cloud.h"
#include "vision/cloud/stereo_geometry.h"
#include "vision/planes/plane_extraction_config.h"
#include "vision/planes/plane_extractor.h"
#include "vision/planes/plane_registration.h"
#include "vision/planes/plane_registration_config.h"
#include "vision/planes/plane_set.h"

namespace deepnav {

struct PlaneOdometryConfig {
  PlaneExtractionConfig extraction;
  PlaneRegistrationConfig registration;
  // A registration further apart than this (capture times) is not a VO step: the chain restarts.
  TimeUs max_gap_us = 1'000'000;
  // A registration of parallel planes only (one face of the panel in view) constrains two of the three
  // rotation axes; when true it is still a measurement, with the unobservable variance about the normal
  // (the paper checks a single plane by the size test only and drops it). Off by default: on the
  // simulated dives the single-plane matches were wrong too often (errors up to 36 deg).
  bool use_partial = false;
};

struct PlaneOdometryOutput {
  int planes = 0;  // extracted in this frame
  PlaneRegistrationResult registration;
  VoMeasurement vo;  // valid when the rotation was observable
};

// The paper's plane VO after the cloud: planes of this frame by region growing, registered to the
// planes of the previous frame (Pathak tests + Davenport q-method), giving the camera motion with its
// covariance. Keeps the previous frame's planes; reset() starts a new chain (after the modality switched
// to ORB, the next plane frame has no predecessor). All buffers sized in init().
class PlaneOdometry {
 public:
  // geometry, rows, cols, step_px: of the cloud grid (StereoCloud::geometry(), rows(), cols(), 1).
  bool init(const PlaneOdometryConfig& config, const StereoGeometry& geometry, int rows, int cols, int step_px,
            std::string* error);
  void reset() { has_previous_ = false; }

  // One frame's (filtered) cloud. Returns true when out->vo holds a relative pose to the previous frame.
  bool process(TimeUs t_us, const OrganizedCloud& cloud, PlaneOdometryOutput* out);

  const PlaneSet& planes() const { return sets_[current_]; }  // of the last processed frame

 private:
  PlaneOdometryConfig config_;
  PlaneExtractor extractor_;
  PlaneRegistrar registrar_;
  std::array<PlaneSet, 2> sets_;
  int current_ = 0;
  bool has_previous_ = false;
  TimeUs previous_t_us_ = 0;
};

}  // namespace deepnav
