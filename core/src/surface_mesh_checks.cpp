#include "cadmedial/surface_mesh_checks.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace cadmedial {

namespace {

struct UnionFind {
  std::vector<Index> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  Index find(Index a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void unite(Index a, Index b) { parent[find(a)] = find(b); }
};

std::uint64_t edgeKey(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

}  // namespace

SurfaceMeshStats checkSurfaceMesh(const std::vector<Vec3>& points, const std::vector<std::array<Index, 3>>& triangles) {
  SurfaceMeshStats stats;
  stats.triangles = triangles.size();
  // Per undirected edge: number of uses, and the signed count of a->b (a<b) uses.
  struct EdgeUse {
    int uses = 0;
    int forward = 0;
  };
  std::unordered_map<std::uint64_t, EdgeUse> edges;
  edges.reserve(triangles.size() * 2);
  std::vector<std::uint8_t> used(points.size(), 0);
  UnionFind components(points.size());
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3];
      EdgeUse& e = edges[edgeKey(a, b)];
      ++e.uses;
      e.forward += a < b ? 1 : -1;
      used[a] = 1;
      components.unite(a, b);
    }
    const Vec3 &p = points[t[0]], &q = points[t[1]], &r = points[t[2]];
    const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    const double v[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    stats.area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    // Signed volume of the tetrahedron (origin, p, q, r).
    stats.enclosedVolume += (p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0]) +
                             p[2] * (q[0] * r[1] - q[1] * r[0])) /
                            6.0;
  }
  stats.edges = edges.size();
  for (const auto& [key, e] : edges) {
    if (e.uses == 1) ++stats.boundaryEdges;
    if (e.uses > 2) ++stats.nonManifoldEdges;
    if (e.uses == 2 && e.forward != 0) ++stats.misorientedEdges;
  }
  for (Index i = 0; i < points.size(); ++i)
    if (used[i]) {
      ++stats.vertices;
      if (components.find(i) == i) ++stats.components;
    }
  stats.eulerCharacteristic = static_cast<long>(stats.vertices) - static_cast<long>(stats.edges) +
                              static_cast<long>(stats.triangles);

  // A vertex is manifold iff its link (the opposite edges of its triangles)
  // forms a single cycle: one connected component with every link vertex of degree 2.
  std::vector<std::vector<std::array<Index, 2>>> link(points.size());
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) link[t[k]].push_back({t[(k + 1) % 3], t[(k + 2) % 3]});
  for (Index i = 0; i < points.size(); ++i) {
    const auto& l = link[i];
    if (l.empty()) continue;
    std::unordered_map<Index, int> degree;
    std::unordered_map<Index, Index> parent;
    auto find = [&](Index a) {
      while (parent[a] != a) a = parent[a] = parent[parent[a]];
      return a;
    };
    for (const auto& e : l)
      for (Index v : e) {
        ++degree[v];
        parent.emplace(v, v);
      }
    for (const auto& e : l) parent[find(e[0])] = find(e[1]);
    std::size_t roots = 0;
    bool allTwo = true;
    for (const auto& [v, d] : degree) {
      allTwo = allTwo && d == 2;
      if (find(v) == v) ++roots;
    }
    if (!allTwo || roots != 1) ++stats.nonManifoldVertices;
  }
  return stats;
}

}  // namespace cadmedial
