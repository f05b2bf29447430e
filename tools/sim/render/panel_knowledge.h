#pragma once
#include "nav/markers/panel_description.h"
#include "tools/sim/render/marker_layout.h"
#include "tools/sim/scenario.h"

namespace deepnav::sim {

// The panel knowledge base of the rendered scene: its faces (valves, grasping, plain; see panel_faces.h)
// and markers in the panel frame P, marker frame M = OpenCV ArUco (x right, y up, z out of the face).
// No markers when panel.markers_enabled is false. The simulator writes it with writePanelDescription.
PanelDescription makePanelDescription(const Scenario& scenario,
                                      const MarkerLayout& layout = defaultMarkerLayout());

}  // namespace deepnav::sim
