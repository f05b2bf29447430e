#pragma once
#include <array>
#include <vector>

#include "tools/sim/render/material.h"
#include "tools/sim/render/panel_faces.h"
#include "tools/sim/render/primitive.h"

namespace deepnav::sim {

// The raised hardware on the panel, as boxes and cylinders that give the faces depth structure:
//   valves face: a T-handle rotary valve, a lever valve, a handwheel valve and a clamped pipe;
//   grasping face: a top handrail, two vertical handles, a U grasp bar and a lower bar, on brackets;
//   plain face: nothing.
// Positions scale with the face (fractions of half width and height), sizes are absolute. Appends the
// primitives and the solid materials they use.
void addPanelFixtures(const std::array<FaceFrame, kPanelFaceCount>& faces, std::vector<Primitive>* primitives,
                      std::vector<Material>* materials);

}  // namespace deepnav::sim
