#include "medial_summary.hpp"

#include "report_json.hpp"

namespace cadmedial {

namespace {

nlohmann::json topologyJson(const MedialResult& m) {
  return {{"euler", m.topology.euler}, {"beta0", m.topology.beta0}, {"beta1", m.topology.beta1},
          {"beta2", m.topology.beta2}};
}

nlohmann::json parametersJson(const MedialParams& params) {
  return {{"theta_deg", params.thetaDeg}, {"rho", params.rho}};
}

}  // namespace

nlohmann::json medialSummaryJson(const SamplingReport& sampling, const MedialResult& m, const MedialParams& params) {
  const MedialCounts& c = m.counts;
  const MedialTimes& t = m.times;
  nlohmann::json j;
  j["algorithm"] = "CAD_MEDIAL";
  j["axis"] = "inner";
  j["parameters"] = parametersJson(params);
  j["counts"] = {{"samples", c.samples},
                 {"duplicate_samples", c.duplicateSamples},
                 {"delaunay_cells", c.delaunayCells},
                 {"delaunay_edges", c.delaunayEdges},
                 {"selected_facets", c.selectedFacets},
                 {"unbounded_facets", c.unboundedFacets},
                 {"inner_facets", c.innerFacets},
                 {"outer_facets", c.outerFacets},
                 {"forced_triangles",
                  {{"convex_edge", c.convexEdgeTriangles},
                   {"convex_edge_fill", c.convexFillTriangles},
                   {"corner", c.cornerTriangles},
                   {"corner_outer_dropped", c.outerCornerTriangles}}},
                 {"medial_vertices", m.vertices.size()},
                 {"medial_polygons", m.polygonCount()},
                 {"sheets", c.sheets}};
  j["topology"] = topologyJson(m);
  j["diagnostics"] = {{"triplets_not_delaunay", c.tripletsNotDelaunay},
                      {"triplets_on_hull", c.tripletsOnHull},
                      {"convex_gaps_without_fill", m.forced.gapsWithoutFill},
                      {"convex_gaps_not_delaunay", m.forced.gapsNotDelaunay},
                      {"triplets_unattached", m.forced.tripletsUnattached},
                      {"samples_without_umbrella", c.samplesWithoutUmbrella},
                      {"degenerate_umbrella_triangles", c.degenerateUmbrellaTriangles},
                      {"walk_blocked_crossings", c.walkBlockedCrossings},
                      {"walk_surface_crossings_refused", c.walkSurfaceCrossingsRefused},
                      {"inner_facets_outside_surface", c.innerFacetsOutsideSurface},
                      {"near_facets_outside_exactly", c.nearFacetsOutsideExactly},
                      {"single_facet_holes_filled", c.singleFacetHolesFilled},
                      {"short_holes_filled", c.shortHolesFilled},
                      {"fringe_polygons_thinned", c.fringePolygonsThinned},
                      {"sub_resolution_islands", c.subResolutionIslands},
                      {"sub_resolution_island_polygons", c.subResolutionIslandPolygons},
                      {"point_islands_dropped", c.pointIslands},
                      {"forced_only_islands_dropped", c.forcedOnlyIslands},
                      {"nested_islands_dropped", c.nestedIslands},
                      {"coincident_vertices_welded", c.coincidentVerticesWelded},
                      {"degenerate_facets_dropped", c.degenerateFacetsDropped},
                      {"walk_oracle_checked", c.oracleChecked},
                      {"walk_oracle_disagreements", c.oracleDisagreements}};
  j["seconds"] = {{"classify", sampling.secondsClassify},
                  {"sample", sampling.secondsSample},
                  {"reconstruct", sampling.secondsReconstruct},
                  {"delaunay", t.delaunay},
                  {"voronoi", t.voronoi},
                  {"umbrellas", t.umbrellas},
                  {"filter", t.selection},
                  {"convex_edges", t.convexEdges},
                  {"corners", t.corners},
                  {"cell_sides", t.cellSides},
                  {"walk", t.walk},
                  {"oracle_check", t.oracle},
                  {"complex", t.complex},
                  {"sheets", t.sheets},
                  {"topology", t.topology},
                  {"medial_total", t.total},
                  {"prepared_alongside_delaunay", t.preparedAlongside}};
  j["sampling"] = toJson(sampling);
  return j;
}

nlohmann::json pointMedialSummaryJson(const PointInput& input, const PointMedialResult& m, const MedialParams& params) {
  const MedialCounts& c = m.counts;
  const PointMedialInfo& info = m.cloud;
  const MedialTimes& t = m.times;
  nlohmann::json j;
  j["algorithm"] = "MEDIAL";
  j["axis"] = info.part == MedialAxisPart::Inner ? "inner" : "whole";
  j["axis_note"] = info.axisNote;
  j["parameters"] = parametersJson(params);
  j["input"] = {{"format", input.format}, {"points", input.points.size()}, {"mesh_triangles", input.triangles.size()}};
  if (info.meshGiven)
    j["input"]["mesh"] = {{"closed_oriented", info.mesh.closedManifold()},
                          {"border_edges", info.mesh.boundaryEdges},
                          {"non_manifold_edges", info.mesh.nonManifoldEdges},
                          {"misoriented_edges", info.mesh.misorientedEdges},
                          {"non_manifold_vertices", info.mesh.nonManifoldVertices},
                          {"components", info.mesh.components},
                          {"enclosed_volume", info.mesh.enclosedVolume}};
  j["counts"] = {{"samples", c.samples},
                 {"duplicate_samples", c.duplicateSamples},
                 {"delaunay_cells", c.delaunayCells},
                 {"delaunay_edges", c.delaunayEdges},
                 {"hull_samples", info.unboundedCells},
                 {"umbrella_triangles", info.umbrellaTriangles},
                 {"selected_facets", c.selectedFacets},
                 {"unbounded_facets_dropped", info.unboundedFacetsDropped},
                 {"outside_facets_dropped", info.outsideFacetsDropped},
                 {"output_facets", c.innerFacets},
                 {"medial_vertices", m.vertices.size()},
                 {"medial_polygons", m.polygonCount()},
                 {"sheets", c.sheets}};
  j["topology"] = topologyJson(m);
  j["diagnostics"] = {{"empty_umbrellas", info.emptyUmbrellas},
                      {"zero_pole_vectors", info.zeroPoleVectors},
                      {"samples_without_umbrella", c.samplesWithoutUmbrella},
                      {"degenerate_umbrella_triangles", c.degenerateUmbrellaTriangles}};
  j["seconds"] = {{"delaunay", t.delaunay},     {"voronoi", t.voronoi},
                  {"poles", info.polesSeconds}, {"tangent_umbrellas", info.tangentUmbrellaSeconds},
                  {"umbrellas", t.umbrellas},   {"filter", t.selection},
                  {"inside", info.insideSeconds}, {"complex", t.complex},
                  {"sheets", t.sheets},         {"topology", t.topology},
                  {"medial_total", t.total}};
  return j;
}

}  // namespace cadmedial
