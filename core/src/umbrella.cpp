#include "cadmedial/umbrella.hpp"

#include <tbb/parallel_for.h>

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

UmbrellaData computeUmbrellaData(const SampleSet& samples) {
  if (samples.umbrellaOffsets.size() == samples.size() + 1)
    return umbrellaDataFromTriangles(samples.points, samples.triangles, samples.umbrellaOffsets,
                                     samples.umbrellaTriangles);
  SampleSet rebuilt;
  rebuilt.points = samples.points;
  rebuilt.triangles = samples.triangles;
  rebuilt.buildUmbrellas();
  return umbrellaDataFromTriangles(samples.points, samples.triangles, rebuilt.umbrellaOffsets,
                                   rebuilt.umbrellaTriangles);
}

UmbrellaData umbrellaDataFromTriangles(const std::vector<Vec3>& points, const std::vector<std::array<Index, 3>>& triangles,
                                       const std::vector<Index>& offsets, const std::vector<Index>& members) {
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
  return u;
}

}  // namespace cadmedial
