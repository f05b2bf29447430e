#pragma once
#include <string>

namespace deepnav {

// OpenCV predefined ArUco dictionary (cv::aruco::PREDEFINED_DICTIONARY_NAME) of a name such as
// "DICT_4X4_50" or "DICT_APRILTAG_36h11", the spelling of the enum. False for an unknown name.
bool arucoDictionaryFromName(const std::string& name, int* dictionary_id);

// Number of codes of a predefined dictionary (ids are 0 .. size-1); 0 for an unknown id.
int arucoDictionarySize(int dictionary_id);

}  // namespace deepnav
