// Poles and pole vectors of MEDIAL (seed 000, Def. 1), for samples without a
// B-rep (point clouds, mesh vertices).
//
// The pole p* of a sample p is the Voronoi vertex of its cell V_p farthest
// from p; the pole vector v_p = p* - p approximates the surface normal at p
// up to orientation. If V_p is unbounded, p* is at infinity and v_p is the
// average direction of the unbounded Voronoi edges of V_p: each is dual to a
// convex-hull triangle incident to p and runs along its outward normal.
#pragma once

#include <vector>

#include "cadmedial/delaunay.hpp"

namespace cadmedial {

struct PoleData {
  // Per sample (indexed like the input points; duplicates share their
  // canonical sample's data and keep a zero direction themselves):
  std::vector<Vec3> direction;   // unit pole vector, zero if none could be formed
  std::vector<Index> poleCell;   // cell id of the pole, kNoIndex when V_p is unbounded
  // Finite and infinite Delaunay cells incident to each canonical sample
  // (= Voronoi vertices of V_p): cells[cellOffsets[p] .. cellOffsets[p+1]).
  std::vector<Index> cellOffsets;
  std::vector<Index> cells;
  std::size_t unboundedCells = 0;     // canonical samples with an unbounded V_p (on the hull)
  std::size_t zeroDirections = 0;     // canonical samples whose pole vector vanished (e.g. a p* at p)
  double seconds = 0;
};

// Empty result (all directions zero) when the triangulation is not 3-dimensional.
PoleData computePoles(const DelaunayVoronoi& dv);

// Outward unit normal of the convex-hull triangle of an infinite cell (the
// direction of its dual Voronoi ray).
Vec3 hullFacetOutwardNormal(const DelaunayVoronoi& dv, Index infiniteCell);

}  // namespace cadmedial
