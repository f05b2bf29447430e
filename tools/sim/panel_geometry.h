#pragma once
#include <array>

namespace deepnav::sim {

// Footprint of the oil & gas panel (DexROV): three vertical faces with rounded corners standing on the
// seabed, open at the back. The trajectory needs only the footprint; the renderer adds height and markers.
// The panel frame P has its origin at the footprint centre on the seabed, x along the front face's
// outward normal, y along the left face's outward normal, z up.
struct PanelGeometry {
  std::array<double, 2> centre_in_odom_m{0.0, 0.0};  // footprint centre (east, north)
  double half_width_m = 1.0;      // half the width of each face (faces are ~2 m wide)
  double height_m = 1.5;          // height of the faces above the seabed
  double corner_radius_m = 0.15;  // radius of the rounded vertical edges
  double front_yaw_deg = 0.0;     // ENU yaw of the front face's outward normal; left = +90, right = -90
  bool markers_enabled = true;    // fiducial markers on the faces (for the renderer)

  bool operator==(const PanelGeometry&) const = default;
};

}  // namespace deepnav::sim
