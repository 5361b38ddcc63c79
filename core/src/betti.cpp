#include <algorithm>
#include <iterator>

#include "cadmedial/polygon_complex.hpp"
#include "cadmedial/union_find.hpp"

namespace cadmedial {

namespace {

// Z2 rank of the boundary matrix restricted to `columns` (each a sorted list
// of edge ids), by column reduction with the largest entry as pivot.
std::size_t z2Rank(std::vector<std::vector<Index>> columns, std::size_t edgeCount) {
  std::vector<Index> pivotOwner(edgeCount, kNoIndex);
  std::vector<Index> scratch;
  std::size_t rank = 0;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    std::vector<Index>& col = columns[c];
    while (!col.empty()) {
      const Index low = col.back();
      const Index owner = pivotOwner[low];
      if (owner == kNoIndex) {
        pivotOwner[low] = static_cast<Index>(c);
        ++rank;
        break;
      }
      scratch.clear();
      std::set_symmetric_difference(col.begin(), col.end(), columns[owner].begin(), columns[owner].end(),
                                    std::back_inserter(scratch));
      col.swap(scratch);
    }
  }
  return rank;
}

}  // namespace

// Elementary collapses: a polygon with a free edge (edge in exactly one
// remaining polygon) is removed together with that edge, until none has one.
std::vector<std::uint8_t> collapsedCore(const MedialComplex& mc, const ComplexEdges& edges) {
  const std::size_t ne = edges.vertices.size(), nf = mc.polygonCount();
  // Edge -> polygons incidence (CSR).
  std::vector<Index> offsets(ne + 1, 0);
  for (Index e : edges.slotEdge) ++offsets[e + 1];
  for (std::size_t e = 0; e < ne; ++e) offsets[e + 1] += offsets[e];
  std::vector<Index> incident(edges.slotEdge.size());
  {
    std::vector<Index> fill(offsets.begin(), offsets.end() - 1);
    for (std::size_t p = 0; p < nf; ++p)
      for (Index k = mc.polygonOffsets[p]; k < mc.polygonOffsets[p + 1]; ++k)
        incident[fill[edges.slotEdge[k]]++] = static_cast<Index>(p);
  }
  std::vector<Index> count(edges.polygonCount);
  std::vector<std::uint8_t> alive(nf, 1);
  std::vector<Index> queue;
  for (std::size_t e = 0; e < ne; ++e)
    if (count[e] == 1) queue.push_back(static_cast<Index>(e));
  while (!queue.empty()) {
    const Index e = queue.back();
    queue.pop_back();
    if (count[e] != 1) continue;
    Index poly = kNoIndex;
    for (Index k = offsets[e]; k < offsets[e + 1]; ++k)
      if (alive[incident[k]]) {
        poly = incident[k];
        break;
      }
    if (poly == kNoIndex) continue;
    alive[poly] = 0;
    for (Index k = mc.polygonOffsets[poly]; k < mc.polygonOffsets[poly + 1]; ++k) {
      const Index e2 = edges.slotEdge[k];
      if (--count[e2] == 1) queue.push_back(e2);
    }
  }
  return alive;
}

ComplexTopology computeTopology(const MedialComplex& mc, const ComplexEdges& edges, std::size_t coreLimit) {
  ComplexTopology t;
  const std::size_t nv = mc.vertices.size();
  const std::size_t ne = edges.vertices.size();
  const std::size_t nf = mc.polygonCount();
  t.vertices = nv;
  t.edges = ne;
  t.polygons = nf;
  t.euler = static_cast<long long>(nv) - static_cast<long long>(ne) + static_cast<long long>(nf);

  // β0: every vertex lies on some polygon, so the edges connect everything.
  UnionFind uf(nv);
  long long components = static_cast<long long>(nv);
  for (const auto& e : edges.vertices)
    if (uf.unite(e[0], e[1])) --components;
  t.beta0 = components;

  const std::vector<std::uint8_t> alive = collapsedCore(mc, edges);
  std::vector<std::vector<Index>> core;
  for (std::size_t p = 0; p < nf; ++p) {
    if (!alive[p]) continue;
    ++t.coreSize;
    if (t.coreSize > coreLimit) continue;
    std::vector<Index> col(edges.slotEdge.begin() + mc.polygonOffsets[p], edges.slotEdge.begin() + mc.polygonOffsets[p + 1]);
    std::sort(col.begin(), col.end());
    core.push_back(std::move(col));
  }
  if (t.coreSize <= coreLimit) {
    t.beta2 = static_cast<long long>(t.coreSize) - static_cast<long long>(z2Rank(std::move(core), ne));
    t.beta1 = t.beta0 + t.beta2 - t.euler;
  }
  return t;
}

}  // namespace cadmedial
