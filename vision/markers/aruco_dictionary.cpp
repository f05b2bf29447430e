#include "vision/markers/aruco_dictionary.h"

#include <array>
#include <opencv2/aruco/dictionary.hpp>
#include <string_view>

namespace deepnav {
namespace {

struct DictionaryEntry {
  std::string_view name;
  int id;
  int size;
};

// Sizes from the comments of opencv2/aruco/dictionary.hpp (OpenCV 4.6).
constexpr std::array<DictionaryEntry, 21> kDictionaries{{
    {"DICT_4X4_50", cv::aruco::DICT_4X4_50, 50},
    {"DICT_4X4_100", cv::aruco::DICT_4X4_100, 100},
    {"DICT_4X4_250", cv::aruco::DICT_4X4_250, 250},
    {"DICT_4X4_1000", cv::aruco::DICT_4X4_1000, 1000},
    {"DICT_5X5_50", cv::aruco::DICT_5X5_50, 50},
    {"DICT_5X5_100", cv::aruco::DICT_5X5_100, 100},
    {"DICT_5X5_250", cv::aruco::DICT_5X5_250, 250},
    {"DICT_5X5_1000", cv::aruco::DICT_5X5_1000, 1000},
    {"DICT_6X6_50", cv::aruco::DICT_6X6_50, 50},
    {"DICT_6X6_100", cv::aruco::DICT_6X6_100, 100},
    {"DICT_6X6_250", cv::aruco::DICT_6X6_250, 250},
    {"DICT_6X6_1000", cv::aruco::DICT_6X6_1000, 1000},
    {"DICT_7X7_50", cv::aruco::DICT_7X7_50, 50},
    {"DICT_7X7_100", cv::aruco::DICT_7X7_100, 100},
    {"DICT_7X7_250", cv::aruco::DICT_7X7_250, 250},
    {"DICT_7X7_1000", cv::aruco::DICT_7X7_1000, 1000},
    {"DICT_ARUCO_ORIGINAL", cv::aruco::DICT_ARUCO_ORIGINAL, 1024},
    {"DICT_APRILTAG_16h5", cv::aruco::DICT_APRILTAG_16h5, 30},
    {"DICT_APRILTAG_25h9", cv::aruco::DICT_APRILTAG_25h9, 35},
    {"DICT_APRILTAG_36h10", cv::aruco::DICT_APRILTAG_36h10, 2320},
    {"DICT_APRILTAG_36h11", cv::aruco::DICT_APRILTAG_36h11, 587},
}};

}  // namespace

bool arucoDictionaryFromName(const std::string& name, int* dictionary_id) {
  for (const auto& d : kDictionaries) {
    if (d.name == name) {
      *dictionary_id = d.id;
      return true;
    }
  }
  return false;
}

int arucoDictionarySize(int dictionary_id) {
  for (const auto& d : kDictionaries) {
    if (d.id == dictionary_id) return d.size;
  }
  return 0;
}

}  // namespace deepnav
