#include "cadmedial/umbrella.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace cadmedial {

namespace {

struct TriangleData {
  std::array<double, 3> normal{0, 0, 0};
  double circumradius = 0;
  bool valid = false;
};

TriangleData triangleData(const Vec3& a, const Vec3& b, const Vec3& c) {
  TriangleData t;
  const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double bc[3] = {c[0] - b[0], c[1] - b[1], c[2] - b[2]};
  const double n[3] = {ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0]};
  const double twiceArea = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const double lab = std::sqrt(ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2]);
  const double lac = std::sqrt(ac[0] * ac[0] + ac[1] * ac[1] + ac[2] * ac[2]);
  const double lbc = std::sqrt(bc[0] * bc[0] + bc[1] * bc[1] + bc[2] * bc[2]);
  const double longest = std::max(lab, std::max(lac, lbc));
  // Zero-area (or numerically so) triangles carry no normal and have an
  // infinite circumradius: skip them rather than let them veto both conditions.
  if (!(twiceArea > 1e-12 * longest * longest)) return t;
  t.valid = true;
  t.normal = {n[0] / twiceArea, n[1] / twiceArea, n[2] / twiceArea};
  t.circumradius = lab * lac * lbc / (2.0 * twiceArea);  // R = abc / (4·area)
  return t;
}

}  // namespace

std::vector<std::uint8_t> concaveEdgeSamples(const SampleSet& samples) {
  std::vector<std::uint8_t> flags(samples.size(), 0);
  if (samples.kind.size() != samples.size() || samples.owner.size() != samples.size()) return flags;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (samples.kind[i] != SampleKind::Edge) continue;
    const std::int32_t e = samples.owner[i];
    if (e >= 0 && static_cast<std::size_t>(e) < samples.edges.size() && samples.edges[e].kind == EdgeKind::Concave)
      flags[i] = 1;
  }
  return flags;
}

UmbrellaData computeUmbrellaData(const SampleSet& samples) {
  const std::vector<std::uint8_t> oneSided = concaveEdgeSamples(samples);
  const std::vector<std::uint8_t>* offSurface = &samples.triangleOffSurface;  // ignored unless one per triangle
  if (samples.umbrellaOffsets.size() == samples.size() + 1)
    return umbrellaDataFromTriangles(samples.points, samples.triangles, samples.umbrellaOffsets,
                                     samples.umbrellaTriangles, &oneSided, offSurface);
  SampleSet rebuilt;
  rebuilt.points = samples.points;
  rebuilt.triangles = samples.triangles;
  rebuilt.buildUmbrellas();
  return umbrellaDataFromTriangles(samples.points, samples.triangles, rebuilt.umbrellaOffsets,
                                   rebuilt.umbrellaTriangles, &oneSided, offSurface);
}

// Why one-sided umbrellas: at a sample inside a concave edge the umbrella
// holds triangles of both faces, and each face lies on one side of the edge
// only. The Angle condition asks whether pq is near tangent to the surface at
// p; a chord from p that leaves across the edge, away from a face, is not
// tangent to that face however flat it runs against its plane (a boss
// standing on a plane: the chords across the boss's foot lie in the plane yet
// inside the solid, and only they join the boss's axis to the rest). So a
// triangle of such a sample judges only the directions over its own corner
// wedge (widened, see satisfiesAngleOrRatio).
bool headsOverWedge(const std::array<std::array<double, 3>, 2>& wedge, const std::array<double, 3>& n,
                    const double dir[3], double slackCos) {
  const double dn = n[0] * dir[0] + n[1] * dir[1] + n[2] * dir[2];
  double u[3] = {dir[0] - dn * n[0], dir[1] - dn * n[1], dir[2] - dn * n[2]};
  const double len = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  if (!(len > 0)) return true;  // along the normal: no side to tell
  for (double& c : u) c /= len;
  const auto& a = wedge[0];
  const auto& b = wedge[1];
  auto tripleWithNormal = [&](const double* x, const double* y) {  // (x × y) · n
    return (x[1] * y[2] - x[2] * y[1]) * n[0] + (x[2] * y[0] - x[0] * y[2]) * n[1] + (x[0] * y[1] - x[1] * y[0]) * n[2];
  };
  const double sense = tripleWithNormal(a.data(), b.data());  // the wedge's turning sense (< 180°)
  if (tripleWithNormal(a.data(), u) * sense >= 0 && tripleWithNormal(u, b.data()) * sense >= 0) return true;
  const double toA = a[0] * u[0] + a[1] * u[1] + a[2] * u[2];
  const double toB = b[0] * u[0] + b[1] * u[1] + b[2] * u[2];
  return std::max(toA, toB) >= slackCos;
}

UmbrellaData umbrellaDataFromTriangles(const std::vector<Vec3>& points, const std::vector<std::array<Index, 3>>& triangles,
                                       const std::vector<Index>& offsets, const std::vector<Index>& members,
                                       const std::vector<std::uint8_t>* oneSided,
                                       const std::vector<std::uint8_t>* offSurface) {
  const std::size_t n = offsets.empty() ? 0 : offsets.size() - 1;
  const std::size_t tcount = triangles.size();
  std::vector<TriangleData> tri(tcount);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tcount, 8192), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t t = r.begin(); t != r.end(); ++t) {
      const auto& v = triangles[t];
      tri[t] = triangleData(points[v[0]], points[v[1]], points[v[2]]);
    }
  });

  UmbrellaData u;
  for (const auto& t : tri) u.degenerateTriangles += t.valid ? 0 : 1;
  if (offSurface && offSurface->size() == tcount)
    for (std::size_t t = 0; t < tcount; ++t)
      if ((*offSurface)[t]) tri[t].valid = false;
  u.offsets.assign(n + 1, 0);
  u.maxCircumradius.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    Index count = 0;
    double maxR = 0;
    for (Index k = offsets[i]; k < offsets[i + 1]; ++k) {
      const TriangleData& t = tri[members[k]];
      if (!t.valid) continue;
      ++count;
      maxR = std::max(maxR, t.circumradius);
    }
    u.offsets[i + 1] = u.offsets[i] + count;
    u.maxCircumradius[i] = maxR;
    if (count == 0) ++u.samplesWithoutUmbrella;
  }
  u.normals.resize(u.offsets[n]);
  for (std::size_t i = 0; i < n; ++i) {
    Index out = u.offsets[i];
    for (Index k = offsets[i]; k < offsets[i + 1]; ++k) {
      const TriangleData& t = tri[members[k]];
      if (t.valid) u.normals[out++] = t.normal;
    }
  }
  if (oneSided && oneSided->size() == n && std::find(oneSided->begin(), oneSided->end(), 1) != oneSided->end()) {
    u.sideStart.assign(n, kNoIndex);
    for (std::size_t i = 0; i < n; ++i) {
      if (!(*oneSided)[i]) continue;
      u.sideStart[i] = static_cast<Index>(u.wedges.size());
      const Vec3& p = points[i];
      for (Index k = offsets[i]; k < offsets[i + 1]; ++k) {
        if (!tri[members[k]].valid) continue;
        std::array<std::array<double, 3>, 2> wedge{};
        int r = 0;
        for (Index v : triangles[members[k]]) {
          if (v == i || r == 2) continue;
          const double d[3] = {points[v][0] - p[0], points[v][1] - p[1], points[v][2] - p[2]};
          const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
          wedge[r++] = {d[0] / l, d[1] / l, d[2] / l};
        }
        u.wedges.push_back(wedge);
      }
    }
  }
  return u;
}

}  // namespace cadmedial
