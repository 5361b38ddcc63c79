// Inner / outer separation (seed 002 §4.2.5, DESIGN.md §4.5).
//
// The walk starts at every unbounded selected facet and moves from a selected
// facet to another selected facet across a shared Voronoi edge, i.e. across a
// Delaunay triangle pqx whose edges pq and px (or qx) are both selected. It
// never moves across a Voronoi vertex. Everything reached is outer.
//
// Forced triangles never carry the walk: each has exactly one Voronoi edge
// (v1v2), the others run to a sample, so entering one leads nowhere. So the
// paper's "never through the forced corner triangles" holds by construction,
// and what really separates the sheets is which Voronoi edges may be crossed,
// set by MedialParams::walkBlocking (default None; NonConcaveCorners refuses
// the Voronoi edges of the cell V_p of a non-concave corner p, i.e. the duals
// of the Delaunay triangles incident to p: the paper's "surface triangles
// around a non-concave corner").
//
// At convex edges: the inner sheet reaches the edge sample s only through
// forced triangles (s v1 v2, fills), which the walk never traverses, so inner
// and outer sheets that both touch s (a point, not a Voronoi edge) are never
// joined there. They are joined only where an inner and an outer *facet*
// share a Voronoi edge; the oracle counters below show whether that happened.
//
// Labels of forced triangles: a corner or convex-edge triangle p v1 v2 takes
// the label of the facet it hangs on through v1v2 (facet(qr) of the corner
// rule, facet(sL sR) of a triplet), so an outer sheet that reaches a feature
// sample gets outer triangles instead of polluting the inner axis; an
// unattached one (facet(sL sR) not selected) and the fills are inner.
//
// Measured (tests/core/test_walk.cpp, L-prism and holed box, h = 0.05): with
// WalkBlocking::None every bounded facet agrees with the exact inside test;
// blocking at non-concave corners cuts outer facets off at the L-prism's
// notch corners (islands labelled inner); blocking at convex-edge samples
// too cuts the outer axis of the notch / hole off from its unbounded seeds
// (about 10 % of the facets wrong). The outer axis really does cross Voronoi
// edges of V_p at those samples, so None is the default.
#pragma once

#include <vector>

#include "cadmedial/facet_selection.hpp"
#include "cadmedial/forced_triangles.hpp"

namespace cadmedial {

struct InnerOuterLabels {
  std::vector<std::uint8_t> facetOuter;   // per selected facet: 1 = outer
  std::vector<std::uint8_t> forcedOuter;  // per forced triangle: 1 = outer
  std::size_t seeds = 0;                  // unbounded selected facets
  std::size_t walks = 0;                  // walks started (outer components reached from infinity)
  std::size_t outerFacets = 0;
  std::size_t innerFacets = 0;            // selected facets not reached (all bounded)
  std::size_t blockedCrossings = 0;       // crossings refused by walkBlocking
  std::size_t surfaceCrossingsRefused = 0;  // crossings refused: the Voronoi edge is not wholly outside
  std::size_t blockedCrossingsToInner = 0;  // ... whose target facet stayed inner
  std::size_t innerFacetsOutsideSurface = 0;  // not reached by the walk, relabelled outer: a Voronoi
                                              // vertex clearly outside the sampled surface
  std::size_t nearFacetsOutsideExactly = 0;   // not reached, every vertex within the band outside, and
                                              // the centroid outside the exact solid (exactSideNearSurface)
  std::size_t outerCornerTriangles = 0;   // corner triangles hanging on an outer facet
  std::size_t outerConvexTriangles = 0;   // convex-edge (fan) triangles hanging on an outer facet
  // Independent check with the inside oracle (0 when no oracle was given):
  // bounded facets by the centroid of their Voronoi vertices, forced
  // triangles by their centroid.
  std::size_t oracleFacetsChecked = 0;
  std::size_t oracleFacetDisagreements = 0;  // walk label != oracle
  std::size_t oracleInnerOutside = 0;        // of those: inner by walk, outside by oracle
  std::size_t oracleForcedChecked = 0;
  std::size_t oracleForcedDisagreements = 0;
  double seconds = 0;
  double oracleSeconds = 0;
};

// cellSide: per cell id, a CellSide of its Voronoi vertex (classifyCellSides);
// empty = no restriction on the walk and no relabelling. The walk never crosses
// a Voronoi edge with an end inside; with params.innerNeedsInsideVertices a
// facet it did not reach is still outer when one of its Voronoi vertices is
// clearly outside (kCellOutside), or, given exactSideNearSurface (false
// where a point is clearly outside the exact solid; called serially), when
// every one is outside within the band (kCellNearOutside) and the facet's
// centroid is outside the exact solid. `oracle`'s check of such a facet is
// then no independent check: it asks the same solid at the same centroid.
InnerOuterLabels separateInnerOuter(const DelaunayVoronoi& dv, const SampleSet& samples,
                                    const SelectedFacets& selected, const ForcedTriangles& forced,
                                    const MedialParams& params, const InsideOracle& oracle = {},
                                    const std::vector<std::uint8_t>& cellSide = {},
                                    const InsideOracle& exactSideNearSurface = {});

}  // namespace cadmedial
