// Private to the pair-mesh repair: do two triangles of a surface cross, other
// than along the corners and edge they share? Used by the edge split so that
// a bent boundary never folds through its neighbours (a folded boundary
// encloses part of the solid twice: every element positive, the volumes
// adding up, and yet the iso-surfaces cross).
#pragma once

#include <array>
#include <vector>

#include "cadmedial/sample_set.hpp"

namespace cadmedial {

// Triangles t and u by node ids into `nodes`; shared ids are shared corners.
// Exact predicates (CGAL's Epick). Conservative where the contact is
// degenerate: two shared corners' edges running along each other, or one
// triangle lying flat on the other, count as crossing; so does the same
// triangle twice (a fin of no volume).
bool trianglesCross(const std::vector<Vec3>& nodes, const std::array<Index, 3>& t, const std::array<Index, 3>& u);

}  // namespace cadmedial
