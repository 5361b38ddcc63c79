// Parameters of CAD_MEDIAL (DESIGN.md §4) and the optional inside oracle.
#pragma once

#include <functional>

#include "cadmedial/sample_set.hpp"

namespace cadmedial {

// Which Delaunay triangles (= Voronoi edges) the inner/outer walk refuses to
// cross. The walk only ever moves from one selected facet to another across a
// Voronoi edge; it never moves through a forced triangle (a forced triangle has
// a single Voronoi edge, so it can never carry the walk anywhere). See
// inner_outer.hpp for what each choice means.
enum class WalkBlocking : unsigned char {
  None = 0,                       // cross every Voronoi edge shared by selected facets
  NonConcaveCorners = 1,          // not across triangles incident to a non-concave corner sample
  CornersAndConvexEdges = 2,      // ... nor across triangles incident to a convex-edge sample
};

struct MedialParams {
  // Angle condition [θ]: all umbrella normals make an acute angle < π/2 - θ with pq.
  double thetaDeg = 5.0;
  // Ratio condition [ρ]: |pq| > ρ · (largest umbrella circumradius at p).
  double rho = 8.0;
  // At samples inside a concave edge, an umbrella triangle judges [θ] only
  // for the edges heading over its corner wedge (umbrella.cpp: the chords
  // across a boss's foot). false = seed 002's test against every normal.
  bool oneSidedConcaveEdges = true;
  WalkBlocking walkBlocking = WalkBlocking::None;  // measured best, see inner_outer.hpp
  // The outer walk only crosses Voronoi edges whose two ends lie outside the
  // sampled surface (cell_sides.hpp). Where sampling is coarse for the local
  // feature size, Voronoi facets straddle the surface and would otherwise
  // carry the walk into the inner axis (a whole part labelled outer).
  bool walkStaysOutside = true;
  // After the walk, a facet it did not reach is outer anyway when one of its
  // Voronoi vertices lies outside the sampled surface by more than
  // nearSurfaceFraction × h (h = SampleSet::spacing): the inner medial axis
  // has every vertex inside the solid. Needs walkStaysOutside (the sides).
  bool innerNeedsInsideVertices = true;
  double nearSurfaceFraction = 0.1;
  // Close one-facet holes of the inner complex: an unselected Voronoi facet
  // whose every vertex and edge is already on it (facet_holes.cpp).
  bool fillSingleFacetHoles = true;
  // Close holes in the sheets whose rim (a simple cycle of border edges) is
  // shorter than the median medial radius on it: no loop of the true axis
  // fits in a medial ball (short_holes.cpp).
  bool fillShortHoles = true;
  // Collapse the fringe of Voronoi facets the Angle condition keeps around
  // 1-D parts of the axis (fillet centre curves, cylinder and torus axes):
  // facets of chords on one smooth surface whose free vertices v have their
  // ball inside another vertex u's, r_u - r_v + s >= cos(fringeBetaDeg) |u - v|
  // with s = fringeSlackFraction h and |u - v| >= fringeMinReachFraction h.
  // Homotopy-preserving (fringe_thinning.cpp). Measured: two contacts on a
  // torus 85.0 -> 99.99 %, on a box with every edge filleted 51 -> 74 %;
  // slack 0.01 h gave the torus 92 %. fringeBetaDeg in (0°, 90°).
  bool thinFringe = true;
  double fringeBetaDeg = 20.0;
  double fringeSlackFraction = 0.03;
  double fringeMinReachFraction = 0.02;
  // A connected component of the inner complex whose medial balls all have
  // radius below islandRadiusFraction × h and no forced triangle is dropped
  // (never the component with the most polygons): the axis of a connected
  // solid is connected, and such an island hangs on a feature thinner than
  // the sampling resolves (lever: the sheets on a zero-angle cusp). 0 keeps
  // every component. On by default since 2026-12-06: on every bundled and
  // public part it changes β0 only (lever 2 -> 1, bottle 6 -> 5) and no other
  // metric (scripts/eval_table.py --public); the 0.66 % of the bottle's
  // convex-edge attachment it cost on 2026-12-03 is no longer lost.
  double islandRadiusFraction = 0.25;
  // A component of the inner complex that is one point (all its vertices
  // within 1e-9 of the bounding-box diagonal: zero-size facets at the centre
  // of a sphere's cospherical samples) is dropped, never the largest one.
  bool dropPointIslands = true;
  // A component of the inner complex made of forced triangles only (no
  // Voronoi facet: the sheet they complete was pruned by the filter) is
  // dropped, never the largest one.
  bool dropForcedOnlyIslands = true;
  // Drop components (not the largest, no forced triangle) whose balls all
  // nearly nest in the main axis's, by the fringe's dominance rule
  // (fringeBetaDeg, fringeSlackFraction h): they add next to nothing to the
  // union of balls (small_islands.cpp).
  bool dropNestedIslands = true;
  // Compute β2 (and so β1) exactly only while the 2-core left after free-face
  // collapses has at most this many polygons; otherwise β1 = β2 = -1.
  std::size_t bettiCoreLimit = 200000;
  // computeCadMedial ends with computeTopology (β numbers of the result, a
  // diagnostic). False leaves MedialResult::topology empty for the caller to
  // compute, e.g. while the outputs are written (the CLI does).
  bool computeTopology = true;

  // The walk or the inner rule may read the cell sides (classifyCellSides).
  bool mayReadCellSides() const { return walkStaysOutside || innerNeedsInsideVertices; }

  // Defaults of seed 002 (CAD samples): θ = 5°, ρ = 8.
  static MedialParams cad() { return MedialParams{}; }
  // Defaults of seed 000 (point clouds): θ = π/8, ρ = 8.
  static MedialParams pointCloud() {
    MedialParams p;
    p.thetaDeg = 22.5;
    return p;
  }
};

// Exact inside test of the solid (sampling/ wraps an OCCT classifier). As
// the walk's check (`oracle`) it only counts disagreements, never decides a
// label, and is called from several threads at once: it must be safe to.
// (exactSideNearSurface, of the same type, is called from one thread.)
using InsideOracle = std::function<bool(const Vec3&)>;

}  // namespace cadmedial
