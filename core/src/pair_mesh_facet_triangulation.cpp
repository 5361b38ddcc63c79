#include "pair_mesh_facet_triangulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

#include "pair_mesh_element_checks.hpp"

namespace cadmedial {

namespace {

std::uint64_t facetKey(const std::array<Index, 2>& e) { return (static_cast<std::uint64_t>(e[0]) << 32) | e[1]; }

// Lexicographic: fewer elements needing repair, then a larger smallest
// relative volume. Adding sub-polygons keeps the order (sum, min).
struct Score {
  std::size_t bad = 0;
  double worst = std::numeric_limits<double>::infinity();
  Score operator+(const Score& o) const { return {bad + o.bad, std::min(worst, o.worst)}; }
  bool betterThan(const Score& o) const { return bad != o.bad ? bad < o.bad : worst > o.worst; }
};

// The two elements (a, p, q, r) and (b, p, r, q) on polygon triangle (p, q, r).
Score triangleScore(const std::vector<Vec3>& nodes, Index a, Index b, Index p, Index q, Index r) {
  Score s;
  for (const std::array<Index, 4>& t : {std::array<Index, 4>{a, p, q, r}, std::array<Index, 4>{b, p, r, q}}) {
    if (elementNeedsRepair(nodes, t)) {
      ++s.bad;
      continue;
    }
    bool coincident = false;
    double longest = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const Vec3 &u = nodes[t[i]], &v = nodes[t[j]];
        coincident = coincident || u == v;
        longest = std::max(longest, (u[0] - v[0]) * (u[0] - v[0]) + (u[1] - v[1]) * (u[1] - v[1]) +
                                        (u[2] - v[2]) * (u[2] - v[2]));
      }
    if (coincident) continue;  // flat by welding: cuts to nothing, no quality to compare
    const double volume = signedTetVolume(nodes[t[0]], nodes[t[1]], nodes[t[2]], nodes[t[3]]);
    s.worst = std::min(s.worst, volume / (longest * std::sqrt(longest)));
  }
  return s;
}

// The polygon (in its orientation as seen from apex a) from the triangles
// (p, q, r) of the elements (a, p, q, r): the directed edges with no reverse
// form one cycle. Empty when they do not.
std::vector<Index> polygonOf(const std::vector<std::array<Index, 3>>& triangles) {
  std::unordered_map<Index, Index> next;
  std::unordered_set<std::uint64_t> directed;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) directed.insert((static_cast<std::uint64_t>(t[k]) << 32) | t[(k + 1) % 3]);
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const Index u = t[k], v = t[(k + 1) % 3];
      if (directed.count((static_cast<std::uint64_t>(v) << 32) | u)) continue;
      if (!next.emplace(u, v).second) return {};
    }
  if (next.size() != triangles.size() + 2) return {};
  std::vector<Index> polygon{next.begin()->first};
  while (polygon.size() <= next.size()) {
    const auto it = next.find(polygon.back());
    if (it == next.end()) return {};
    if (it->second == polygon.front()) break;
    polygon.push_back(it->second);
  }
  return polygon.size() == next.size() ? polygon : std::vector<Index>{};
}

// Best triangulation of the polygon by dynamic programming over its
// sub-polygons i..j; returns the triangles (polygon order) and their score.
std::pair<std::vector<std::array<Index, 3>>, Score> bestTriangulation(const std::vector<Vec3>& nodes, Index a, Index b,
                                                                       const std::vector<Index>& poly) {
  const std::size_t k = poly.size();
  std::vector<Score> best(k * k);
  std::vector<std::size_t> split(k * k, 0);
  for (std::size_t length = 2; length < k; ++length)
    for (std::size_t i = 0; i + length < k; ++i) {
      const std::size_t j = i + length;
      bool first = true;
      for (std::size_t l = i + 1; l < j; ++l) {
        const Score s = best[i * k + l] + best[l * k + j] + triangleScore(nodes, a, b, poly[i], poly[l], poly[j]);
        if (first || s.betterThan(best[i * k + j])) {
          best[i * k + j] = s;
          split[i * k + j] = l;
          first = false;
        }
      }
    }
  std::vector<std::array<Index, 3>> triangles;
  std::vector<std::pair<std::size_t, std::size_t>> stack{{0, k - 1}};
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    if (j - i < 2) continue;
    const std::size_t l = split[i * k + j];
    triangles.push_back({poly[i], poly[l], poly[j]});
    stack.push_back({i, l});
    stack.push_back({l, j});
  }
  return {triangles, best[k - 1]};
}

}  // namespace

std::size_t retriangulateFaceVertexPolygons(PairMesh& m, std::vector<std::uint8_t>* needsRepair,
                                            std::vector<std::size_t>* flagged, PolygonSlots* known,
                                            std::vector<std::uint64_t>* changedKeys) {
  // Only the polygons holding a bad element.
  std::vector<std::uint64_t> keys;
  auto consider = [&](std::size_t i) {
    if (m.type[i] == PairElementType::FaceVertex &&
        (needsRepair ? (*needsRepair)[i] != 0 : elementNeedsRepair(m.nodes, m.tets[i])))
      keys.push_back(facetKey(m.medialSimplex[i]));
  };
  if (needsRepair && flagged) {
    for (std::size_t i : *flagged) consider(i);
  } else {
    for (std::size_t i = 0; i < m.tets.size(); ++i) consider(i);
  }
  if (keys.empty()) return 0;
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  // Each with its element slots: those of polygons not met before from one
  // pass over the elements.
  PolygonSlots local;
  PolygonSlots& slots = needsRepair && known ? *known : local;
  PolygonSlots fresh;
  for (std::uint64_t key : keys)
    if (!slots.count(key)) fresh[key];
  if (!fresh.empty()) {
    // In parallel, and past the table only for elements whose edge starts
    // at a sample of a fresh polygon's edge: this pass runs once per repair
    // round that meets new polygons, over every element.
    std::vector<std::uint8_t> startsFresh(m.nodes.size(), 0);
    for (const auto& entry : fresh) startsFresh[static_cast<Index>(entry.first >> 32)] = 1;
    const std::vector<std::size_t> found = selectElements(m.tets.size(), [&](std::size_t i) {
      return m.type[i] == PairElementType::FaceVertex && startsFresh[m.medialSimplex[i][0]] &&
             fresh.count(facetKey(m.medialSimplex[i])) != 0;
    });
    for (std::size_t i : found) fresh.at(facetKey(m.medialSimplex[i])).push_back(i);
    for (auto& [key, elements] : fresh) slots.emplace(key, std::move(elements));
  }

  // One polygon's choice does not depend on another's (their elements are
  // apart, their nodes do not move here): any order gives the same mesh.
  std::size_t changed = 0;
  for (std::uint64_t key : keys) {
    const std::vector<std::size_t>& elements = slots.at(key);
    const Index a = m.tets[elements[0]][0];
    Index b = kNoIndex;
    std::vector<std::array<Index, 3>> current;
    std::size_t badBefore = 0;
    for (std::size_t i : elements) {
      const auto& t = m.tets[i];
      if (t[0] == a) current.push_back({t[1], t[2], t[3]});
      else b = t[0];
      badBefore += elementNeedsRepair(m.nodes, t) ? 1 : 0;
    }
    if (b == kNoIndex || 2 * current.size() != elements.size()) continue;
    const std::vector<Index> polygon = polygonOf(current);
    if (polygon.size() < 4) continue;  // a triangle has one triangulation
    const auto [triangles, score] = bestTriangulation(m.nodes, a, b, polygon);
    if (score.bad >= badBefore) continue;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      const auto& [p, q, r] = triangles[t];
      m.tets[elements[2 * t]] = {a, p, q, r};
      m.tets[elements[2 * t + 1]] = {b, p, r, q};
      m.boundarySimplex[elements[2 * t]] = {a, kNoIndex, kNoIndex};
      m.boundarySimplex[elements[2 * t + 1]] = {b, kNoIndex, kNoIndex};
    }
    if (needsRepair)
      for (std::size_t i : elements) {
        (*needsRepair)[i] = elementNeedsRepair(m.nodes, m.tets[i]) ? 1 : 0;
        if (flagged && (*needsRepair)[i]) flagged->push_back(i);
      }
    if (changedKeys && needsRepair && known) changedKeys->push_back(key);
    ++changed;
  }
  return changed;
}

}  // namespace cadmedial
