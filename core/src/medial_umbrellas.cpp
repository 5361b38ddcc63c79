#include "cadmedial/medial_umbrellas.hpp"

#include <tbb/parallel_for.h>

#include <numeric>

#include "cadmedial/timer.hpp"

namespace cadmedial {

namespace {

double sideOf(const Vec3& x, const Vec3& site, const Vec3& normal) {
  return (x[0] - site[0]) * normal[0] + (x[1] - site[1]) * normal[1] + (x[2] - site[2]) * normal[2];
}

// Half-open: a crossing needs one end at side <= 0 and the other at side > 0.
bool crosses(double a, double b) { return (a <= 0 && b > 0) || (a > 0 && b <= 0); }

}  // namespace

TangentPolygonUmbrellas computeTangentPolygonUmbrellas(const DelaunayVoronoi& dv, const PoleData& poles) {
  Stopwatch watch;
  const std::size_t n = dv.sampleCount();
  TangentPolygonUmbrellas out;
  out.offsets.assign(n + 1, 0);
  if (dv.dimension() < 3 || poles.cellOffsets.size() != n + 1) {
    out.seconds = watch.seconds();
    return out;
  }
  const auto& dt = dv.triangulation();
  std::vector<std::vector<std::array<Index, 3>>> perSample(n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 512), [&](const tbb::blocked_range<std::size_t>& range) {
    for (std::size_t p = range.begin(); p != range.end(); ++p) {
      const Vec3& normal = poles.direction[p];
      if (normal == Vec3{0, 0, 0}) continue;
      const auto vp = dv.vertex(static_cast<Index>(p));
      const Vec3 site{vp->point().x(), vp->point().y(), vp->point().z()};
      auto& umbrella = perSample[p];
      for (Index k = poles.cellOffsets[p]; k < poles.cellOffsets[p + 1]; ++k) {
        const Index cid = poles.cells[k];
        const auto c = dv.cell(cid);
        const int ip = c->index(vp);
        // The three facets of c that contain p: opposite each other vertex j.
        for (int j = 0; j < 4; ++j) {
          if (j == ip) continue;
          const auto d = c->neighbor(j);
          const Index did = DelaunayVoronoi::cellId(d);
          if (did < cid) continue;  // each facet once, from its lower cell id
          Index qr[2];
          int m = 0;
          bool finiteFacet = true;
          for (int i = 0; i < 4; ++i) {
            if (i == j || i == ip) continue;
            const auto v = c->vertex(i);
            if (dt.is_infinite(v)) finiteFacet = false;
            else qr[m++] = v->info();
          }
          if (!finiteFacet) continue;
          bool crossed;
          const bool cInf = dv.isInfinite(cid), dInf = dv.isInfinite(did);
          if (!cInf && !dInf) {
            crossed = crosses(sideOf(dv.circumcenter(cid), site, normal), sideOf(dv.circumcenter(did), site, normal));
          } else {
            // A hull triangle: its Voronoi edge is a ray from the finite
            // cell's circumcentre along the hull's outward normal.
            const Index finite = cInf ? did : cid, infinite = cInf ? cid : did;
            const Vec3 ray = hullFacetOutwardNormal(dv, infinite);
            const double s = sideOf(dv.circumcenter(finite), site, normal);
            const double slope = ray[0] * normal[0] + ray[1] * normal[1] + ray[2] * normal[2];
            crossed = (s <= 0 && slope > 0) || (s > 0 && slope < 0);
          }
          if (crossed) umbrella.push_back({static_cast<Index>(p), qr[0], qr[1]});
        }
      }
    }
  });
  for (std::size_t p = 0; p < n; ++p) {
    out.offsets[p + 1] = out.offsets[p] + static_cast<Index>(perSample[p].size());
    if (perSample[p].empty() && poles.cellOffsets[p + 1] > poles.cellOffsets[p]) ++out.emptyUmbrellas;
  }
  out.triangles.reserve(out.offsets[n]);
  for (auto& u : perSample) out.triangles.insert(out.triangles.end(), u.begin(), u.end());
  out.seconds = watch.seconds();
  return out;
}

UmbrellaData umbrellaDataOf(const std::vector<Vec3>& points, const TangentPolygonUmbrellas& umbrellas) {
  std::vector<Index> members(umbrellas.triangles.size());
  std::iota(members.begin(), members.end(), Index{0});
  return umbrellaDataFromTriangles(points, umbrellas.triangles, umbrellas.offsets, members);
}

}  // namespace cadmedial
