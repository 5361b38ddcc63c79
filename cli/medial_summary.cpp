#include "medial_summary.hpp"

#include "report_json.hpp"

namespace cadmedial {

nlohmann::json medialSummaryJson(const SamplingReport& sampling, const MedialResult& m, const MedialParams& params) {
  const MedialCounts& c = m.counts;
  const MedialTimes& t = m.times;
  nlohmann::json j;
  j["parameters"] = {{"theta_deg", params.thetaDeg}, {"rho", params.rho}};
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
  j["topology"] = {{"euler", m.topology.euler}, {"beta0", m.topology.beta0}, {"beta1", m.topology.beta1},
                   {"beta2", m.topology.beta2}};
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
                  {"medial_total", t.total}};
  j["sampling"] = toJson(sampling);
  return j;
}

}  // namespace cadmedial
