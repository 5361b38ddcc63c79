// Private to the pair-mesh build: the last resort for elements the repair
// could not turn positive.
#pragma once

#include <cstdint>
#include <vector>

#include "cadmedial/delaunay.hpp"
#include "cadmedial/pair_mesh.hpp"

namespace cadmedial {

// The inner cells on the boundary (at least one outer neighbour) whose
// Voronoi nodes are corners of the given elements of `mesh` (indices into
// mesh.tets, e.g. invertedElements(mesh)), for the caller to relabel outer:
// the boundary then runs over their other facets, and the fold their nodes
// could not leave goes with them. `rings` layers of the boundary cells next
// to them (across a facet) are added first: a fold in a wedge thinner than
// the sampling (the lever's blade between a plane and a cylinder touching
// it) can need a patch of the wedge's cells to go, not one. Where that would
// leave inner cells around one of their edges in two runs (a non-manifold
// edge: the cells sit across a wedge thinner than the sampling, e.g. a
// cylinder tangent to a plane), the runs cut off from the widest one (by
// angle) go too, up to 4 × (cells) + 64 cells in all. A cell with the runs it
// cut off goes back when one of them would still leave a non-manifold edge.
// Vertices are not checked. Sorted, each cell once.
std::vector<Index> boundaryCellsOfElements(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner,
                                           const PairMesh& mesh, const std::vector<std::size_t>& elements,
                                           int rings = 0);

// The other way round: finite outer cells next to inverted elements, for the
// caller to relabel inner (the boundary then runs over their other
// facets): those across the boundary facets of inverted Vertex-Face
// elements, across the boundary facets on the edge of inverted Edge-Edge
// elements, and next to the boundary cells holding the Voronoi nodes of
// inverted Face-Vertex elements. Where the repair and the cells going outer
// leave elements inverted on coarsely sampled parts (NIST CTC-01, h = 23 mm:
// 5 -> 0 with 8 cells in two passes), this is what removes them. Like the
// cells going outer, they go with the runs of outer cells they cut off
// around an edge (all but the widest, never one with an infinite cell), and
// a group that would still leave a non-manifold edge stays outer. Vertices
// are not checked. Sorted, each cell once. `elements`: indices into
// mesh.tets, all inverted ones or one at a time.
std::vector<Index> outerCellsAcrossElements(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner,
                                            const PairMesh& mesh, const std::vector<std::size_t>& elements);

// Indices of the inverted elements of `mesh`, in order.
std::vector<std::size_t> invertedElements(const PairMesh& mesh);

}  // namespace cadmedial
