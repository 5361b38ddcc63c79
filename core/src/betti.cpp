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
FreeFaceCollapse::FreeFaceCollapse(const MedialComplex& mc, const ComplexEdges& edges)
    : mc_(mc), edges_(edges), count_(edges.polygonCount), alive_(mc.polygonCount(), 1) {
  const std::size_t ne = edges.vertices.size(), nf = mc.polygonCount();
  // Edge -> polygons incidence (CSR).
  offsets_.assign(ne + 1, 0);
  for (Index e : edges.slotEdge) ++offsets_[e + 1];
  for (std::size_t e = 0; e < ne; ++e) offsets_[e + 1] += offsets_[e];
  incident_.resize(edges.slotEdge.size());
  {
    std::vector<Index> fill(offsets_.begin(), offsets_.end() - 1);
    for (std::size_t p = 0; p < nf; ++p)
      for (Index k = mc.polygonOffsets[p]; k < mc.polygonOffsets[p + 1]; ++k)
        incident_[fill[edges.slotEdge[k]]++] = static_cast<Index>(p);
  }
  for (std::size_t e = 0; e < ne; ++e)
    if (count_[e] == 1) queue_.push_back(static_cast<Index>(e));
  collapse();
}

void FreeFaceCollapse::removeFromCore(Index polygon) {
  if (!alive_[polygon]) return;
  takeOut(polygon);
  collapse();
}

void FreeFaceCollapse::takeOut(Index polygon) {
  alive_[polygon] = 0;
  for (Index k = mc_.polygonOffsets[polygon]; k < mc_.polygonOffsets[polygon + 1]; ++k) {
    const Index e = edges_.slotEdge[k];
    if (--count_[e] == 1) queue_.push_back(e);
  }
}

void FreeFaceCollapse::collapse() {
  while (!queue_.empty()) {
    const Index e = queue_.back();
    queue_.pop_back();
    if (count_[e] != 1) continue;
    for (Index k = offsets_[e]; k < offsets_[e + 1]; ++k)
      if (alive_[incident_[k]]) {
        takeOut(incident_[k]);
        break;
      }
  }
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

  const FreeFaceCollapse collapse(mc, edges);
  const std::vector<std::uint8_t>& alive = collapse.core();
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
