#include "cadmedial/medial_poles.hpp"

#include <tbb/parallel_for.h>

#include <cmath>

#include "cadmedial/timer.hpp"
#include "cadmedial/vec3_ops.hpp"

namespace cadmedial {

namespace {

using vec3::cross;
using vec3::dot;
using vec3::sub;
Vec3 toVec(const DelaunayVoronoi::Point& p) { return {p.x(), p.y(), p.z()}; }

Vec3 normalized(const Vec3& v) {
  const double len = std::sqrt(dot(v, v));
  if (!(len > 0) || !std::isfinite(len)) return {0, 0, 0};
  return {v[0] / len, v[1] / len, v[2] / len};
}

}  // namespace

Vec3 hullFacetOutwardNormal(const DelaunayVoronoi& dv, Index infiniteCell) {
  const auto& dt = dv.triangulation();
  const auto c = dv.cell(infiniteCell);
  const int inf = c->index(dt.infinite_vertex());
  const Vec3 a = toVec(c->vertex((inf + 1) & 3)->point());
  const Vec3 b = toVec(c->vertex((inf + 2) & 3)->point());
  const Vec3 d = toVec(c->vertex((inf + 3) & 3)->point());
  Vec3 n = normalized(cross(sub(b, a), sub(d, a)));
  // Away from the finite cell on the other side of the hull triangle.
  const auto finite = c->neighbor(inf);
  const Vec3 mirror = toVec(finite->vertex(finite->index(c))->point());
  if (dot(n, sub(mirror, a)) > 0) n = {-n[0], -n[1], -n[2]};
  return n;
}

PoleData computePoles(const DelaunayVoronoi& dv) {
  Stopwatch watch;
  const std::size_t n = dv.sampleCount();
  PoleData out;
  out.direction.assign(n, Vec3{0, 0, 0});
  out.poleCell.assign(n, kNoIndex);
  out.cellOffsets.assign(n + 1, 0);
  if (dv.dimension() < 3) {
    out.seconds = watch.seconds();
    return out;
  }

  // Cells around each canonical sample, from one pass over all cells (the
  // TDS's own incident_cells marks cells and is not safe to run in parallel).
  const std::size_t m = dv.cellCount();
  for (Index id = 0; id < m; ++id)
    for (int i = 0; i < 4; ++i)
      if (const Index s = dv.cellSample(id, i); s != kNoIndex) ++out.cellOffsets[s + 1];
  for (std::size_t i = 0; i < n; ++i) out.cellOffsets[i + 1] += out.cellOffsets[i];
  out.cells.resize(out.cellOffsets[n]);
  {
    std::vector<Index> fill(out.cellOffsets.begin(), out.cellOffsets.end() - 1);
    for (Index id = 0; id < m; ++id)
      for (int i = 0; i < 4; ++i)
        if (const Index s = dv.cellSample(id, i); s != kNoIndex) out.cells[fill[s]++] = id;
  }

  std::vector<std::uint8_t> unbounded(n, 0), zero(n, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t p = r.begin(); p != r.end(); ++p) {
      const Index b = out.cellOffsets[p], e = out.cellOffsets[p + 1];
      if (b == e) continue;  // a duplicate: its canonical sample carries the data
      const Vec3 site = toVec(dv.vertex(static_cast<Index>(p))->point());
      Vec3 rays{0, 0, 0};
      double farthest = -1;
      Index pole = kNoIndex;
      bool isUnbounded = false;
      for (Index k = b; k < e; ++k) {
        const Index c = out.cells[k];
        if (dv.isInfinite(c)) {
          isUnbounded = true;
          const Vec3 nrm = hullFacetOutwardNormal(dv, c);
          for (int j = 0; j < 3; ++j) rays[j] += nrm[j];
          continue;
        }
        const Vec3 d = sub(dv.circumcenter(c), site);
        const double dist2 = dot(d, d);
        if (dist2 > farthest) {
          farthest = dist2;
          pole = c;
        }
      }
      Vec3 dir{0, 0, 0};
      if (isUnbounded) {
        unbounded[p] = 1;
        dir = normalized(rays);
      }
      // A hull sample whose rays cancel out (cannot happen on a strictly
      // convex hull vertex) falls back on the farthest finite Voronoi vertex.
      if (dir == Vec3{0, 0, 0} && pole != kNoIndex) dir = normalized(sub(dv.circumcenter(pole), site));
      out.direction[p] = dir;
      out.poleCell[p] = isUnbounded ? kNoIndex : pole;
      zero[p] = dir == Vec3{0, 0, 0} ? 1 : 0;
    }
  });
  for (std::size_t p = 0; p < n; ++p) {
    out.unboundedCells += unbounded[p];
    out.zeroDirections += zero[p];
  }
  out.seconds = watch.seconds();
  return out;
}

}  // namespace cadmedial
