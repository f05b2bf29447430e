#pragma once
#include <string>

#include "nav/types/vo_measurement.h"

namespace deepnav {

// Which visual odometry the stage-2 pipeline runs (board key vision.vo_mode).
enum class VoMode {
  kAdaptive,  // the paper's EKF-adaptive: ORB when the image is good, planes when it is poor
  kAll,       // the paper's EKF-all: both on every frame, both fused
  kOrb,       // ORB only
  kPlanes,    // planes only
  kNone,      // no VO (the paper's T_L1: navigation sensors and markers)
};

bool parseVoMode(const std::string& text, VoMode* mode);
const char* toString(VoMode mode);

struct ModalityConfig {
  VoMode mode = VoMode::kAdaptive;
  double threshold = 0.45;  // m_I below it: planes (the paper's threshold)
  // Hysteresis: once on planes, m_I must exceed threshold + hysteresis to return to ORB, and once on
  // ORB it must fall below threshold - hysteresis to go to planes. It keeps a score hovering at the
  // threshold from alternating the modality every frame (each switch costs the plane VO its
  // predecessor frame). 0 gives the paper's bare threshold.
  double hysteresis = 0.02;
  // Adaptive mode: when the ORB VO was chosen but gives no relative pose for the pair (tracking lost,
  // e.g. on the textureless side of the panel while MDM still rates the contrast well), the plane VO
  // runs for that pair instead (beyond the paper, whose threshold alone would leave the pair without VO).
  bool planes_when_orb_lost = true;
};

// The decision of the paper's stage 2, per stereo pair, from m_I(t) (vision/iqa/image_quality_score.h).
class ModalitySelector {
 public:
  bool init(const ModalityConfig& config, std::string* error);
  void reset() { current_ = VoSource::kNone; }
  // The modality for a pair of quality image_quality in [0, 1] (negative: frame unusable -> none).
  VoSource select(double image_quality);
  VoSource current() const { return current_; }
  bool runOrb() const { return config_.mode == VoMode::kAll || config_.mode == VoMode::kOrb || adaptive(); }
  bool runPlanes(VoSource selected) const {
    return config_.mode == VoMode::kAll || config_.mode == VoMode::kPlanes ||
           (adaptive() && selected == VoSource::kPlanes);
  }
  const ModalityConfig& config() const { return config_; }

 private:
  bool adaptive() const { return config_.mode == VoMode::kAdaptive; }
  ModalityConfig config_;
  VoSource current_ = VoSource::kNone;
};

}  // namespace deepnav
