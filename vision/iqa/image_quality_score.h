#pragma once
#include "vision/iqa/mdm.h"

namespace deepnav {

// Combined image quality m̄_I(t) of the DexROV navigation paper (IROS 2019, "image quality
// assessment"): the mean of the three normalised MDM features (f1, f2, f3/8) and the ORB tracking
// ratio min(1, tracked_orb / orb_max). The ORB term makes the score fall when the scene has no
// texture the visual odometry can use, which MDM's global contrast alone cannot see.
// Result in [0, 1]; orb_max <= 0 or tracked_orb <= 0 give a zero ORB term.
double imageQualityScore(const MdmScore& mdm, int tracked_orb, int orb_max);

}  // namespace deepnav
