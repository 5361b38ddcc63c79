#include <algorithm>
#include <atomic>
#include <cstdint>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "cadmedial/edge_table.hpp"
#include "cadmedial/polygon_complex.hpp"

namespace cadmedial {
namespace {

struct Vote {
  std::uint64_t edge;  // PairTable::key of a Delaunay edge
  Index cell;          // a cell around it, to circulate from
};

}  // namespace

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
// Cost: one parallel pass over the complex's polygon edges and one sort,
// instead of a circulation around every Delaunay edge next to the axis
// (that cost about the Delaunay time on a 53 k-sample box). A facet's
// boundary is the ring of triangles around its Delaunay edge, so the facet is
// a hole exactly when the number of distinct complex Voronoi edges
// (= triangles) containing that Delaunay edge equals the edge's degree; only
// unselected edges counted at least three times are circulated.
std::size_t fillSingleFacetHoles(const DelaunayVoronoi& dv, const SelectedFacets& selected, MedialComplex& mc) {
  if (dv.dimension() < 3) return 0;
  const auto& dt = dv.triangulation();
  std::vector<Index> cellVertex(dv.cellCount(), kNoIndex);
  for (std::size_t v = 0; v < mc.vertices.size(); ++v)
    if (mc.vertexCell[v] != kNoIndex) cellVertex[mc.vertexCell[v]] = static_cast<Index>(v);

  // Each distinct Voronoi edge of the complex (the triangle shared by two
  // cells, named by the lower cell and its facet index) votes once for each
  // of its three Delaunay edges.
  std::vector<std::atomic<std::uint8_t>> seen(4 * dv.cellCount());  // value-initialised: 0
  tbb::enumerable_thread_specific<std::vector<Vote>> votesPerThread;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mc.polygonCount(), 1024),
                    [&](const tbb::blocked_range<std::size_t>& range) {
    auto& out = votesPerThread.local();
    if (out.capacity() == 0) out.reserve(mc.polygonVertices.size() + 16);
    for (std::size_t p = range.begin(); p != range.end(); ++p) {
      const Index b = mc.polygonOffsets[p], e = mc.polygonOffsets[p + 1];
      for (Index k = b; k < e; ++k) {
        Index cu = mc.vertexCell[mc.polygonVertices[k]];
        Index cv = mc.vertexCell[mc.polygonVertices[k + 1 < e ? k + 1 : b]];
        if (cu == kNoIndex || cv == kNoIndex || cu == cv) continue;
        if (cu > cv) std::swap(cu, cv);
        const auto ca = dv.cell(cu);
        const int facet = ca->index(dv.cell(cv));  // ca's vertex opposite the shared triangle
        if (facet < 0 || facet > 3 || seen[4 * std::size_t(cu) + facet].exchange(1)) continue;
        for (int i = 0; i < 4; ++i)
          for (int j = i + 1; j < 4; ++j)
            if (i != facet && j != facet)
              out.push_back({PairTable::key(ca->vertex(i)->info(), ca->vertex(j)->info()), cu});
      }
    }
  });
  std::vector<Vote> votes;
  std::size_t voteCount = 0;
  for (const auto& part : votesPerThread) voteCount += part.size();
  votes.reserve(voteCount);
  for (const auto& part : votesPerThread) votes.insert(votes.end(), part.begin(), part.end());
  tbb::parallel_sort(votes.begin(), votes.end(),
                     [](const Vote& x, const Vote& y) { return x.edge != y.edge ? x.edge < y.edge : x.cell < y.cell; });

  // Selected edges never become holes (inner: already there; outer: the
  // walk decided); a merge with their sorted keys replaces a hash lookup per run.
  std::vector<std::uint64_t> selectedKeys(selected.size());
  for (std::size_t f = 0; f < selected.size(); ++f) selectedKeys[f] = PairTable::key(selected.edge[f][0], selected.edge[f][1]);
  tbb::parallel_sort(selectedKeys.begin(), selectedKeys.end());

  std::size_t added = 0;
  std::vector<Index> ring;
  auto nextSelected = selectedKeys.begin();
  for (std::size_t r = 0; r < votes.size();) {
    std::size_t end = r;
    while (end < votes.size() && votes[end].edge == votes[r].edge) ++end;
    const std::size_t count = end - r;
    const std::uint64_t key = votes[r].edge;
    const Index from = votes[r].cell;
    r = end;
    if (count < 3) continue;
    while (nextSelected != selectedKeys.end() && *nextSelected < key) ++nextSelected;
    if (nextSelected != selectedKeys.end() && *nextSelected == key) continue;
    const Index a = static_cast<Index>(key >> 32), b = static_cast<Index>(key);
    const auto c = dv.cell(from);
    int i = -1, j = -1;
    for (int k = 0; k < 4; ++k) {
      if (dt.is_infinite(c->vertex(k))) continue;
      if (c->vertex(k)->info() == a) i = k;
      if (c->vertex(k)->info() == b) j = k;
    }
    if (i < 0 || j < 0) continue;
    ring.clear();
    auto circ = dt.incident_cells(c, i, j);
    const auto start = circ;
    do {
      ring.push_back(DelaunayVoronoi::cellId(circ));
      ++circ;
    } while (circ != start && ring.size() <= count);
    if (ring.size() != count) continue;  // some triangle around the edge is not on the complex
    // Every triangle around the edge is a complex Voronoi edge, so every cell
    // on the ring is finite and a complex vertex.
    for (Index cell : ring) mc.polygonVertices.push_back(cellVertex[cell]);
    mc.polygonOffsets.push_back(static_cast<Index>(mc.polygonVertices.size()));
    mc.provenance.push_back(PolygonProvenance::DelaunayEdgeFacet);
    mc.provenanceSamples.push_back({a, b});
    ++added;
  }
  mc.sheet.assign(mc.polygonCount(), kNoIndex);
  return added;
}

}  // namespace cadmedial
