#include "board/config/dense_stereo_range.h"

namespace deepnav {

int sgbmSearchedDisparities(int num_disparities) { return (num_disparities + 15) / 16 * 16; }

bool denseStereoRangeFits(const std::string& method, int width_px, int num_disparities, std::string* why) {
  const bool sgbm = method == "sgbm" || method == "sgbm-wls";
  const int searched = sgbm ? sgbmSearchedDisparities(num_disparities) : num_disparities;
  if (searched < width_px) return true;
  if (why) {
    // The largest admitted range: below the width, and for SGBM a multiple of 16 below it.
    const int largest = sgbm ? (width_px - 1) / 16 * 16 : width_px - 1;
    *why = "a range of " + std::to_string(num_disparities) + " px" +
           (sgbm ? " (searched as " + std::to_string(searched) + ", a multiple of 16)" : std::string()) +
           " reaches the matched image width of " + std::to_string(width_px) + " px; " + method +
           (largest >= 1 ? " admits at most " + std::to_string(largest) + " px on it" : " cannot run on it");
  }
  return false;
}

}  // namespace deepnav
