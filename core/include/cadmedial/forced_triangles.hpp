// Forced triangles of CAD_MEDIAL (seed 002 §4.2.2–4.2.3, DESIGN.md §4.3–4.4):
// they connect the selected Voronoi facets to convex-edge samples and to
// non-concave corner samples.
#pragma once

#include <array>
#include <vector>

#include "cadmedial/delaunay.hpp"
#include "cadmedial/facet_selection.hpp"
#include "cadmedial/medial_params.hpp"

namespace cadmedial {

// Where a polygon of the medial complex comes from.
enum class PolygonProvenance : std::uint8_t {
  DelaunayEdgeFacet = 0,       // Voronoi facet dual to Delaunay edge pq (samples p, q)
  ConvexEdgeTriangle = 1,      // s v1 v2, v1v2 dual to the triplet triangle s sL sR (samples s, -)
  ConvexEdgeFillTriangle = 2,  // s s' v, closing the zigzag along a convex edge (samples s, s')
  CornerTriangle = 3,          // p v1 v2 at a non-concave corner p (samples p, -)
  HoleFill = 4,                // the rim of a short hole in a sheet, closed (short_holes.cpp; samples -, -)
};

// A forced triangle: its corners are one or two samples and two or one
// Voronoi vertices (cells), in this order:
//   ConvexEdgeTriangle:     (samples[0], cells[0], cells[1])
//   ConvexEdgeFillTriangle: (samples[0], samples[1], cells[0])
//   CornerTriangle:         (samples[0], cells[0], cells[1])
struct ForcedTriangle {
  PolygonProvenance kind = PolygonProvenance::ConvexEdgeTriangle;
  std::array<Index, 2> samples{kNoIndex, kNoIndex};  // canonical sample ids
  std::array<Index, 2> cells{kNoIndex, kNoIndex};
  // The selected facet this triangle hangs on through its Voronoi edge
  // cells[0]cells[1]: facet(sL sR) for a convex-edge triangle, facet(qr) for a
  // corner triangle; kNoIndex if that facet is not selected / for fills.
  Index attachedFacet = kNoIndex;
  Index source = kNoIndex;  // triplet index (convex, fill) or corner sample (corner)
};

struct ForcedTriangles {
  std::vector<ForcedTriangle> triangles;
  // ProcConvexEdges
  std::size_t convexEdgeTriangles = 0;      // s v1 v2 of the triplet triangles
  std::size_t convexFanTriangles = 0;       // further s v1 v2 by the corner rule at s (also ConvexEdgeTriangle)
  std::size_t convexFillTriangles = 0;
  std::size_t gapsWithoutFill = 0;          // consecutive feature samples s, s' with no common fan vertex
  std::size_t gapsNotDelaunay = 0;          // ... whose segment ss' is not a Delaunay edge
  std::size_t fillDuplicatesMerged = 0;     // same (s, s', v) proposed from both sides of a gap
  std::size_t tripletsNotDelaunay = 0;      // triangle s sL sR not in the triangulation (skipped)
  std::size_t tripletsOnHull = 0;           // its dual Voronoi edge is a ray (skipped)
  std::size_t tripletsUnattached = 0;       // facet(sL sR) not selected (triangle still added)
  // ProcNonconcaveCorners
  std::size_t cornerTriangles = 0;
  std::size_t cornersProcessed = 0;
  std::size_t cornerEdgesSuppressed = 0;    // qr selected but pq or pr selected too
  std::size_t cornerEdgesUnbounded = 0;     // qr selected, Voronoi edge is a ray (skipped)
  double convexSeconds = 0;
  double cornerSeconds = 0;
};

// The corner rule for a Delaunay triangle pqr at feature sample p (DESIGN.md
// §4 CGAL notes): the Voronoi edge dual to pqr lies on the selected axis
// through facet(qr) and no facet of V_p incident to it is selected. Returns
// facet(qr) when the rule holds, kNoIndex otherwise.
inline Index cornerRuleFacet(const SelectedFacets& selected, Index p, Index q, Index r) {
  const Index f = selected.find(q, r);
  if (f == kNoIndex || selected.find(p, q) != kNoIndex || selected.find(p, r) != kNoIndex) return kNoIndex;
  return f;
}

// ProcConvexEdges (seed 002 §4.2.2), in three parts:
//  1. For each triplet (s, sL, sR): find the Delaunay triangle s sL sR (count
//     and skip if absent or if its dual Voronoi edge is a ray) and add
//     s v1 v2 for its dual Voronoi edge v1v2, as the paper does.
//  2. Fan at s: also add s v1 v2 for every other Voronoi edge of V_s on the
//     axis by the corner rule (facet(qr) selected, facet(sq), facet(sr) not).
//     The paper adds only the triplet's edge; but the axis meets V_s along a
//     path of Voronoi edges (the Voronoi vertices between two triplets are
//     several cells, exactly so in cospherical prisms), and with one
//     triangle per triplet and two fills per gap every gap leaves a slit
//     and a 1-cycle (β1 = number of gaps on a box).
//  3. Fills: for consecutive feature samples s, s' along the edge chain
//     (s' = prev / next of the triplet, when s' has a triplet or is a
//     non-concave corner), add s s' v for every cell v around the Delaunay
//     edge ss' (so v ∈ V_s ∩ V_s', the paper's test) that is a vertex of
//     both fans. Fills proposed from both sides are merged.
void procConvexEdges(const DelaunayVoronoi& dv, const SampleSet& samples, const SelectedFacets& selected,
                     ForcedTriangles& out);

// For each non-concave corner p and each finite Delaunay triangle pqr: add
// p v1 v2 (v1v2 = dual Voronoi edge of pqr) exactly when qr is selected and
// neither pq nor pr is.
void procNonconcaveCorners(const DelaunayVoronoi& dv, const SampleSet& samples, const SelectedFacets& selected,
                           ForcedTriangles& out);

}  // namespace cadmedial
