// Seed 003 §4.1, second case of flipped elements: a boundary Delaunay edge ab
// that does not cross its Voronoi cut face. Every node of the cut face's
// chain (the inner Voronoi nodes around ab) lies near the bisector plane of
// ab, and the Edge-Edge element (a, b, vi, vj) is positive when the edge's
// crossing point with that plane sees the chain segment vi vj turn the right
// way. When it does not, the edge is bent at a new boundary node m chosen
// inside the cut face: (a, b, vi, vj) becomes (a, m, vi, vj) + (m, b, vi, vj),
// which are positive when m sees vi vj correctly, and the two boundary
// triangles on ab become polygons a m b ..., re-triangulated into Vertex-Face
// elements on the same Voronoi node. Faces stay shared pairwise, so the
// signed volumes still add up to the volume inside the (slightly bent)
// boundary. The bent boundary must not fold through its neighbours: where
// the solid is thinner than the bend (a knife edge between tangent faces,
// 0.005 mm thick on bm2_ec_lever-A where the split was needed), m would end
// up beyond the other side, the boundary would enclose a sliver twice, and
// the iso-surfaces would cross there although every element is positive. So
// no triangle of the new triangulations may cross a boundary triangle near
// the edge (trianglesCross); a split with none that fits is not made.

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "cadmedial/edge_table.hpp"
#include "cadmedial/pair_mesh.hpp"
#include "pair_mesh_edit.hpp"
#include "pair_mesh_element_checks.hpp"
#include "point_box.hpp"
#include "triangle_crossing.hpp"

namespace cadmedial {

namespace {

// A boundary triangle (outward corners) with the Voronoi node of its
// Vertex-Face elements, the split node on each of its edges (corner k to
// k + 1) and the elements that currently fill it.
struct BoundaryPolygon {
  std::array<Index, 3> corners;
  Index apex;
  std::array<Index, 3> splits{kNoIndex, kNoIndex, kNoIndex};
  std::vector<std::size_t> elements;
  std::vector<std::array<Index, 3>> triangles;  // current triangulation
};

// Every triangulation of the convex polygon 0..n-1 (n <= 6: at most 14),
// as triangles of polygon positions in the polygon's orientation.
using Triangulation = std::vector<std::array<int, 3>>;
std::vector<Triangulation> triangulations(int i, int j) {
  if (j - i < 2) return {Triangulation{}};
  std::vector<Triangulation> all;
  for (int k = i + 1; k < j; ++k)
    for (const Triangulation& left : triangulations(i, k))
      for (const Triangulation& right : triangulations(k, j)) {
        Triangulation t = left;
        t.insert(t.end(), right.begin(), right.end());
        t.push_back({i, k, j});
        all.push_back(std::move(t));
      }
  return all;
}

const std::vector<Triangulation>& triangulationsOf(int n) {
  static const std::vector<std::vector<Triangulation>> table = [] {
    std::vector<std::vector<Triangulation>> t(7);
    for (int k = 3; k <= 6; ++k) t[k] = triangulations(0, k - 1);
    return t;
  }();
  return table[n];
}


// Negative elements and how negative, for comparing candidate repairs.
struct Score {
  std::size_t negative = 0;
  double deficit = 0;
  bool operator<(const Score& o) const {
    return negative != o.negative ? negative < o.negative : deficit < o.deficit;
  }
};

// Bad as in the rest of the repair: inverted, or flat with four distinct
// corners (a split point on a Voronoi node would make such elements).
void addToScore(Score& s, const std::vector<Vec3>& nodes, const std::array<Index, 4>& t) {
  if (elementNeedsRepair(nodes, t)) {
    ++s.negative;
    s.deficit -= signedTetVolume(nodes[t[0]], nodes[t[1]], nodes[t[2]], nodes[t[3]]);
  }
}

class EdgeSplitter {
 public:
  EdgeSplitter(PairMesh& m, const std::vector<std::size_t>* candidates, std::vector<std::uint8_t>* flags)
      : m_(m), candidates_(candidates), flags_(flags) {}

  std::size_t run() {
    collectEdges();
    if (edges_.empty()) return 0;
    collectPolygons();
    collectNearbyTriangles();
    std::size_t split = 0;
    for (const auto& [key, ee] : edges_) split += trySplit(key, ee) ? 1 : 0;
    if (split > 0) rebuild();
    return split;
  }

 private:
  // Boundary edges {a, b} (a < b) with a negative Edge-Edge element, and all
  // the Edge-Edge elements of those edges. The negative ones are looked for
  // among the candidates when given (the repair's flagged elements), else
  // in parallel over all; the passes after it look up an element's edges only when its
  // nodes are ends of such an edge (a few dozen of 100 k samples), since
  // these passes over every element ran on every repair and trial.
  void collectEdges() {
    auto negativeEdgeEdge = [&](std::size_t i) {
      return m_.type[i] == PairElementType::EdgeEdge && isInverted(m_, i);
    };
    std::vector<std::size_t> negative;
    if (candidates_) {
      std::copy_if(candidates_->begin(), candidates_->end(), std::back_inserter(negative), negativeEdgeEdge);
    } else {
      negative = selectElements(m_.size(), negativeEdgeEdge);
    }
    if (negative.empty()) return;
    edgeEnd_.assign(m_.nodes.size(), 0);
    for (std::size_t i : negative) {
      edges_[key(m_.tets[i][0], m_.tets[i][1])];
      edgeEnd_[m_.tets[i][0]] = edgeEnd_[m_.tets[i][1]] = 1;
    }
    for (std::size_t i = 0; i < m_.size(); ++i)
      if (m_.type[i] == PairElementType::EdgeEdge && edgeEnd_[m_.tets[i][0]] && edgeEnd_[m_.tets[i][1]]) {
        auto it = edges_.find(key(m_.tets[i][0], m_.tets[i][1]));
        if (it != edges_.end()) it->second.push_back(i);
      }
  }

  // The boundary triangles on those edges, with their Vertex-Face element.
  void collectPolygons() {
    for (std::size_t i = 0; i < m_.size(); ++i) {
      if (m_.type[i] != PairElementType::VertexFace) continue;
      const auto& t = m_.tets[i];
      if (edgeEnd_[t[1]] + edgeEnd_[t[2]] + edgeEnd_[t[3]] < 2) continue;
      bool touches = false;
      for (int k = 0; k < 3; ++k) touches |= edges_.count(key(t[1 + k], t[1 + (k + 1) % 3])) > 0;
      if (!touches) continue;
      BoundaryPolygon p;
      p.corners = {t[1], t[2], t[3]};
      p.apex = t[0];
      p.elements = {i};
      p.triangles = {p.corners};
      for (int k = 0; k < 3; ++k) {
        auto& list = polygonsOfEdge_[key(p.corners[k], p.corners[(k + 1) % 3])];
        list.push_back(polygons_.size());
      }
      polygons_.push_back(std::move(p));
    }
  }

  // The other boundary triangles a bent edge could fold through: those whose
  // boxes meet an edge's polygons' box grown by the edge's length (a split
  // node stays within the edge's length of its midpoint).
  void collectNearbyTriangles() {
    std::vector<PointBox> regions;
    for (const auto& [edgeKey, ee] : edges_) {
      const auto it = polygonsOfEdge_.find(edgeKey);
      if (it == polygonsOfEdge_.end() || ee.empty()) continue;
      std::vector<Vec3> corners;
      for (std::size_t q : it->second)
        for (Index c : polygons_[q].corners) corners.push_back(m_.nodes[c]);
      const Vec3 &pa = m_.nodes[m_.tets[ee[0]][0]], &pb = m_.nodes[m_.tets[ee[0]][1]];
      const double length = std::sqrt((pa[0] - pb[0]) * (pa[0] - pb[0]) + (pa[1] - pb[1]) * (pa[1] - pb[1]) +
                                      (pa[2] - pb[2]) * (pa[2] - pb[2]));
      regions.push_back(grown(boxOf(corners.data(), corners.data() + corners.size()), 1.001 * length));
    }
    std::vector<std::uint8_t> inPolygon(m_.size(), 0);
    for (const BoundaryPolygon& p : polygons_)
      for (std::size_t e : p.elements) inPolygon[e] = 1;
    for (std::size_t i = 0; i < m_.size(); ++i) {
      if (m_.type[i] != PairElementType::VertexFace || inPolygon[i]) continue;
      const std::array<Index, 3> tri{m_.tets[i][1], m_.tets[i][2], m_.tets[i][3]};
      const PointBox b = triangleBox(tri);
      if (std::any_of(regions.begin(), regions.end(), [&](const PointBox& r) { return boxesMeet(r, b); }))
        nearby_.push_back({tri, b});
    }
  }

  PointBox triangleBox(const std::array<Index, 3>& t) const {
    const std::array<Vec3, 3> corners{m_.nodes[t[0]], m_.nodes[t[1]], m_.nodes[t[2]]};
    return boxOf(corners.data(), corners.data() + 3);
  }

  // Does triangle t of a new triangulation cross a boundary triangle near the
  // edge, a current triangle of another polygon (not p0, p1: being replaced)
  // or one of `also`?
  bool folds(const std::array<Index, 3>& t, const BoundaryPolygon& p0, const BoundaryPolygon& p1,
             const std::vector<std::array<Index, 3>>& also) const {
    const PointBox b = triangleBox(t);
    auto crosses = [&](const std::array<Index, 3>& u) {
      return boxesMeet(b, triangleBox(u)) && trianglesCross(m_.nodes, t, u);
    };
    auto crossesNearby = [&](const NearbyTriangle& u) {
      return boxesMeet(b, u.box) && trianglesCross(m_.nodes, t, u.corners);
    };
    if (std::any_of(nearby_.begin(), nearby_.end(), crossesNearby) || std::any_of(also.begin(), also.end(), crosses))
      return true;
    for (const BoundaryPolygon& q : polygons_)
      if (&q != &p0 && &q != &p1 && std::any_of(q.triangles.begin(), q.triangles.end(), crosses)) return true;
    return false;
  }

  static std::uint64_t key(Index a, Index b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(a) << 32) | b;
  }

  // The polygon of p: corners with split nodes between them; `extra` is a
  // split being tried on edge `extraEdge`.
  std::vector<Index> outline(const BoundaryPolygon& p, int extraEdge = -1, Index extra = kNoIndex) const {
    std::vector<Index> o;
    for (int k = 0; k < 3; ++k) {
      o.push_back(p.corners[k]);
      const Index s = k == extraEdge ? extra : p.splits[k];
      if (s != kNoIndex) o.push_back(s);
    }
    return o;
  }

  using TriangleKey = std::array<Index, 3>;  // sorted node ids
  static TriangleKey sortedKey(Index a, Index b, Index c) {
    TriangleKey k{a, b, c};
    std::sort(k.begin(), k.end());
    return k;
  }

  // Best triangulation of an outline coned to apex, and its score, without
  // the triangles in `forbidden` (see earsOfPartners) and without folds
  // (folds(), against the polygons p0, p1 of the edge being split and
  // `also`; nor within the triangulation). kNone when no triangulation fits.
  static constexpr std::size_t kNone = ~std::size_t{0};
  Score bestTriangulation(const BoundaryPolygon& p, const std::vector<Index>& o,
                          std::vector<std::array<Index, 3>>* out, const std::vector<TriangleKey>& forbidden,
                          const BoundaryPolygon& p0, const BoundaryPolygon& p1,
                          const std::vector<std::array<Index, 3>>& also) const {
    Score best{kNone, 0};
    std::vector<std::array<Index, 3>> chosen;
    std::vector<std::pair<TriangleKey, bool>> foldsOf;  // memo: a polygon of n <= 6 has at most 20 triangles
    auto triangleFolds = [&](const std::array<Index, 3>& t) {
      const TriangleKey k = sortedKey(t[0], t[1], t[2]);
      for (const auto& [key, f] : foldsOf)
        if (key == k) return f;
      const bool f = folds(t, p0, p1, also);
      foldsOf.emplace_back(k, f);
      return f;
    };
    for (const Triangulation& tr : triangulationsOf(static_cast<int>(o.size()))) {
      const bool allowed = std::none_of(tr.begin(), tr.end(), [&](const std::array<int, 3>& t) {
        const TriangleKey k = sortedKey(o[t[0]], o[t[1]], o[t[2]]);
        return std::find(forbidden.begin(), forbidden.end(), k) != forbidden.end();
      });
      if (!allowed) continue;
      Score s;
      for (const auto& t : tr) addToScore(s, m_.nodes, {p.apex, o[t[0]], o[t[1]], o[t[2]]});
      if (!(s < best)) continue;
      std::vector<std::array<Index, 3>> triangles;
      for (const auto& t : tr) triangles.push_back({o[t[0]], o[t[1]], o[t[2]]});
      bool fits = true;
      for (std::size_t i = 0; i < triangles.size() && fits; ++i) {
        fits = !triangleFolds(triangles[i]);
        for (std::size_t j = 0; j < i && fits; ++j) fits = !trianglesCross(m_.nodes, triangles[i], triangles[j]);
      }
      if (fits) {
        best = s;
        chosen = std::move(triangles);
      }
    }
    if (out) *out = std::move(chosen);
    return best;
  }

  // A polygon may keep a split edge's own three nodes (corner, split node,
  // corner) as one thin triangle, the split undone on its side. If the
  // polygon across that edge did the same, the boundary would hold one
  // triangle twice, back to back (a fin of no volume, on which neither
  // Vertex-Face element is the triangle's only one). So a polygon may not
  // use such a triangle where the polygon across the edge already does.
  std::vector<TriangleKey> earsOfPartners(const BoundaryPolygon& p) const {
    std::vector<TriangleKey> ears;
    const std::size_t self = static_cast<std::size_t>(&p - polygons_.data());
    for (int k = 0; k < 3; ++k) {
      if (p.splits[k] == kNoIndex) continue;
      const TriangleKey ear = sortedKey(p.corners[k], p.splits[k], p.corners[(k + 1) % 3]);
      const auto it = polygonsOfEdge_.find(key(p.corners[k], p.corners[(k + 1) % 3]));
      if (it == polygonsOfEdge_.end()) continue;
      for (std::size_t q : it->second)
        if (q != self && hasTriangle(polygons_[q].triangles, ear)) ears.push_back(ear);
    }
    return ears;
  }

  static bool hasTriangle(const std::vector<std::array<Index, 3>>& triangles, const TriangleKey& k) {
    return std::any_of(triangles.begin(), triangles.end(),
                       [&](const std::array<Index, 3>& t) { return sortedKey(t[0], t[1], t[2]) == k; });
  }

  int edgeIndex(const BoundaryPolygon& p, Index a, Index b) const {
    for (int k = 0; k < 3; ++k) {
      const Index x = p.corners[k], y = p.corners[(k + 1) % 3];
      if ((x == a && y == b) || (x == b && y == a)) return k;
    }
    return -1;
  }

  // Candidate split points: from the edge's midpoint toward each chain node
  // and the chain's centroid, by growing steps (the first positive one stays
  // closest to the boundary).
  std::vector<Vec3> candidates(Index a, Index b, const std::vector<std::size_t>& ee) const {
    std::vector<Index> chain;
    for (std::size_t i : ee) chain.push_back(m_.tets[i][2]), chain.push_back(m_.tets[i][3]);
    std::sort(chain.begin(), chain.end());
    chain.erase(std::unique(chain.begin(), chain.end()), chain.end());
    const Vec3 &pa = m_.nodes[a], &pb = m_.nodes[b];
    const Vec3 mid{(pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, (pa[2] + pb[2]) / 2};
    std::vector<Vec3> targets;
    Vec3 centroid{0, 0, 0};
    for (Index v : chain) {
      targets.push_back(m_.nodes[v]);
      for (int k = 0; k < 3; ++k) centroid[k] += m_.nodes[v][k] / static_cast<double>(chain.size());
    }
    targets.push_back(centroid);
    for (std::size_t i : ee) {  // chain segment midpoints
      const Vec3 &p = m_.nodes[m_.tets[i][2]], &q = m_.nodes[m_.tets[i][3]];
      targets.push_back({(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2});
    }
    // Up to and a little past the chain: when the chain lies between the
    // edge and the cut face, the face is just beyond it.
    static constexpr double kSteps[] = {0.05, 0.1, 0.2, 0.35, 0.5, 0.7, 0.9, 1.02, 1.1, 1.25};
    const double dx = pa[0] - pb[0], dy = pa[1] - pb[1], dz = pa[2] - pb[2];
    const double length2 = dx * dx + dy * dy + dz * dz;
    const double tooClose = 1e-6 * length2;  // (1e-3 of the edge)^2
    std::vector<Vec3> out;
    for (double s : kSteps)
      for (const Vec3& q : targets) {
        // The boundary is bent at c: no farther from the edge's midpoint than
        // the edge is long (a chain node of a flat cell can be anywhere, and
        // on a thick part the chain is many edge lengths away): the step is
        // shortened to that.
        const double qx = q[0] - mid[0], qy = q[1] - mid[1], qz = q[2] - mid[2];
        const double far = std::sqrt(qx * qx + qy * qy + qz * qz);
        const double step = far > 0 ? std::min(s, std::sqrt(length2) / far) : s;
        const Vec3 c{mid[0] + step * qx, mid[1] + step * qy, mid[2] + step * qz};
        bool onChain = false;
        for (Index v : chain) {
          const double x = c[0] - m_.nodes[v][0], y = c[1] - m_.nodes[v][1], z = c[2] - m_.nodes[v][2];
          onChain = onChain || x * x + y * y + z * z <= tooClose;
        }
        if (!onChain) out.push_back(c);
      }
    return out;
  }

  // Both polygons of edge ab re-triangulated with split node m on it (p0's
  // first, p1's not folding through it nor repeating its ear a m b).
  // Returns their scores summed, negative = kNone when either has no
  // triangulation that fits; the triangulations go to tri0, tri1 if given.
  Score triangulateBoth(const BoundaryPolygon& p0, int k0, const BoundaryPolygon& p1, int k1, Index m,
                        std::vector<std::array<Index, 3>>* tri0 = nullptr,
                        std::vector<std::array<Index, 3>>* tri1 = nullptr) const {
    const Index a = p0.corners[k0], b = p0.corners[(k0 + 1) % 3];
    std::vector<std::array<Index, 3>> first;
    const Score s0 = bestTriangulation(p0, outline(p0, k0, m), &first, earsOfPartners(p0), p0, p1, {});
    if (s0.negative == kNone) return s0;
    std::vector<TriangleKey> forbidden1 = earsOfPartners(p1);
    if (hasTriangle(first, sortedKey(a, m, b))) forbidden1.push_back(sortedKey(a, m, b));
    const Score s1 = bestTriangulation(p1, outline(p1, k1, m), tri1, forbidden1, p0, p1, first);
    if (s1.negative == kNone) return s1;
    if (tri0) *tri0 = std::move(first);
    return {s0.negative + s1.negative, s0.deficit + s1.deficit};
  }

  bool trySplit(std::uint64_t edgeKey, const std::vector<std::size_t>& ee) {
    auto pit = polygonsOfEdge_.find(edgeKey);
    if (pit == polygonsOfEdge_.end() || pit->second.size() != 2 || ee.empty()) return false;  // non-manifold
    const Index a = m_.tets[ee[0]][0], b = m_.tets[ee[0]][1];
    BoundaryPolygon& p0 = polygons_[pit->second[0]];
    BoundaryPolygon& p1 = polygons_[pit->second[1]];
    const int k0 = edgeIndex(p0, a, b), k1 = edgeIndex(p1, a, b);
    if (k0 < 0 || k1 < 0 || p0.splits[k0] != kNoIndex || p1.splits[k1] != kNoIndex) return false;

    Score current;
    for (std::size_t i : ee) addToScore(current, m_.nodes, m_.tets[i]);
    for (const BoundaryPolygon* p : {&p0, &p1})
      for (const auto& t : p->triangles) addToScore(current, m_.nodes, {p->apex, t[0], t[1], t[2]});
    if (current.negative == 0) return false;

    // Try each candidate as a temporary node at the end of the node list.
    const Index m = static_cast<Index>(m_.nodes.size());
    m_.nodes.push_back({0, 0, 0});
    Score best = current;
    Vec3 bestPoint{};
    bool found = false;
    for (const Vec3& c : candidates(a, b, ee)) {
      m_.nodes[m] = c;
      Score s;
      for (std::size_t i : ee) {
        const auto& t = m_.tets[i];
        addToScore(s, m_.nodes, {t[0], m, t[2], t[3]});
        addToScore(s, m_.nodes, {m, t[1], t[2], t[3]});
      }
      // The polygons can only make the score worse: they add negative
      // elements or, adding none, a deficit of exactly 0. So a split point
      // whose Edge-Edge halves alone do no better than the best is not
      // worth re-triangulating them for (most of the split's time on pmi1,
      // where no edge is split: 40 → 6 ms).
      if (found ? !(s < best) : s.negative >= best.negative) continue;
      // kNone: every way to bend the boundary at c folds it.
      const Score polygons = triangulateBoth(p0, k0, p1, k1, m);
      if (polygons.negative == kNone) continue;
      s.negative += polygons.negative;
      s.deficit += polygons.deficit;
      if (s.negative < best.negative || (found && s < best)) {
        best = s;
        bestPoint = c;
        found = true;
      }
      if (found && best.negative == 0) break;
    }
    if (!found) {
      m_.nodes.pop_back();
      return false;
    }
    // Keep it: the node, the two halves of each Edge-Edge element, the new
    // triangulations of both polygons (the ones its score was made of).
    m_.nodes[m] = bestPoint;
    std::vector<std::array<Index, 3>> tri0, tri1;
    if (triangulateBoth(p0, k0, p1, k1, m, &tri0, &tri1).negative == kNone) {
      m_.nodes.pop_back();
      return false;
    }
    m_.nodeCell.push_back(kNoIndex);
    m_.boundaryNode.push_back(1);
    for (std::size_t i : ee) {
      const auto t = m_.tets[i];
      removed_.push_back(i);
      addElement(PairElementType::EdgeEdge, {t[0], m, t[2], t[3]}, m_.medialSimplex[i], {t[0], m, kNoIndex},
                 m_.onSheets[i]);
      addElement(PairElementType::EdgeEdge, {m, t[1], t[2], t[3]}, m_.medialSimplex[i], {m, t[1], kNoIndex},
                 m_.onSheets[i]);
    }
    p0.splits[k0] = m;
    p1.splits[k1] = m;
    p0.triangles = std::move(tri0);
    p1.triangles = std::move(tri1);
    for (BoundaryPolygon* p : {&p0, &p1}) {
      const std::size_t first = p->elements.front();
      const std::array<Index, 2> medial = m_.medialSimplex[first];
      const std::uint8_t linked = m_.onSheets[first];
      for (std::size_t e : p->elements) removed_.push_back(e);
      p->elements.clear();
      for (const auto& t : p->triangles) {
        p->elements.push_back(m_.tets.size());
        addElement(PairElementType::VertexFace, {p->apex, t[0], t[1], t[2]}, medial, t, linked);
      }
    }
    return true;
  }

  void addElement(PairElementType type, std::array<Index, 4> tet, std::array<Index, 2> medial,
                  std::array<Index, 3> boundary, std::uint8_t linked) {
    m_.tets.push_back(tet);
    m_.type.push_back(type);
    m_.medialSimplex.push_back(medial);
    m_.boundarySimplex.push_back(boundary);
    m_.onSheets.push_back(linked);
  }

  // Drops the replaced elements and rebuilds the boundary triangles; the
  // flags, when kept, follow (the new elements are the appended ones).
  void rebuild() {
    if (flags_) flagElementsNeedingRepair(m_.nodes, m_.tets, *flags_, flags_->size());
    std::vector<std::uint8_t> drop(m_.size(), 0);
    for (std::size_t i : removed_) drop[i] = 1;
    removeElements(m_, drop, flags_);
    recountElements(m_);
  }

  PairMesh& m_;
  const std::vector<std::size_t>* candidates_;  // optional: where the negative elements are
  std::vector<std::uint8_t>* flags_;            // optional: elementNeedsRepair per element
  std::map<std::uint64_t, std::vector<std::size_t>> edges_;  // ordered: the same splits on every run
  std::vector<std::uint8_t> edgeEnd_;  // per node: an end of one of edges_
  std::vector<BoundaryPolygon> polygons_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> polygonsOfEdge_;
  // Boundary triangles near edges_, not in polygons_, with their boxes
  // (each fold test reads them all).
  struct NearbyTriangle {
    std::array<Index, 3> corners;
    PointBox box;
  };
  std::vector<NearbyTriangle> nearby_;
  std::vector<std::size_t> removed_;
};

}  // namespace

std::size_t splitBoundaryEdges(PairMesh& m, const std::vector<std::size_t>* candidates,
                               std::vector<std::uint8_t>* needsRepairFlags) {
  if (needsRepairFlags && needsRepairFlags->size() != m.size())
    throw std::invalid_argument("pair-mesh edge split: one repair flag per element needed");
  return EdgeSplitter(m, candidates, needsRepairFlags).run();
}

}  // namespace cadmedial
