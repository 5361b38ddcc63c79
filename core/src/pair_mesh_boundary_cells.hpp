// Private to the pair-mesh build: the last resort for elements the repair
// could not turn positive.
#pragma once

#include <cstdint>
#include <vector>

#include "cadmedial/delaunay.hpp"
#include "cadmedial/pair_mesh.hpp"

namespace cadmedial {

// The inner cells on the boundary (at least one outer neighbour) whose
// Voronoi nodes are corners of an inverted element of `mesh`, for the caller
// to relabel outer: the boundary then runs over their other facets, and the
// fold their nodes could not leave goes with them. Where that would leave
// inner cells around one of their edges in two runs (a non-manifold edge:
// the cells sit across a wedge thinner than the sampling, e.g. a cylinder
// tangent to a plane), the runs cut off from the widest one (by angle) go
// too, up to 4 × (cells) + 64 cells in all. A cell with the runs it cut off
// goes back when one of them would still leave a non-manifold edge.
// Vertices are not checked. Sorted, each cell once.
std::vector<Index> boundaryCellsOfInvertedElements(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner,
                                                   const PairMesh& mesh);

}  // namespace cadmedial
