#include "nav/types/vo_measurement.h"

namespace deepnav {

const char* toString(VoSource source) {
  switch (source) {
    case VoSource::kNone: return "none";
    case VoSource::kOrb: return "orb";
    case VoSource::kPlanes: return "planes";
  }
  return "unknown";
}

}  // namespace deepnav
