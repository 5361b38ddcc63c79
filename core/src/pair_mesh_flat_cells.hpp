// Private to the pair-mesh build: inner labels of flat Delaunay cells.
#pragma once

#include <cstdint>
#include <vector>

#include "cadmedial/delaunay.hpp"

namespace cadmedial {

// Four nearly coplanar samples (a planar face's grid, or a cell between the
// sample rows on two sides of a thin edge) make a cell of volume at most
// 1e-12 × (longest edge)³: its circumcenter is far away or anywhere on a
// line, so the solid classifier's answer at it means nothing, and either
// label encloses the same volume. When three or four of its neighbours have
// the other label, the boundary would run over three of its faces, which
// overlap pairwise (a fold: no Voronoi node can sit on the inner side of all
// of them); the cell takes the neighbours' label instead, leaving at most one
// of its faces on the boundary. Repeats until nothing changes. Returns the
// number of cells relabelled; `inner` is per cell id, infinite cells outer.
std::size_t settleFlatCells(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner);

}  // namespace cadmedial
