#include "vision/pipeline/modality_selector.h"

namespace deepnav {

bool parseVoMode(const std::string& text, VoMode* mode) {
  static constexpr struct {
    const char* name;
    VoMode mode;
  } kModes[] = {{"adaptive", VoMode::kAdaptive}, {"all", VoMode::kAll}, {"orb", VoMode::kOrb},
                {"planes", VoMode::kPlanes}, {"none", VoMode::kNone}};
  for (const auto& m : kModes) {
    if (text == m.name) {
      *mode = m.mode;
      return true;
    }
  }
  return false;
}

const char* toString(VoMode mode) {
  switch (mode) {
    case VoMode::kAdaptive: return "adaptive";
    case VoMode::kAll: return "all";
    case VoMode::kOrb: return "orb";
    case VoMode::kPlanes: return "planes";
    case VoMode::kNone: return "none";
  }
  return "unknown";
}

bool ModalitySelector::init(const ModalityConfig& config, std::string* error) {
  if (!(config.threshold >= 0.0 && config.threshold <= 1.0) || !(config.hysteresis >= 0.0 && config.hysteresis < 0.5)) {
    if (error) *error = "vision.quality_threshold must be in [0, 1] and vision.quality_hysteresis in [0, 0.5)";
    return false;
  }
  config_ = config;
  current_ = VoSource::kNone;
  return true;
}

VoSource ModalitySelector::select(double image_quality) {
  switch (config_.mode) {
    case VoMode::kNone: return current_ = VoSource::kNone;
    case VoMode::kOrb: return current_ = VoSource::kOrb;
    case VoMode::kPlanes: return current_ = VoSource::kPlanes;
    case VoMode::kAll:
    case VoMode::kAdaptive: break;
  }
  if (image_quality < 0.0) return current_ = VoSource::kNone;
  const double h = current_ == VoSource::kNone ? 0.0 : config_.hysteresis;
  if (current_ == VoSource::kPlanes) {
    current_ = image_quality > config_.threshold + h ? VoSource::kOrb : VoSource::kPlanes;
  } else {
    current_ = image_quality < config_.threshold - h ? VoSource::kPlanes : VoSource::kOrb;
  }
  return current_;
}

}  // namespace deepnav
