#include <algorithm>
#include <vector>

#include "cadmedial/polygon_complex.hpp"
#include "cadmedial/vec3_ops.hpp"

namespace cadmedial {

// Why: where a wall is thinner than the sampling resolves (the sliver at a
// zero-angle cusp, a neck below the finest spacing), the filter and the walk
// keep the facets of the sheet there only here and there, and the sheet is
// left with pinholes: each one a spurious loop (β1). fillSingleFacetHoles
// closes a hole that is exactly one unselected Voronoi facet; these are not
// (their rims join facets of different cells, or vertices the weld merged).
// A hole whose rim is short against the balls on it cannot be a loop of the
// true axis: if the rim's length L is below r, the radius at one of its
// vertices v, every point of the fan from v over the rim lies within L/2 of
// v, inside v's medial ball and so inside the solid; a loop that bounds a
// disk inside the solid is null-homotopic there, and the inner medial axis
// is homotopy equivalent to the solid. (L < 2r would do for exact balls; L < r
// leaves half the ball for balls that poke out by the sampling's error.)
// A loop around a real tunnel of the solid has every ball on it outside the
// tunnel, so its rim is longer than twice any of its radii. Where walls are
// thinner than the sampling resolves, one Voronoi ball may reach through the
// wall, so r is the rim's median radius, not its largest: half the balls on
// a rim would have to be that wrong (on the cusp box below, 39 of the 40
// holes the largest radius closes).
// Only rims that are simple cycles of border edges (every vertex on exactly
// two) are closed, by one polygon through the rim's vertices in order: it
// adds no vertex and no edge (medialness, coverage and attachment stay as
// they are). A rim that is the mouth of a closed pocket is left open: it
// bounds a disk in the complex already, so closing it removes no loop and
// encloses a void (β2).
std::size_t fillShortHoles(MedialComplex& mc, ComplexEdges& edges) {
  const std::size_t nv = mc.vertices.size(), ne = edges.vertices.size();
  // Border edges per vertex (CSR).
  std::vector<Index> offsets(nv + 1, 0);
  for (std::size_t e = 0; e < ne; ++e)
    if (edges.polygonCount[e] == 1) {
      ++offsets[edges.vertices[e][0] + 1];
      ++offsets[edges.vertices[e][1] + 1];
    }
  for (std::size_t v = 0; v < nv; ++v) offsets[v + 1] += offsets[v];
  std::vector<Index> borderEdges(offsets[nv]);
  {
    std::vector<Index> fill(offsets.begin(), offsets.end() - 1);
    for (std::size_t e = 0; e < ne; ++e)
      if (edges.polygonCount[e] == 1)
        for (Index v : edges.vertices[e]) borderEdges[fill[v]++] = static_cast<Index>(e);
  }
  auto degree = [&](Index v) { return offsets[v + 1] - offsets[v]; };

  std::vector<std::uint8_t> visited(ne, 0);
  std::vector<Index> rim, rimEdges;
  std::vector<double> radii;
  std::size_t filled = 0;
  for (std::size_t start = 0; start < ne; ++start) {
    if (edges.polygonCount[start] != 1 || visited[start]) continue;
    // Walk the rim from edge `start`; give up at a vertex with other than
    // two border edges (the walk still marks what it passed).
    rim.clear();
    rimEdges.clear();
    bool simple = true;
    double length = 0;
    Index e = static_cast<Index>(start), v = edges.vertices[start][0];
    while (!visited[e]) {
      visited[e] = 1;
      if (degree(v) != 2) simple = false;
      rim.push_back(v);
      rimEdges.push_back(e);
      const Index w = edges.vertices[e][0] == v ? edges.vertices[e][1] : edges.vertices[e][0];
      length += vec3::norm(vec3::sub(mc.vertices[v], mc.vertices[w]));
      if (degree(w) != 2) {
        simple = false;
        break;
      }
      const Index* at = &borderEdges[offsets[w]];
      e = at[0] == e ? at[1] : at[0];
      v = w;
    }
    if (!simple || v != edges.vertices[start][0] || rim.size() < 3) continue;
    radii.clear();
    for (Index u : rim) radii.push_back(mc.radius[u]);
    std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
    if (!(length < radii[radii.size() / 2])) continue;
    // The fill adds no edge: its rim edges go from border to manifold, and
    // slot k of the new polygon is rimEdges[k] (from rim[k] to the next).
    const Index fill = static_cast<Index>(mc.polygonCount());
    for (Index re : rimEdges) {
      edges.polygonCount[re] = 2;
      edges.secondPolygon[re] = fill;
    }
    edges.slotEdge.insert(edges.slotEdge.end(), rimEdges.begin(), rimEdges.end());
    edges.borderEdges -= rimEdges.size();
    edges.manifoldEdges += rimEdges.size();
    mc.polygonVertices.insert(mc.polygonVertices.end(), rim.begin(), rim.end());
    mc.polygonOffsets.push_back(static_cast<Index>(mc.polygonVertices.size()));
    mc.provenance.push_back(PolygonProvenance::HoleFill);
    mc.provenanceSamples.push_back({kNoIndex, kNoIndex});
    ++filled;
  }
  if (filled == 0) return 0;
  // A fill left in the 2-core after free-face collapses closes a pocket
  // (NIST CTC-01 had one: β2 0 -> 1). Fills are taken out of the core one at
  // a time, newest first, and the collapses go on after each: of a tube's
  // two short mouths only the second goes, and the first, now collapsible,
  // stays (closing one end of a tube kills its loop, both make a void).
  const std::size_t firstFill = mc.polygonCount() - filled;
  FreeFaceCollapse collapse(mc, edges);
  std::vector<std::uint8_t> keep(mc.polygonCount(), 1);
  for (std::size_t p = mc.polygonCount(); p-- > firstFill;)
    if (collapse.inCore(static_cast<Index>(p))) {
      collapse.removeFromCore(static_cast<Index>(p));
      keep[p] = 0;
      --filled;
    }
  if (filled < mc.polygonCount() - firstFill) {
    keepPolygons(mc, keep);  // drops no vertex: the fills added none
    edges = buildComplexEdges(mc);
  }
  mc.sheet.assign(mc.polygonCount(), kNoIndex);
  mc.sheetCount = 0;
  return filled;
}

}  // namespace cadmedial
