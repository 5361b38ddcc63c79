// Private to the pair-mesh: edits of a built mesh shared by the edge split
// and the in-place relabelling, which both replace some elements.
#pragma once

#include <cstdint>
#include <vector>

#include "cadmedial/pair_mesh.hpp"

namespace cadmedial {

// Removes the elements with drop[i] != 0, keeping the others in order;
// `perElement` (optional, one entry per element: the repair's flags) loses
// the same entries.
void removeElements(PairMesh& mesh, const std::vector<std::uint8_t>& drop,
                    std::vector<std::uint8_t>* perElement = nullptr);

// Removes the nodes with drop[n] != 0 (no element may use them), keeping the
// others in order and renumbering the elements' corners.
void removeNodes(PairMesh& mesh, const std::vector<std::uint8_t>& drop);

// Element counts per type and the boundary triangles (those of the
// Vertex-Face elements, in element order), from the elements.
void recountElements(PairMesh& mesh);

// Boundary nodes the repair put on split edges.
std::size_t splitNodeCount(const PairMesh& mesh);

}  // namespace cadmedial
