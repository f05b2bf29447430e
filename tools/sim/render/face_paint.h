#pragma once
#include <cstdint>

#include "nav/markers/panel_description.h"
#include "tools/sim/render/marker_layout.h"
#include "tools/sim/render/panel_faces.h"
#include "tools/sim/render/texture_map.h"

namespace deepnav::sim {

// The texture of one face, covering s in [-half_width, half_width] and z in [z_bottom_m, height]:
// texel (u, v) = ((s + half_width) / texel_m, (height - z) / texel_m).
struct FacePaintSpec {
  double z_bottom_m = -0.1;   // below the seabed relief, so the paint reaches the ground
  double texel_m = 0.002;     // about one pixel at 1.5 m (fx = 700 px)
  double quiet_zone_m = 0.025;  // MarkerLayout::quiet_zone_m
};

// Paints face `face_index` (0 valves, 1 grasping: yellow paint, mottling, rust streaks, fouling spots,
// dirt near the seabed, painted frames and labels; 2 plain: grey paint with about 1.5 % contrast) and
// its markers (black cells albedo 0.04, white cells and quiet zone 0.85, anti-aliased by 4 x 4
// supersampling of the exact bit pattern of cv::aruco::drawMarker). Deterministic in seed.
bool paintFace(const FaceFrame& face, int face_index, const PanelDescription& panel, const FacePaintSpec& spec,
               std::uint32_t seed, TextureMap* texture, std::string* error);

// Paint for a rounded corner (yellow, mottled), arc length x height; u along the arc.
void paintCorner(double arc_length_m, double height_m, const FacePaintSpec& spec, std::uint32_t seed,
                 TextureMap* texture);

}  // namespace deepnav::sim
