#include "cadmedial/edge_table.hpp"
#include "cadmedial/polygon_complex.hpp"

namespace cadmedial {

// Why: the Angle/Ratio filter judges each Delaunay edge on its own. Where the
// axis is a jumble of facets (near a 1-D part of the axis such as a rod's
// centre line, or in a plate not much thicker than the spacing) a tangent
// "tunnel" edge between two samples of one face can have a small Voronoi
// facet deep inside, bounded only by Voronoi edges of selected inner facets:
// the filter drops it (its edge is tangent to both umbrellas and short) and
// leaves a one-facet hole, i.e. a spurious 1-cycle (rod: the only extra
// cycle is the three Voronoi edges of a degree-3 Delaunay edge; NIST FTC-11
// likewise). A facet whose every vertex and edge already lies on the inner
// complex is a convex disk spanned by points of the inner axis, so adding it
// only kills cycles that are null-homotopic through that disk: it adds no
// vertex (medialness, coverage, attachment unchanged), and a loop around a
// tunnel of the solid bounds no such disk unless the facet leaves the solid
// between its inner vertices (a tunnel thinner than one Voronoi facet, i.e.
// far below the sampling resolution). Single-pass: holes of two or more
// facets stay.
std::size_t fillSingleFacetHoles(const DelaunayVoronoi& dv, const SelectedFacets& selected, MedialComplex& mc) {
  if (dv.dimension() < 3) return 0;
  const auto& dt = dv.triangulation();
  std::vector<Index> cellVertex(dv.cellCount(), kNoIndex);
  for (std::size_t v = 0; v < mc.vertices.size(); ++v)
    if (mc.vertexCell[v] != kNoIndex) cellVertex[mc.vertexCell[v]] = static_cast<Index>(v);

  // Voronoi edges of the complex, as pairs of cells.
  PairTable voronoiEdges;
  voronoiEdges.reserve(mc.polygonVertices.size() / 2 + 16);
  std::vector<std::array<Index, 2>> edgeList;
  for (std::size_t p = 0; p < mc.polygonCount(); ++p) {
    const Index b = mc.polygonOffsets[p], e = mc.polygonOffsets[p + 1];
    for (Index k = b; k < e; ++k) {
      const Index cu = mc.vertexCell[mc.polygonVertices[k]];
      const Index cv = mc.vertexCell[mc.polygonVertices[k + 1 < e ? k + 1 : b]];
      if (cu == kNoIndex || cv == kNoIndex || cu == cv) continue;
      if (voronoiEdges.insert(cu, cv, static_cast<Index>(edgeList.size())) == edgeList.size())
        edgeList.push_back({cu, cv});
    }
  }

  // Candidates: the unselected Delaunay edges of the triangles dual to those
  // Voronoi edges (the facets that contain a Voronoi edge of the complex).
  PairTable tried;
  tried.reserve(3 * edgeList.size() + 16);
  std::size_t added = 0;
  std::vector<Index> ring;
  for (const auto& ve : edgeList) {
    const auto ca = dv.cell(ve[0]);
    const auto cb = dv.cell(ve[1]);
    const int ib = ca->index(cb);  // ca's vertex opposite the shared triangle
    if (ib < 0 || ib > 3) continue;
    for (int i = 0; i < 4; ++i) {
      if (i == ib) continue;
      for (int j = i + 1; j < 4; ++j) {
        if (j == ib) continue;
        const auto vi = ca->vertex(i), vj = ca->vertex(j);
        if (dt.is_infinite(vi) || dt.is_infinite(vj)) continue;
        const Index a = vi->info(), b = vj->info();
        if (selected.find(a, b) != kNoIndex) continue;  // inner: already there; outer: its label decides
        const std::size_t triedBefore = tried.size();
        tried.insert(a, b, 1);
        if (tried.size() == triedBefore) continue;  // each Delaunay edge once
        ring.clear();
        bool closed = true;
        auto circ = dt.incident_cells(ca, i, j);
        const auto start = circ;
        do {
          const Index cid = DelaunayVoronoi::cellId(circ);
          if (dv.isInfinite(cid) || cellVertex[cid] == kNoIndex) {
            closed = false;
            break;
          }
          ring.push_back(cid);
          ++circ;
        } while (circ != start);
        if (!closed || ring.size() < 3) continue;
        for (std::size_t t = 0; t < ring.size() && closed; ++t)
          closed = voronoiEdges.find(ring[t], ring[(t + 1) % ring.size()]) != kNoIndex;
        if (!closed) continue;
        for (Index c : ring) mc.polygonVertices.push_back(cellVertex[c]);
        mc.polygonOffsets.push_back(static_cast<Index>(mc.polygonVertices.size()));
        mc.provenance.push_back(PolygonProvenance::DelaunayEdgeFacet);
        mc.provenanceSamples.push_back({std::min(a, b), std::max(a, b)});
        ++added;
      }
    }
  }
  mc.sheet.assign(mc.polygonCount(), kNoIndex);
  return added;
}

}  // namespace cadmedial
