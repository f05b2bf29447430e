#include "vision/iqa/image_quality_score.h"

#include <algorithm>

namespace deepnav {

double imageQualityScore(const MdmScore& mdm, int tracked_orb, int orb_max) {
  double orb_ratio = 0.0;
  if (orb_max > 0 && tracked_orb > 0) {
    orb_ratio = std::min(1.0, static_cast<double>(tracked_orb) / static_cast<double>(orb_max));
  }
  return (mdm.f1 + mdm.f2 + mdm.f3 + orb_ratio) / 4.0;
}

}  // namespace deepnav
