#include "cadmedial/compute_medial.hpp"

#include <stdexcept>
#include <string>

#include "cadmedial/cell_sides.hpp"
#include "cadmedial/medial_poles.hpp"
#include "cadmedial/medial_umbrellas.hpp"
#include "cadmedial/timer.hpp"

namespace cadmedial {

SampleSet pointCloudSamples(const std::vector<Vec3>& points, const std::vector<std::array<Index, 3>>& triangles) {
  SampleSet s;
  const std::size_t n = points.size();
  s.points = points;
  s.kind.assign(n, SampleKind::Face);
  s.owner.assign(n, 0);
  s.onConvexEdge.assign(n, 0);
  s.isNonConcaveCorner.assign(n, 0);
  s.triangles = triangles;
  s.triangleFace.assign(triangles.size(), 0);
  s.faceCount = 1;
  if (n > 0) {
    s.bboxMin = s.bboxMax = points[0];
    for (const Vec3& p : points)
      for (int k = 0; k < 3; ++k) {
        s.bboxMin[k] = std::min(s.bboxMin[k], p[k]);
        s.bboxMax[k] = std::max(s.bboxMax[k], p[k]);
      }
  }
  return s;
}

PointMedialResult computeMedial(const std::vector<Vec3>& points, const MedialParams& params,
                                const std::vector<std::array<Index, 3>>& meshTriangles) {
  if (!(params.thetaDeg > 0 && params.thetaDeg < 90)) throw std::invalid_argument("MedialParams: theta must be in (0°, 90°)");
  if (!(params.rho > 0)) throw std::invalid_argument("MedialParams: rho must be positive");
  for (const auto& t : meshTriangles)
    for (Index v : t)
      if (v >= points.size()) throw std::invalid_argument("mesh triangle refers to vertex " + std::to_string(v) +
                                                          " of " + std::to_string(points.size()));
  const SampleSet samples = pointCloudSamples(points, meshTriangles);
  samples.validate();  // non-finite coordinates

  PointMedialResult r;
  PointMedialInfo& info = r.cloud;
  info.meshGiven = !meshTriangles.empty();
  bool inner = false;
  if (info.meshGiven) {
    info.mesh = checkSurfaceMesh(points, meshTriangles);
    inner = info.mesh.closedManifold();
    if (inner) {
      info.axisNote = "inner medial axis (closed, consistently oriented mesh; inside test on the mesh)";
    } else {
      info.axisNote = "whole medial axis, inner and outer: the mesh is not closed and consistently oriented (" +
                      std::to_string(info.mesh.boundaryEdges) + " border, " +
                      std::to_string(info.mesh.nonManifoldEdges) + " non-manifold, " +
                      std::to_string(info.mesh.misorientedEdges) + " misoriented edges, " +
                      std::to_string(info.mesh.nonManifoldVertices) + " non-manifold vertices)";
    }
  } else {
    info.axisNote = "whole medial axis, inner and outer: a bare point cloud has no inside";
  }
  info.part = inner ? MedialAxisPart::Inner : MedialAxisPart::Whole;

  DelaunayVoronoi dv(points);
  r.times.delaunay = dv.delaunaySeconds();
  r.times.voronoi = dv.sideArraySeconds();
  Stopwatch total;
  if (dv.dimension() < 3) {
    info.axisNote = "empty: the points span fewer than 3 dimensions";
    r.labels.facetOuter.clear();
    r.times.total = r.times.delaunay + r.times.voronoi;
    r.counts.samples = points.size();
    r.counts.duplicateSamples = dv.duplicateCount();
    return r;
  }

  // Umbrellas from poles and tangent polygons (Def. 1-3), then the selection
  // shared with CAD_MEDIAL.
  const PoleData poles = computePoles(dv);
  const TangentPolygonUmbrellas tangent = computeTangentPolygonUmbrellas(dv, poles);
  Stopwatch watch;
  const UmbrellaData umbrellas = umbrellaDataOf(points, tangent);
  info.polesSeconds = poles.seconds;
  info.tangentUmbrellaSeconds = tangent.seconds;
  r.times.umbrellas = poles.seconds + tangent.seconds + watch.seconds();
  info.unboundedCells = poles.unboundedCells;
  info.zeroPoleVectors = poles.zeroDirections;
  info.emptyUmbrellas = tangent.emptyUmbrellas;
  info.umbrellaTriangles = tangent.triangles.size();

  const SelectedFacets selected = selectFacetsByAngleAndRatio(dv, umbrellas, params);
  r.times.selection = selected.seconds;

  // Which facets are output: every bounded one, or (closed mesh) those whose
  // Voronoi vertices are all inside. Labels in the form the shared closure
  // (buildInnerComplex) takes; MEDIAL has no forced triangles.
  watch.restart();
  InnerOuterLabels& labels = r.labels;
  labels.facetOuter.assign(selected.size(), 0);
  // A Voronoi vertex a million diagonals away is at infinity for any use of
  // the axis: the exact centre of a sliver of nearly coplanar samples
  // (delaunay.cpp) lies ~1e15 away. Facets through one are dropped with the
  // unbounded ones (the whole axis of an open mesh kept them, 3e18 wide).
  const double farRadius = 1e6 * samples.bboxDiagonal();
  auto reachesInfinity = [&](Index f) {
    if (selected.unbounded[f]) return true;
    for (const Index* c = selected.ringBegin(f); c != selected.ringEnd(f); ++c)
      if (!(dv.circumradius(*c) <= farRadius)) return true;
    return false;
  };
  std::vector<std::uint8_t> cellInside;
  if (inner) {  // the point-in-mesh test is the costly part: only the cells read below
    std::vector<std::uint8_t> onRing(dv.cellCount(), 0);
    for (Index f = 0; f < selected.size(); ++f)
      if (!reachesInfinity(f))
        for (const Index* c = selected.ringBegin(f); c != selected.ringEnd(f); ++c) onRing[*c] = 1;
    cellInside = classifyCellSides(dv, samples, outwardSampleNormals(samples), 0, &onRing);
  }
  for (Index f = 0; f < selected.size(); ++f) {
    if (reachesInfinity(f)) {
      labels.facetOuter[f] = 1;
      ++info.unboundedFacetsDropped;
      continue;
    }
    if (!inner) continue;
    for (const Index* c = selected.ringBegin(f); c != selected.ringEnd(f); ++c)
      if (cellInside[*c] != kCellInside) {
        labels.facetOuter[f] = 1;
        ++info.outsideFacetsDropped;
        break;
      }
  }
  for (std::uint8_t o : labels.facetOuter) (o ? labels.outerFacets : labels.innerFacets) += 1;
  labels.seeds = selected.unboundedCount;
  info.insideSeconds = watch.seconds();
  r.times.walk = info.insideSeconds;

  watch.restart();
  static_cast<MedialComplex&>(r) = buildInnerComplex(dv, samples, selected, r.forced, labels);
  r.times.complex = watch.seconds();
  watch.restart();
  r.edges = buildComplexEdges(r);
  segmentSheets(r, r.edges);
  r.times.sheets = watch.seconds();
  watch.restart();
  r.topology = computeTopology(r, r.edges, params.bettiCoreLimit);
  r.times.topology = watch.seconds();
  r.times.total = r.times.delaunay + r.times.voronoi + total.seconds();

  MedialCounts& c = r.counts;
  c.samples = points.size();
  c.duplicateSamples = dv.duplicateCount();
  c.delaunayCells = dv.finiteCellCount();
  c.delaunayEdges = selected.finiteEdges;
  c.selectedFacets = selected.size();
  c.unboundedFacets = selected.unboundedCount;
  c.innerFacets = labels.innerFacets;
  c.outerFacets = labels.outerFacets;
  c.degenerateUmbrellaTriangles = umbrellas.degenerateTriangles;
  c.samplesWithoutUmbrella = umbrellas.samplesWithoutUmbrella;
  c.sheets = r.sheetCount;
  return r;
}

}  // namespace cadmedial
