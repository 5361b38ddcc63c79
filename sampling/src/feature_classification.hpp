// Sharp-feature classification from exact geometry: edges convex / concave /
// smooth from the face normals along them, feature vertices as corners or
// tangent pass-throughs, and corners as non-concave or concave.
#pragma once

#include <vector>

#include "cadmedial/sample_set.hpp"
#include "solid_topology.hpp"

namespace cadmedial {

struct EdgeFeature {
  EdgeKind kind = EdgeKind::Smooth;
  bool seam = false;        // bounds one face on both sides (unsplit periodic face)
  bool free = false;        // bounds only one face: the shell is open there
  bool mixedSign = false;   // convex along part of it, concave along another part
  double maxDeviationDeg = 0;  // max angle between the two outward normals along it
  int validProbes = 0;  // probes where both faces gave a frame; with none, Smooth is only the default
  double length = 0;
  bool sharp() const { return kind != EdgeKind::Smooth; }
};

struct VertexFeature {
  int sharpEdgeEnds = 0;  // number of sharp edge ends at the vertex
  bool isCorner = false;  // sharp, and not a tangent pass-through of one sharp chain
  bool nonConcave = false;
};

// smoothAngleDeg: edges whose outward normals stay within this angle are smooth.
std::vector<EdgeFeature> classifyEdges(const SolidTopology& topo, double smoothAngleDeg);

// Corners and their concavity (see DESIGN.md §3): the interior tangent cone
// is probed with rays into every incident face; a corner is concave iff the
// rays fit in a closed half-space {x·n >= 0} whose opposite side is inside the
// solid (checked with the exact OCCT classifier).
std::vector<VertexFeature> classifyVertices(const SolidTopology& topo, const std::vector<EdgeFeature>& edges);

}  // namespace cadmedial
