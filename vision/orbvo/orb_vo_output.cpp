#include "vision/orbvo/orb_vo_output.h"

namespace deepnav {

const char* toString(OrbVoStatus status) {
  switch (status) {
    case OrbVoStatus::kInitialised:
      return "initialised";
    case OrbVoStatus::kOk:
      return "ok";
    case OrbVoStatus::kLost:
      return "lost";
    case OrbVoStatus::kRelocalised:
      return "relocalised";
  }
  return "unknown";
}

}  // namespace deepnav
