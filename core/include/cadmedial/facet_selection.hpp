// MEDIAL's facet selection (seed 000 §3, DESIGN.md §4.2): the Voronoi facet
// dual to Delaunay edge pq is selected if p or q satisfies the Angle condition
// [θ] or the Ratio condition [ρ] for pq. One pass over the finite edges.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "cadmedial/delaunay.hpp"
#include "cadmedial/edge_table.hpp"
#include "cadmedial/medial_params.hpp"
#include "cadmedial/umbrella.hpp"

namespace cadmedial {

// Angle [θ] or Ratio [ρ] condition for edge pq at p. `dir` is q - p, `len` its
// length; sinTheta = sin θ. Angle: every umbrella normal n has |n·dir| > sinθ·len
// (acute angle < π/2 - θ). Ratio: len > ρ · max umbrella circumradius. A sample
// without usable umbrella satisfies neither.
inline bool satisfiesAngleOrRatio(const UmbrellaData& u, Index p, const double dir[3], double len, double sinTheta,
                                  double rho) {
  const Index b = u.offsets[p], e = u.offsets[p + 1];
  if (b == e) return false;
  if (len > rho * u.maxCircumradius[p]) return true;
  const double threshold = sinTheta * len;
  const Index side = u.sideStart.empty() ? kNoIndex : u.sideStart[p];
  // One-sided umbrella (concave edge): widen each wedge by 2θ (cos 2θ =
  // 1 - 2 sin²θ), so edges along the concave edge itself stay judged by both faces.
  const double slackCos = 1 - 2 * sinTheta * sinTheta;
  for (Index k = b; k < e; ++k) {
    const auto& n = u.normals[k];
    const double d = n[0] * dir[0] + n[1] * dir[1] + n[2] * dir[2];
    if (std::abs(d) > threshold) continue;
    if (side != kNoIndex && !headsOverWedge(u.wedges[side + (k - b)], n, dir, slackCos)) continue;
    return false;
  }
  return true;
}

struct SelectedFacets {
  // Per selected facet f: its Delaunay edge as canonical sample ids (p < q),
  // and the Voronoi vertices (cell ids) of its boundary in cyclic order:
  // ringCells[ringOffsets[f] .. ringOffsets[f+1]).
  std::vector<std::array<Index, 2>> edge;
  std::vector<Index> ringOffsets{0};
  std::vector<Index> ringCells;
  std::vector<std::uint8_t> unbounded;  // 1 if an infinite cell is on the ring
  PairTable lookup;                     // {p,q} -> facet id
  // Per cell id, bit cellEdgeBit(i, j): the Delaunay edge between the cell's
  // local vertices i and j is selected (0 for infinite cells). The same
  // answer as find() without a hash lookup, for passes over cells.
  std::vector<std::uint8_t> cellEdgeMask;

  std::size_t finiteEdges = 0;          // Delaunay edges examined
  std::size_t unboundedCount = 0;
  double seconds = 0;       // whole stage
  double testSeconds = 0;   // of which the (parallel) Angle/Ratio tests

  std::size_t size() const { return edge.size(); }
  Index find(Index p, Index q) const { return lookup.find(p, q); }
  Index ringSize(Index f) const { return ringOffsets[f + 1] - ringOffsets[f]; }
  const Index* ringBegin(Index f) const { return ringCells.data() + ringOffsets[f]; }
  const Index* ringEnd(Index f) const { return ringCells.data() + ringOffsets[f + 1]; }
  bool cellEdgeSelected(Index cell, int i, int j) const { return cellEdgeMask[cell] >> cellEdgeBit(i, j) & 1u; }

  // Local edges of a cell: edge e joins local vertices kEdgeI[e] and kEdgeJ[e].
  static constexpr int kEdgeI[6] = {0, 0, 0, 1, 1, 2};
  static constexpr int kEdgeJ[6] = {1, 2, 3, 2, 3, 3};
  static constexpr int cellEdgeBit(int i, int j) {
    constexpr int kEdgeOf[4][4] = {{-1, 0, 1, 2}, {0, -1, 3, 4}, {1, 3, -1, 5}, {2, 4, 5, -1}};
    return kEdgeOf[i][j];
  }
};

SelectedFacets selectFacetsByAngleAndRatio(const DelaunayVoronoi& dv, const UmbrellaData& umbrellas,
                                           const MedialParams& params);

}  // namespace cadmedial
