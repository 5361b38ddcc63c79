// DESIGN.md §6 pair-mesh validity, computed from the elements and the
// boundary triangles independently of how they were built.
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "cadmedial/edge_table.hpp"
#include "cadmedial/pair_mesh.hpp"

namespace cadmedial {

namespace {

struct TriangleKey {
  std::array<Index, 3> v;
  explicit TriangleKey(std::array<Index, 3> t) : v(t) { std::sort(v.begin(), v.end()); }
  bool operator==(const TriangleKey& o) const { return v == o.v; }
};
struct TriangleKeyHash {
  std::size_t operator()(const TriangleKey& k) const {
    std::uint64_t h = 1469598103934665603ull;
    for (Index i : k.v) h = (h ^ i) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

}  // namespace

// Volume enclosed by closed, outward triangles: Σ det(x - o, y - o, z - o) / 6
// about a point o near the surface (less cancellation than about the origin).
double boundaryEnclosedVolume(const PairMesh& m) {
  if (m.boundaryTriangles.empty()) return 0;
  const Vec3 o = m.nodes[m.boundaryTriangles[0][0]];
  double sum = 0;
  for (const auto& t : m.boundaryTriangles) {
    const Vec3 &x = m.nodes[t[0]], &y = m.nodes[t[1]], &z = m.nodes[t[2]];
    const double a[3] = {x[0] - o[0], x[1] - o[1], x[2] - o[2]};
    const double b[3] = {y[0] - o[0], y[1] - o[1], y[2] - o[2]};
    const double c[3] = {z[0] - o[0], z[1] - o[1], z[2] - o[2]};
    sum += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return sum / 6.0;
}

PairMeshValidity checkPairMesh(const PairMesh& m) {
  PairMeshValidity v;
  v.elements = m.size();
  // Plain double sums: over 10^6 terms the rounding stays near 1e-13
  // relative, far below the 1e-9 the volume identity is held to.
  for (std::size_t i = 0; i < m.size(); ++i) {
    const double vol = tetVolume(m, i);
    if (isInverted(m, i)) ++v.inverted;
    else if (std::abs(vol) <= negligibleVolume(m, i)) ++v.degenerate;
    v.sumVolume += vol;
    v.sumAbsVolume += std::abs(vol);
  }
  v.enclosedVolume = boundaryEnclosedVolume(m);
  v.boundaryTriangles = m.boundaryTriangles.size();
  if (v.enclosedVolume > 0) {
    v.overlapError = (v.sumAbsVolume - std::abs(v.sumVolume)) / v.enclosedVolume;
    v.gapError = std::abs(v.sumVolume - v.enclosedVolume) / v.enclosedVolume;
  }

  // Each boundary triangle in exactly one Vertex-Face element, and no
  // Vertex-Face element on anything but a boundary triangle.
  std::unordered_map<TriangleKey, int, TriangleKeyHash> uses;
  uses.reserve(2 * m.boundaryTriangles.size() + 1);
  for (const auto& t : m.boundaryTriangles) uses.emplace(TriangleKey(t), 0);
  std::size_t strays = 0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (m.type[i] != PairElementType::VertexFace) continue;
    const auto& t = m.tets[i];
    auto it = uses.find(TriangleKey({t[1], t[2], t[3]}));
    if (it == uses.end()) ++strays;
    else ++it->second;
  }
  for (const auto& [key, count] : uses) v.boundaryTrianglesNotInOneVertexFace += count == 1 ? 0 : 1;
  v.boundaryTrianglesNotInOneVertexFace += strays;

  // Closed: every edge in an even number of boundary triangles, with as
  // many uses a -> b as b -> a (consistent orientation).
  PairTable edgeIds;
  edgeIds.reserve(3 * m.boundaryTriangles.size() / 2 + 1);
  std::vector<int> balance;
  for (const auto& t : m.boundaryTriangles)
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3];
      const Index id = edgeIds.insert(a, b, static_cast<Index>(balance.size()));
      if (id == balance.size()) balance.push_back(0);
      balance[id] += a < b ? 1 : -1;
    }
  for (int b : balance) v.boundaryEdgesNotShared += b == 0 ? 0 : 1;
  return v;
}

}  // namespace cadmedial
