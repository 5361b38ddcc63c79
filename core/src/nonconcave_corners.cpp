#include <algorithm>
#include <iterator>

#include "cadmedial/forced_triangles.hpp"
#include "cadmedial/timer.hpp"

namespace cadmedial {

void procNonconcaveCorners(const DelaunayVoronoi& dv, const SampleSet& samples, const SelectedFacets& selected,
                           ForcedTriangles& out) {
  Stopwatch watch;
  if (dv.dimension() < 3) return;

  std::vector<Index> corners;
  for (std::size_t i = 0; i < samples.isNonConcaveCorner.size(); ++i)
    if (samples.isNonConcaveCorner[i]) corners.push_back(dv.canonicalSample(static_cast<Index>(i)));
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());

  std::vector<DelaunayVoronoi::Facet> facets;
  for (Index p : corners) {
    ++out.cornersProcessed;
    dv.finiteIncidentFacets(p, facets);
    for (const auto& f : facets) {
      const auto c = f.first;
      const int opposite = f.second;
      Index qr[2];
      int n = 0;
      for (int i = 0; i < 4; ++i) {
        if (i == opposite) continue;
        const Index v = c->vertex(i)->info();
        if (v == p) continue;
        if (n < 2) qr[n] = v;
        ++n;
      }
      if (n != 2) continue;
      const Index facetQR = selected.find(qr[0], qr[1]);
      if (facetQR == kNoIndex) continue;
      if (selected.find(p, qr[0]) != kNoIndex || selected.find(p, qr[1]) != kNoIndex) {
        ++out.cornerEdgesSuppressed;
        continue;
      }
      const Index c1 = DelaunayVoronoi::cellId(c);
      const Index c2 = DelaunayVoronoi::cellId(c->neighbor(opposite));
      if (dv.isInfinite(c1) || dv.isInfinite(c2)) {
        ++out.cornerEdgesUnbounded;
        continue;
      }
      ForcedTriangle tri;
      tri.kind = PolygonProvenance::CornerTriangle;
      tri.samples = {p, kNoIndex};
      tri.cells = {c1, c2};
      tri.attachedFacet = facetQR;
      tri.source = p;
      out.triangles.push_back(tri);
      ++out.cornerTriangles;
    }
  }
  out.cornerSeconds += watch.seconds();
}

}  // namespace cadmedial
