// Private to the pair-mesh repair: the triangulation of the Voronoi polygons
// of Face-Vertex pyramids.
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "cadmedial/pair_mesh.hpp"

namespace cadmedial {

// A Face-Vertex pair of pyramids (apexes a and b, the samples of one interior
// Delaunay edge) over one Voronoi polygon may use any triangulation of the
// polygon: the signed volumes still add up, and the faces shared with the
// neighbours (the polygon's sides coned to a and b) do not change. Built as a
// fan, which is fine while the polygon is convex; once the repair has moved
// its nodes it can fold where another triangulation would not.
// For every polygon with an element needing repair: picks the triangulation
// with the fewest such elements, then the largest smallest volume relative to
// size (dynamic programming over the polygon, O(k^3)), and keeps it when it
// has fewer bad elements than the current one. Element slots stay the same.
// Returns the number of polygons re-triangulated. needsRepair: per element,
// whether it needs repair, when the caller keeps that current (else tested);
// updated for the elements rewritten, so the caller need not test all again.
// With needsRepair, the caller may also give:
//  * flagged: every element flagged in needsRepair (others, and repeats, may
//    be listed too); only those are looked at, and the elements rewritten
//    that need repair are added to it;
//  * known: the element slots of the polygons found by earlier calls, valid
//    while the mesh keeps its elements in their slots (node moves and
//    re-triangulations do; splits and relabellings do not). Only polygons
//    not in it cost a pass over the elements (on CTC-01 14 ms a call);
//  * changedKeys (with known): gets the keys in `known` of the polygons
//    re-triangulated, for the caller to update what it keeps per element.
using PolygonSlots = std::unordered_map<std::uint64_t, std::vector<std::size_t>>;
std::size_t retriangulateFaceVertexPolygons(PairMesh& mesh, std::vector<std::uint8_t>* needsRepair = nullptr,
                                            std::vector<std::size_t>* flagged = nullptr,
                                            PolygonSlots* known = nullptr,
                                            std::vector<std::uint64_t>* changedKeys = nullptr);

}  // namespace cadmedial
