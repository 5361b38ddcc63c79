// Seed 003 §4.1: flipped Vertex-Face and Edge-Edge elements come from Voronoi
// vertices that lie outside the boundary surface (near it, where the solid's
// surface bulges past the Delaunay triangles). Moving such a vertex toward
// the inside of its own Delaunay cell turns its Vertex-Face elements positive
// (the centroid of the cell is on the inner side of each of its facets), and
// the step is kept as small as the neighbouring elements allow.
#include <algorithm>
#include <cmath>

#include "cadmedial/pair_mesh.hpp"

namespace cadmedial {

namespace {

double orient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
  return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0])) /
         6.0;
}

double squaredLength(const Vec3& a, const Vec3& b) {
  const double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
  return x * x + y * y + z * z;
}

}  // namespace

double tetVolume(const PairMesh& m, std::size_t i) {
  const auto& t = m.tets[i];
  return orient(m.nodes[t[0]], m.nodes[t[1]], m.nodes[t[2]], m.nodes[t[3]]);
}

double negligibleVolume(const PairMesh& m, std::size_t i) {
  const auto& t = m.tets[i];
  double longest = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) longest = std::max(longest, squaredLength(m.nodes[t[a]], m.nodes[t[b]]));
  return 1e-12 * longest * std::sqrt(longest);
}

std::size_t repairFlippedElements(PairMesh& m, const DelaunayVoronoi& dv, int rounds) {
  const std::size_t n = m.nodes.size();
  auto negative = [&m](std::size_t i) { return tetVolume(m, i) < -negligibleVolume(m, i); };
  // Node -> incident tetrahedra (CSR).
  std::vector<Index> offsets(n + 1, 0), incident;
  for (const auto& t : m.tets)
    for (Index v : t) ++offsets[v + 1];
  for (std::size_t v = 0; v < n; ++v) offsets[v + 1] += offsets[v];
  incident.resize(offsets[n]);
  {
    std::vector<Index> fill(offsets.begin(), offsets.end() - 1);
    for (std::size_t i = 0; i < m.tets.size(); ++i)
      for (Index v : m.tets[i]) incident[fill[v]++] = static_cast<Index>(i);
  }
  auto negativeAround = [&](Index v, double* deficit) {
    std::size_t count = 0;
    for (Index k = offsets[v]; k < offsets[v + 1]; ++k) {
      const double vol = tetVolume(m, incident[k]), eps = negligibleVolume(m, incident[k]);
      if (vol < -eps) {
        ++count;
        if (deficit) *deficit -= vol;
      }
    }
    return count;
  };

  std::size_t bad = 0;
  for (std::size_t i = 0; i < m.tets.size(); ++i) bad += negative(i) ? 1 : 0;
  m.counts.invertedBeforeRepair = bad;
  std::vector<std::uint8_t> moved(n, 0);
  static constexpr double kSteps[] = {0.03125, 0.0625, 0.125, 0.25, 0.5, 0.75, 1.0};
  for (int round = 0; round < rounds && bad > 0; ++round) {
    std::vector<Index> candidates;
    for (std::size_t i = 0; i < m.tets.size(); ++i)
      if (negative(i))
        for (Index v : m.tets[i])
          if (!m.isSampleNode(v)) candidates.push_back(v);
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    for (Index v : candidates) {
      double deficit0 = 0;
      const std::size_t before = negativeAround(v, &deficit0);
      if (before == 0) continue;
      const Index cell = m.nodeCell[v];
      Vec3 centroid{0, 0, 0};
      for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 3; ++k) centroid[k] += 0.25 * m.nodes[dv.cellSample(cell, i)][k];
      const Vec3 start = m.nodes[v];
      // Candidates: steps toward the centroid, then the positions of the
      // Voronoi nodes it shares elements with. The latter fix nearly flat
      // cells (four cocircular samples, e.g. triplet legs around a convex
      // edge): their circumcenter is any point of the circle's axis, and the
      // one picked can fall outside the span of the neighbours' vertices on
      // that axis, folding the Voronoi polygons; a neighbour's position
      // unfolds them (the elements between the two become flat).
      std::vector<Vec3> targets;
      for (double s : kSteps)
        targets.push_back({(1 - s) * start[0] + s * centroid[0], (1 - s) * start[1] + s * centroid[1],
                           (1 - s) * start[2] + s * centroid[2]});
      for (Index k = offsets[v]; k < offsets[v + 1]; ++k)
        for (Index u : m.tets[incident[k]])
          if (u != v && !m.isSampleNode(u)) targets.push_back(m.nodes[u]);
      Vec3 best = start;
      std::size_t bestCount = before;
      double bestDeficit = deficit0;
      for (const Vec3& target : targets) {
        m.nodes[v] = target;
        double deficit = 0;
        const std::size_t count = negativeAround(v, &deficit);
        if (count < bestCount || (count == bestCount && deficit < bestDeficit)) {
          best = target;
          bestCount = count;
          bestDeficit = deficit;
        }
        if (count == 0) break;
      }
      m.nodes[v] = best;
      if (best != start) moved[v] = 1;
    }
    bad = 0;
    for (std::size_t i = 0; i < m.tets.size(); ++i) bad += negative(i) ? 1 : 0;
  }
  m.counts.movedNodes = static_cast<std::size_t>(std::count(moved.begin(), moved.end(), 1));
  m.counts.invertedAfterRepair = bad;
  return bad;
}

}  // namespace cadmedial
