// Narrow faces: a face whose boundary comes back close to itself (the 0.2 mm
// riser of a step on a part sampled at 3.75, a hole's rim 0.5 mm from the
// plate's edge) has no room at the part's spacing for the triplet legs of
// its convex edges, nor for the samples that bound its medial sheets: the
// legs are dropped and the sheet of the edge is missing (small_step in
// scripts/robustness_parts.py attached 91 % of its convex edges). The wall
// thickness probes do not see it: rays into the solid from such a face
// travel far. So a face's own width, the distance between two of its
// boundary edges that share no vertex where the boundary runs far between
// them, asks for a finer spacing there.
#pragma once

#include <vector>

#include "face_spacing_field.hpp"
#include "solid_topology.hpp"

namespace cadmedial {

// Per face: points along its boundary edges where another of its edges,
// sharing no vertex with theirs, is nearer than cap / fraction and the way
// between the two points along the face's boundary is at least twice their
// distance (on different wires: always), each asking for fraction × that
// distance, clamped to [floor, cap]. An edge is sampled once, at half its
// nearest partner's distance, on the pieces that come near a partner. Empty
// for faces that are nowhere narrow. For FaceSpacingField::gradeFrom, with
// the convex edges' sources.
std::vector<std::vector<FaceSpacingField::Source>> narrowFaceSources(const SolidTopology& topo, double floor,
                                                                      double cap, double fraction);

}  // namespace cadmedial
