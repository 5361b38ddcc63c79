#include <algorithm>
#include <iterator>

#include "cadmedial/forced_triangles.hpp"
#include "cadmedial/timer.hpp"

namespace cadmedial {

namespace {

struct FanContext {
  const DelaunayVoronoi& dv;
  const SelectedFacets& selected;
  const std::vector<Index>& tripletOf;               // per canonical sample
  const std::vector<std::array<Index, 2>>& redCells;  // per triplet

  // Is finite cell v an end of a fan triangle x v w at sample x (the
  // triplet's own triangle, or the corner rule on a facet of v through x)?
  bool inFan(Index v, Index x) const {
    const Index t = tripletOf[x];
    if (t != kNoIndex && (redCells[t][0] == v || redCells[t][1] == v)) return true;
    const auto c = dv.cell(v);
    int ix = -1;
    for (int i = 0; i < 4; ++i)
      if (dv.cellSample(v, i) == x) ix = i;
    if (ix < 0) return false;
    for (int k = 0; k < 4; ++k) {
      if (k == ix) continue;
      if (dv.isInfinite(DelaunayVoronoi::cellId(c->neighbor(k)))) continue;
      Index qr[2];
      int n = 0;
      for (int i = 0; i < 4; ++i)
        if (i != k && i != ix) qr[n++] = dv.cellSample(v, i);
      if (cornerRuleFacet(selected, x, qr[0], qr[1]) != kNoIndex) return true;
    }
    return false;
  }
};

}  // namespace

void procConvexEdges(const DelaunayVoronoi& dv, const SampleSet& samples, const SelectedFacets& selected,
                     ForcedTriangles& out) {
  Stopwatch watch;
  if (dv.dimension() < 3) return;
  const auto& dt = dv.triangulation();
  const std::size_t n = samples.size();
  std::vector<Index> tripletOf(n, kNoIndex);
  std::vector<std::array<Index, 2>> redCells(samples.triplets.size(), {kNoIndex, kNoIndex});
  std::vector<std::uint8_t> fanAtCorner(n, 0);
  for (std::size_t i = 0; i < samples.isNonConcaveCorner.size(); ++i)
    if (samples.isNonConcaveCorner[i]) fanAtCorner[dv.canonicalSample(static_cast<Index>(i))] = 1;

  // 1. The triplet triangles.
  for (std::size_t k = 0; k < samples.triplets.size(); ++k) {
    const Triplet& t = samples.triplets[k];
    const Index s = dv.canonicalSample(t.s);
    const Index l = dv.canonicalSample(t.sLeft);
    const Index r = dv.canonicalSample(t.sRight);
    DelaunayVoronoi::Cell_handle c;
    int i = 0, j = 0, m = 0;
    if (s == l || s == r || l == r || !dt.is_facet(dv.vertex(s), dv.vertex(l), dv.vertex(r), c, i, j, m)) {
      ++out.tripletsNotDelaunay;
      continue;
    }
    const Index c1 = DelaunayVoronoi::cellId(c);
    const Index c2 = DelaunayVoronoi::cellId(c->neighbor(6 - i - j - m));
    if (dv.isInfinite(c1) || dv.isInfinite(c2)) {
      ++out.tripletsOnHull;
      continue;
    }
    if (tripletOf[s] != kNoIndex) continue;  // a second triplet at the same sample adds nothing
    tripletOf[s] = static_cast<Index>(k);
    redCells[k] = {c1, c2};
    ForcedTriangle tri;
    tri.kind = PolygonProvenance::ConvexEdgeTriangle;
    tri.samples = {s, kNoIndex};
    tri.cells = {c1, c2};
    tri.attachedFacet = selected.find(l, r);
    tri.source = static_cast<Index>(k);
    if (tri.attachedFacet == kNoIndex) ++out.tripletsUnattached;
    out.triangles.push_back(tri);
    ++out.convexEdgeTriangles;
  }

  // 2. The rest of the fan at each triplet sample.
  std::vector<DelaunayVoronoi::Facet> facets;
  for (std::size_t k = 0; k < samples.triplets.size(); ++k) {
    if (redCells[k][0] == kNoIndex) continue;
    const Index s = dv.canonicalSample(samples.triplets[k].s);
    dv.finiteIncidentFacets(s, facets);
    for (const auto& f : facets) {
      const Index c1 = DelaunayVoronoi::cellId(f.first);
      const Index c2 = DelaunayVoronoi::cellId(f.first->neighbor(f.second));
      if ((c1 == redCells[k][0] && c2 == redCells[k][1]) || (c1 == redCells[k][1] && c2 == redCells[k][0])) continue;
      if (dv.isInfinite(c1) || dv.isInfinite(c2)) continue;
      Index qr[2];
      int cnt = 0;
      for (int i = 0; i < 4; ++i) {
        if (i == f.second) continue;
        const Index v = dv.cellSample(c1, i);
        if (v == s) continue;
        if (cnt < 2) qr[cnt] = v;
        ++cnt;
      }
      if (cnt != 2) continue;
      const Index facetQR = cornerRuleFacet(selected, s, qr[0], qr[1]);
      if (facetQR == kNoIndex) continue;
      ForcedTriangle tri;
      tri.kind = PolygonProvenance::ConvexEdgeTriangle;
      tri.samples = {s, kNoIndex};
      tri.cells = {c1, c2};
      tri.attachedFacet = facetQR;
      tri.source = static_cast<Index>(k);
      out.triangles.push_back(tri);
      ++out.convexFanTriangles;
    }
  }

  // 3. Fills between consecutive feature samples, each gap once.
  // A vertex where one convex edge meets only concave or smooth ones (the
  // foot of a boss's vertical edge on its plate) has no fan of its own, but
  // the edge's sheet reaches it: the gap to the edge's first sample is
  // filled from that sample's fan alone (`oneSided`). A new vertex coned
  // over edges of one fan adds no loop; with two or more convex edges at
  // the vertex (a pocket's rim corner) it would join their sheets a second
  // time, so those stay open.
  std::vector<int> convexEdgesAt(n, 0);
  for (const EdgeInfo& e : samples.edges) {
    if (e.kind != EdgeKind::Convex || e.samples.size() < 2) continue;
    ++convexEdgesAt[dv.canonicalSample(e.samples.front())];
    ++convexEdgesAt[dv.canonicalSample(e.samples.back())];
  }
  struct Gap {
    Index a, b, triplet;
    bool oneSided = false;  // only b (the triplet sample) has a fan; a is the vertex
  };
  std::vector<Gap> gaps;
  for (std::size_t k = 0; k < samples.triplets.size(); ++k) {
    if (redCells[k][0] == kNoIndex) continue;
    const Triplet& t = samples.triplets[k];
    const Index s = dv.canonicalSample(t.s);
    for (Index nb : {t.prev, t.next}) {
      if (nb == kNoIndex) continue;
      const Index sn = dv.canonicalSample(nb);
      if (sn == s) continue;
      const bool hasFan = (tripletOf[sn] != kNoIndex) || fanAtCorner[sn];
      if (hasFan) {
        gaps.push_back({std::min(s, sn), std::max(s, sn), static_cast<Index>(k)});
      } else if (samples.kind[sn] == SampleKind::Corner && convexEdgesAt[sn] == 1) {
        gaps.push_back({sn, s, static_cast<Index>(k), true});
      }
    }
  }
  std::sort(gaps.begin(), gaps.end(), [](const Gap& x, const Gap& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
  const FanContext fan{dv, selected, tripletOf, redCells};
  for (std::size_t g = 0; g < gaps.size(); ++g) {
    if (g > 0 && gaps[g].a == gaps[g - 1].a && gaps[g].b == gaps[g - 1].b) {
      ++out.fillDuplicatesMerged;
      continue;
    }
    const Index a = gaps[g].a, b = gaps[g].b;
    DelaunayVoronoi::Cell_handle c;
    int i = 0, j = 0;
    if (!dt.is_edge(dv.vertex(a), dv.vertex(b), c, i, j)) {
      ++out.gapsNotDelaunay;
      continue;
    }
    std::size_t added = 0;
    auto circ = dt.incident_cells(c, i, j);
    const auto start = circ;
    do {
      const Index v = DelaunayVoronoi::cellId(circ);
      if (!dv.isInfinite(v) && (gaps[g].oneSided || fan.inFan(v, a)) && fan.inFan(v, b)) {
        ForcedTriangle fill;
        fill.kind = PolygonProvenance::ConvexEdgeFillTriangle;
        fill.samples = {a, b};
        fill.cells = {v, kNoIndex};
        fill.source = gaps[g].triplet;
        out.triangles.push_back(fill);
        ++added;
      }
      ++circ;
    } while (circ != start);
    out.convexFillTriangles += added;
    if (added == 0) ++out.gapsWithoutFill;
  }
  out.convexSeconds += watch.seconds();
}

}  // namespace cadmedial
