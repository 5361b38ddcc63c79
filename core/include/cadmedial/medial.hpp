// CAD_MEDIAL (seeds 000 and 002, DESIGN.md §4): the inner medial axis of a
// solid from its SampleSet, as an indexed polygon complex split into sheets.
//
//   MedialResult r = computeCadMedial(samples, MedialParams::cad(), oracle);
//
// The stages are public for tests and benchmarks, each in its own header:
//   delaunay.hpp         DelaunayVoronoi               (§4.1)
//   umbrella.hpp         computeUmbrellaData           (§4.2, per-sample data)
//   facet_selection.hpp  selectFacetsByAngleAndRatio   (§4.2)
//   forced_triangles.hpp procConvexEdges, procNonconcaveCorners (§4.3, §4.4)
//   inner_outer.hpp      separateInnerOuter            (§4.5)
//   polygon_complex.hpp  buildInnerComplex, segmentSheets, computeTopology (§4.6)
#pragma once

#include <memory>

#include "cadmedial/cell_sides.hpp"
#include "cadmedial/delaunay.hpp"
#include "cadmedial/facet_selection.hpp"
#include "cadmedial/forced_triangles.hpp"
#include "cadmedial/inner_outer.hpp"
#include "cadmedial/medial_params.hpp"
#include "cadmedial/polygon_complex.hpp"
#include "cadmedial/sample_set.hpp"
#include "cadmedial/umbrella.hpp"

namespace cadmedial {

struct MedialCounts {
  std::size_t samples = 0;
  std::size_t duplicateSamples = 0;       // merged by the triangulation
  std::size_t delaunayCells = 0;          // finite cells (= Voronoi vertices)
  std::size_t delaunayEdges = 0;          // finite edges examined
  std::size_t selectedFacets = 0;         // by Angle/Ratio, bounded and unbounded
  std::size_t unboundedFacets = 0;
  std::size_t innerFacets = 0;
  std::size_t outerFacets = 0;
  std::size_t convexEdgeTriangles = 0;
  std::size_t convexFillTriangles = 0;
  std::size_t cornerTriangles = 0;        // all; outerCornerTriangles of them were dropped
  std::size_t outerCornerTriangles = 0;
  std::size_t tripletsNotDelaunay = 0;
  std::size_t tripletsOnHull = 0;
  std::size_t degenerateUmbrellaTriangles = 0;
  std::size_t samplesWithoutUmbrella = 0;
  std::size_t sheets = 0;
  std::size_t walkBlockedCrossings = 0;
  std::size_t walkSurfaceCrossingsRefused = 0;  // crossings refused: a Voronoi vertex inside the surface
  std::size_t innerFacetsOutsideSurface = 0;    // unreached facets relabelled outer (a vertex outside)
  std::size_t nearFacetsOutsideExactly = 0;     // ... (every vertex near outside, the centroid outside exactly)
  std::size_t singleFacetHolesFilled = 0;       // unselected facets closing a one-facet hole
  std::size_t shortHolesFilled = 0;             // holes whose rim is shorter than a ball on it, closed
  std::size_t fringePolygonsThinned = 0;        // fringe facets collapsed (thinFringe)
  std::size_t subResolutionIslands = 0;         // components dropped (all radii < islandRadiusFraction h)
  std::size_t subResolutionIslandPolygons = 0;  // their polygons
  std::size_t pointIslands = 0;                 // components dropped that are one point (zero-size facets)
  std::size_t forcedOnlyIslands = 0;            // components dropped that have no Voronoi facet
  std::size_t nestedIslands = 0;                // components dropped whose balls nest in the main axis's
  std::size_t coincidentVerticesWelded = 0;     // Voronoi vertices joined to a coincident one (cospherical samples)
  std::size_t degenerateFacetsDropped = 0;      // inner facets the weld left a segment or a point, or made equal to another polygon
  std::size_t oracleChecked = 0;          // bounded selected facets checked by the inside oracle
  std::size_t oracleDisagreements = 0;    // ... whose walk label != oracle at their centroid
  std::size_t oracleForcedChecked = 0;    // forced triangles checked (reported apart: samples on the
  std::size_t oracleForcedDisagreements = 0;  // boundary make their centroids borderline)
};

struct MedialTimes {  // seconds
  double delaunay = 0;     // CGAL insertion alone: the floor of DESIGN.md §7
  double voronoi = 0;      // cell ids, circumcenters, sample -> vertex map
  double umbrellas = 0;
  double selection = 0;
  double convexEdges = 0;
  double corners = 0;
  double cellSides = 0;    // which side of the reconstructed surface each used Voronoi vertex is on
  double walk = 0;
  double oracle = 0;       // not part of the pipeline proper
  double complex = 0;
  double sheets = 0;
  double topology = 0;
  double total = 0;        // the whole pipeline incl. Delaunay, without the oracle
  double preparedAlongside = 0;  // PreparedSamples built while the Delaunay ran (not in total)
};

struct MedialResult : MedialComplex {
  ComplexTopology topology;  // of the inner complex
  ComplexEdges edges;        // its 1-skeleton (border / manifold / junction)
  MedialCounts counts;
  MedialTimes times;
  ForcedTriangles forced;    // all forced triangles with their counters
  InnerOuterLabels labels;   // walk counters (per-facet labels included)
};

// Whole pipeline; throws std::runtime_error / std::invalid_argument on an
// inconsistent SampleSet. Inputs spanning fewer than 3 dimensions give an
// empty result.
MedialResult computeCadMedial(const SampleSet& samples, const MedialParams& params = MedialParams::cad(),
                              const InsideOracle& oracle = {});

// Same on a triangulation already built from samples.points (reuse it for the
// pair-mesh).
MedialResult computeCadMedial(const DelaunayVoronoi& dv, const SampleSet& samples,
                              const MedialParams& params = MedialParams::cad(), const InsideOracle& oracle = {});

// The pipeline's work on the samples alone (umbrella data, cell-side inputs,
// ~2.5 s at 10^6 samples): it needs no triangulation, so a caller with a
// second core builds it while the Delaunay runs and passes it in. `surface`
// as for CellSideInputs.
struct PreparedSamples {
  explicit PreparedSamples(const SampleSet& samples, bool withCellSides = true,
                           const SurfaceMeshStats* surface = nullptr);
  UmbrellaData umbrellas;
  std::unique_ptr<CellSideInputs> cellSides;  // null: built when needed
  double umbrellaSeconds = 0, cellSideSeconds = 0;
};

// Same with the samples' part prepared beforehand from the same samples; its
// time is reported as times.preparedAlongside, not in the stages or total.
MedialResult computeCadMedial(const DelaunayVoronoi& dv, const SampleSet& samples, const PreparedSamples& prepared,
                              const MedialParams& params = MedialParams::cad(), const InsideOracle& oracle = {},
                              const InsideOracle& exactSideNearSurface = {});

}  // namespace cadmedial
