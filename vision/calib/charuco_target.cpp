#include "vision/calib/charuco_target.h"

#include "vision/markers/aruco_dictionary.h"

namespace deepnav {

bool validateCharucoTarget(const CharucoTarget& t, std::string* error) {
  auto fail = [&](const std::string& what) {
    if (error) *error = what;
    return false;
  };
  if (t.squares_x < 3 || t.squares_y < 3) return fail("squares_x and squares_y must be at least 3");
  if (!(t.square_m > 0.0)) return fail("square_m must be positive");
  if (!(t.marker_m > 0.0 && t.marker_m < t.square_m))
    return fail("marker_m must be positive and smaller than square_m (" + std::to_string(t.square_m) + ")");
  int dictionary_id = 0;
  if (!arucoDictionaryFromName(t.dictionary, &dictionary_id))
    return fail("dictionary '" + t.dictionary + "' is not an OpenCV predefined dictionary (e.g. DICT_5X5_100)");
  const int markers = t.squares_x * t.squares_y / 2;
  if (markers > arucoDictionarySize(dictionary_id))
    return fail("dictionary " + t.dictionary + " holds " + std::to_string(arucoDictionarySize(dictionary_id)) +
                " markers; a " + std::to_string(t.squares_x) + " x " + std::to_string(t.squares_y) + " board needs " +
                std::to_string(markers));
  if (t.min_corners < 6) return fail("min_corners must be at least 6");
  return true;
}

cv::Ptr<cv::aruco::CharucoBoard> makeCharucoBoard(const CharucoTarget& t) {
  if (!validateCharucoTarget(t, nullptr)) return nullptr;
  int dictionary_id = 0;
  arucoDictionaryFromName(t.dictionary, &dictionary_id);
  const auto dictionary = cv::aruco::getPredefinedDictionary(dictionary_id);
  return cv::aruco::CharucoBoard::create(t.squares_x, t.squares_y, static_cast<float>(t.square_m),
                                         static_cast<float>(t.marker_m), dictionary);
}

}  // namespace deepnav
