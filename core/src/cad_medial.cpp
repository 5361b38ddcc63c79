#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>

#include "cadmedial/medial.hpp"
#include "cadmedial/cell_sides.hpp"
#include "cadmedial/timer.hpp"

namespace cadmedial {

MedialResult computeCadMedial(const SampleSet& samples, const MedialParams& params, const InsideOracle& oracle) {
  samples.validate();
  DelaunayVoronoi dv(samples.points);
  return computeCadMedial(dv, samples, params, oracle);
}

PreparedSamples::PreparedSamples(const SampleSet& samples, bool withCellSides, const SurfaceMeshStats* surface) {
  Stopwatch watch;
  umbrellas = computeUmbrellaData(samples);
  umbrellaSeconds = watch.seconds();
  watch.restart();
  if (withCellSides) cellSides = std::make_unique<CellSideInputs>(samples, surface);
  cellSideSeconds = watch.seconds();
}

MedialResult computeCadMedial(const DelaunayVoronoi& dv, const SampleSet& samples, const MedialParams& params,
                              const InsideOracle& oracle) {
  samples.validate();
  // Cell sides only where the walk or the inner rule may read them.
  const PreparedSamples prepared(samples, params.mayReadCellSides());
  MedialResult r = computeCadMedial(dv, samples, prepared, params, oracle);
  r.times.umbrellas += prepared.umbrellaSeconds;
  r.times.cellSides += prepared.cellSideSeconds;
  r.times.total += prepared.umbrellaSeconds + prepared.cellSideSeconds;
  r.times.preparedAlongside = 0;
  return r;
}

MedialResult computeCadMedial(const DelaunayVoronoi& dv, const SampleSet& samples, const PreparedSamples& prepared,
                              const MedialParams& params, const InsideOracle& oracle,
                              const InsideOracle& exactSideNearSurface) {
  samples.validate();
  if (dv.sampleCount() != samples.size())
    throw std::invalid_argument("computeCadMedial: triangulation and SampleSet differ in size");
  if (!(params.thetaDeg > 0 && params.thetaDeg < 90)) throw std::invalid_argument("MedialParams: theta must be in (0°, 90°)");
  if (!(params.rho > 0)) throw std::invalid_argument("MedialParams: rho must be positive");
  if ((params.thinFringe || params.dropNestedIslands) &&
      !(params.fringeBetaDeg > 0 && params.fringeBetaDeg < 90 && params.fringeSlackFraction >= 0 &&
        params.fringeMinReachFraction > 0))
    throw std::invalid_argument("MedialParams: fringe beta must be in (0°, 90°), slack >= 0, min reach > 0");

  MedialResult r;
  r.times.delaunay = dv.delaunaySeconds();
  r.times.voronoi = dv.sideArraySeconds();
  r.times.preparedAlongside = prepared.umbrellaSeconds + prepared.cellSideSeconds;
  Stopwatch total;
  Stopwatch watch;

  std::unique_ptr<UmbrellaData> seedUmbrellas;  // the seed's two-sided test: no one-sided wedges
  if (!params.oneSidedConcaveEdges) {
    seedUmbrellas = std::make_unique<UmbrellaData>(prepared.umbrellas);
    seedUmbrellas->sideStart.clear();
  }
  const UmbrellaData& umbrellas = seedUmbrellas ? *seedUmbrellas : prepared.umbrellas;
  r.times.umbrellas = watch.seconds();

  const SelectedFacets selected = selectFacetsByAngleAndRatio(dv, umbrellas, params);
  r.times.selection = selected.seconds;

  procConvexEdges(dv, samples, selected, r.forced);
  procNonconcaveCorners(dv, samples, selected, r.forced);
  r.times.convexEdges = r.forced.convexSeconds;
  r.times.corners = r.forced.cornerSeconds;

  watch.restart();
  std::vector<std::uint8_t> cellSide;
  // The walk (through unbounded facets) and the relabel of unreached facets
  // read cellSide, and only on the rings of selected facets.
  const bool walkReadsSides = params.walkStaysOutside && selected.unboundedCount > 0;
  if (walkReadsSides || params.innerNeedsInsideVertices) {
    std::vector<std::uint8_t> onRing(dv.cellCount(), 0);
    for (Index c : selected.ringCells)
      if (c < onRing.size()) onRing[c] = 1;
    const double spacing = samples.spacing > 0 ? samples.spacing : samples.bboxDiagonal() / 40;
    std::unique_ptr<CellSideInputs> built;
    if (!prepared.cellSides) built = std::make_unique<CellSideInputs>(samples);
    cellSide = classifyCellSides(dv, samples, built ? *built : *prepared.cellSides,
                                 params.nearSurfaceFraction * spacing, &onRing);
  }
  r.times.cellSides = watch.seconds();
  r.labels = separateInnerOuter(dv, samples, selected, r.forced, params, oracle, cellSide, exactSideNearSurface);
  r.times.walk = r.labels.seconds;
  r.times.oracle = r.labels.oracleSeconds;

  watch.restart();
  static_cast<MedialComplex&>(r) = buildInnerComplex(dv, samples, selected, r.forced, r.labels);
  if (params.fillSingleFacetHoles) r.counts.singleFacetHolesFilled = fillSingleFacetHoles(dv, selected, r);
  const double spacing = samples.spacing > 0 ? samples.spacing : samples.bboxDiagonal() / 40;
  // The fringe's dominance (v's ball nearly inside u's), also read by the nested-island rule.
  const double fringeCosBeta = std::cos(params.fringeBetaDeg * 3.14159265358979323846 / 180.0);
  if (params.thinFringe && spacing > 0 && r.polygonCount() > 0) {  // no scale on flat or empty input
    FringeThinningParams fringe;
    fringe.cosBeta = fringeCosBeta;
    fringe.minReach = params.fringeMinReachFraction * spacing;
    fringe.slack = params.fringeSlackFraction * spacing;
    r.counts.fringePolygonsThinned = thinFringe(r, samples, fringe);
  }
  // The island rules share the complex's components while none removes anything.
  std::optional<VertexComponents> components;
  if (params.dropPointIslands)
    r.counts.pointIslands = dropPointIslands(r, 1e-9 * samples.bboxDiagonal(), nullptr, &components);
  if (params.dropForcedOnlyIslands) r.counts.forcedOnlyIslands = dropForcedOnlyIslands(r, nullptr, &components);
  if (params.islandRadiusFraction > 0) {
    r.counts.subResolutionIslands = dropSubResolutionIslands(r, params.islandRadiusFraction * spacing,
                                                             &r.counts.subResolutionIslandPolygons, &components);
  }
  if (params.dropNestedIslands && spacing > 0) {
    r.counts.nestedIslands =
        dropNestedIslands(r, fringeCosBeta, params.fringeSlackFraction * spacing, nullptr, &components);
  }
  components.reset();
  // After the rules above, which read one vertex per cell. Voronoi vertices
  // this close are one (cospherical samples).
  r.counts.coincidentVerticesWelded =
      weldCoincidentVertices(r, 1e-9 * samples.bboxDiagonal(), &r.counts.degenerateFacetsDropped);
  r.times.complex = watch.seconds();

  watch.restart();
  r.edges = buildComplexEdges(r);
  if (params.fillShortHoles) r.counts.shortHolesFilled = fillShortHoles(r, r.edges);
  segmentSheets(r, r.edges);
  r.times.sheets = watch.seconds();

  watch.restart();
  if (params.computeTopology) r.topology = computeTopology(r, r.edges, params.bettiCoreLimit);
  r.times.topology = watch.seconds();
  r.times.total = r.times.delaunay + r.times.voronoi + total.seconds() - r.times.oracle;

  MedialCounts& c = r.counts;
  c.samples = samples.size();
  c.duplicateSamples = dv.duplicateCount();
  c.delaunayCells = dv.finiteCellCount();
  c.delaunayEdges = selected.finiteEdges;
  c.selectedFacets = selected.size();
  c.unboundedFacets = selected.unboundedCount;
  c.innerFacets = r.labels.innerFacets;
  c.outerFacets = r.labels.outerFacets;
  c.convexEdgeTriangles = r.forced.convexEdgeTriangles;
  c.convexFillTriangles = r.forced.convexFillTriangles;
  c.cornerTriangles = r.forced.cornerTriangles;
  c.outerCornerTriangles = r.labels.outerCornerTriangles;
  c.tripletsNotDelaunay = r.forced.tripletsNotDelaunay;
  c.tripletsOnHull = r.forced.tripletsOnHull;
  c.degenerateUmbrellaTriangles = umbrellas.degenerateTriangles;
  c.samplesWithoutUmbrella = umbrellas.samplesWithoutUmbrella;
  c.sheets = r.sheetCount;
  c.walkBlockedCrossings = r.labels.blockedCrossings;
  c.walkSurfaceCrossingsRefused = r.labels.surfaceCrossingsRefused;
  c.innerFacetsOutsideSurface = r.labels.innerFacetsOutsideSurface;
  c.nearFacetsOutsideExactly = r.labels.nearFacetsOutsideExactly;
  c.oracleChecked = r.labels.oracleFacetsChecked;
  c.oracleDisagreements = r.labels.oracleFacetDisagreements;
  c.oracleForcedChecked = r.labels.oracleForcedChecked;
  c.oracleForcedDisagreements = r.labels.oracleForcedDisagreements;
  return r;
}

}  // namespace cadmedial
