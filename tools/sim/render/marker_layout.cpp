#include "tools/sim/render/marker_layout.h"

#include <array>
#include <set>
#include <utility>

#include "tools/sim/render/panel_faces.h"

namespace deepnav::sim {

MarkerLayout defaultMarkerLayout() {
  MarkerLayout layout;
  // At the dive's dwell the cameras are 0.9 m from the face centre, 1.3 m above the seabed, the left
  // one 0.15 m left of the centre line: the left image covers s in [-0.59, 0.29] m, z in [0.97, 1.63] m
  // of the face, the right one s in [-0.29, 0.59] m. The markers sit in two columns at s = +-0.42 m,
  // z = 1.15 m and 1.38 m (1.5 m panel): two in each image at the dwell, margins >= 7 cm for the
  // disturbances, all four from farther away; the hardware stays between the columns.
  layout.spots = {{0, 0, -0.42, 0.92}, {1, 0, 0.42, 0.92}, {2, 0, -0.42, 0.767}, {3, 0, 0.42, 0.767},
                  {4, 1, -0.42, 0.92}, {5, 1, 0.42, 0.92}, {6, 1, -0.42, 0.767}, {7, 1, 0.42, 0.767},
                  // Plain face: one marker per image at the dwell, the rest of the face stays bare.
                  {8, 2, -0.42, 0.867}, {9, 2, 0.42, 0.767}};
  return layout;
}

cv::Ptr<cv::aruco::Dictionary> arucoDictionaryByName(const std::string& name) {
  using cv::aruco::PREDEFINED_DICTIONARY_NAME;
  static const std::array<std::pair<const char*, PREDEFINED_DICTIONARY_NAME>, 21> kNames{{
      {"DICT_4X4_50", cv::aruco::DICT_4X4_50},       {"DICT_4X4_100", cv::aruco::DICT_4X4_100},
      {"DICT_4X4_250", cv::aruco::DICT_4X4_250},     {"DICT_4X4_1000", cv::aruco::DICT_4X4_1000},
      {"DICT_5X5_50", cv::aruco::DICT_5X5_50},       {"DICT_5X5_100", cv::aruco::DICT_5X5_100},
      {"DICT_5X5_250", cv::aruco::DICT_5X5_250},     {"DICT_5X5_1000", cv::aruco::DICT_5X5_1000},
      {"DICT_6X6_50", cv::aruco::DICT_6X6_50},       {"DICT_6X6_100", cv::aruco::DICT_6X6_100},
      {"DICT_6X6_250", cv::aruco::DICT_6X6_250},     {"DICT_6X6_1000", cv::aruco::DICT_6X6_1000},
      {"DICT_7X7_50", cv::aruco::DICT_7X7_50},       {"DICT_7X7_100", cv::aruco::DICT_7X7_100},
      {"DICT_7X7_250", cv::aruco::DICT_7X7_250},     {"DICT_7X7_1000", cv::aruco::DICT_7X7_1000},
      {"DICT_ARUCO_ORIGINAL", cv::aruco::DICT_ARUCO_ORIGINAL},
      {"DICT_APRILTAG_16h5", cv::aruco::DICT_APRILTAG_16h5},
      {"DICT_APRILTAG_25h9", cv::aruco::DICT_APRILTAG_25h9},
      {"DICT_APRILTAG_36h10", cv::aruco::DICT_APRILTAG_36h10},
      {"DICT_APRILTAG_36h11", cv::aruco::DICT_APRILTAG_36h11},
  }};
  for (const auto& [n, id] : kNames) {
    if (name == n) return cv::aruco::getPredefinedDictionary(id);
  }
  return nullptr;
}

bool validateMarkerLayout(const MarkerLayout& layout, const PanelGeometry& panel, std::string* error) {
  const auto fail = [&](const std::string& m) {
    if (error) *error = "marker layout: " + m;
    return false;
  };
  const cv::Ptr<cv::aruco::Dictionary> dict = arucoDictionaryByName(layout.dictionary);
  if (!dict) return fail("unknown ArUco dictionary '" + layout.dictionary + "'");
  if (!(layout.marker_size_m > 0.0) || !(layout.quiet_zone_m >= 0.0))
    return fail("marker_size_m must be > 0 and quiet_zone_m >= 0");
  const auto faces = panelFaces(panel);
  const double half_extent = 0.5 * layout.marker_size_m + layout.quiet_zone_m;
  std::set<int> ids;
  for (const MarkerSpot& spot : layout.spots) {
    const std::string which = "marker " + std::to_string(spot.id);
    if (spot.id < 0 || spot.id >= dict->bytesList.rows) return fail(which + " is not in " + layout.dictionary);
    if (!ids.insert(spot.id).second) return fail(which + " appears twice");
    if (spot.face < 0 || spot.face >= kPanelFaceCount) return fail(which + ": face must be 0, 1 or 2");
    const FaceFrame& f = faces[spot.face];
    const double s = spot.s_fraction * f.half_width_m, z = spot.z_fraction * f.height_m;
    if (s - half_extent < f.s_min_m || s + half_extent > f.s_max_m || z - half_extent < 0.0 ||
        z + half_extent > f.height_m)
      return fail(which + " (with its quiet zone) does not fit on the flat part of face " + f.name);
  }
  return true;
}

}  // namespace deepnav::sim
