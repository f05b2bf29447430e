#include "tools/sim/render/panel_knowledge.h"

#include "tools/sim/render/panel_faces.h"

namespace deepnav::sim {

PanelDescription makePanelDescription(const Scenario& scenario, const MarkerLayout& layout) {
  const PanelGeometry& panel = scenario.panel;
  const auto faces = panelFaces(panel);
  PanelDescription d;
  d.dictionary = layout.dictionary;
  d.marker_size_m = layout.marker_size_m;
  d.corner_radius_m = panel.corner_radius_m;
  for (const FaceFrame& f : faces) {
    PanelFace face;
    face.name = f.name;
    face.centre_in_panel_m = f.pointAt(0.0, 0.5 * f.height_m);
    face.normal_in_panel = f.normal_in_panel;
    face.width_m = 2.0 * f.half_width_m;
    face.height_m = f.height_m;
    d.faces.push_back(face);
  }
  if (!panel.markers_enabled) return d;
  for (const MarkerSpot& spot : layout.spots) {
    if (spot.face < 0 || spot.face >= kPanelFaceCount) continue;  // validateMarkerLayout reports it
    const FaceFrame& f = faces[spot.face];
    PanelMarker m;
    m.id = spot.id;
    m.face = spot.face;
    m.p_marker_in_panel_m = f.pointAt(spot.s_fraction * f.half_width_m, spot.z_fraction * f.height_m);
    m.q_panel_marker = Eigen::Quaterniond(f.R_panel_face());
    d.markers.push_back(m);
  }
  return d;
}

}  // namespace deepnav::sim
