// Private to the pair-mesh repair: node -> incident elements, kept current
// through re-triangulations of Voronoi polygons without a pass over all
// elements (on CTC-01 each rebuild was 15 ms, two of the three per repair).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include <tbb/parallel_for.h>

#include "cadmedial/pair_mesh.hpp"

namespace cadmedial {

class NodeIncidence {
 public:
  // From every element, for the nodes `keep` accepts only (asking for
  // another node is an error: its list would be silently empty).
  template <typename Keep>
  void build(const PairMesh& m, Keep keep) {
    const std::size_t n = m.nodes.size();
    kept_.assign(n, 0);
    for (Index v = 0; v < n; ++v) kept_[v] = keep(v) ? 1 : 0;
    elements_ = m.tets.size();
    // The (node, element) pairs of the kept nodes, in element order: found
    // in parallel over blocks of elements joined in block order (the kept
    // nodes are often a few thousand of 10^5, and two serial passes over
    // every element were most of a build).
    constexpr std::size_t kBlock = 16384;
    const std::size_t blocks = (m.tets.size() + kBlock - 1) / kBlock;
    std::vector<std::vector<std::array<Index, 2>>> found(blocks);
    tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) {
      const std::size_t end = std::min(m.tets.size(), (b + 1) * kBlock);
      for (std::size_t i = b * kBlock; i < end; ++i)
        for (Index v : m.tets[i])
          if (kept_[v]) found[b].push_back({v, static_cast<Index>(i)});
    });
    offsets_.assign(n + 1, 0);
    for (const auto& block : found)
      for (const auto& pair : block) ++offsets_[pair[0] + 1];
    for (std::size_t v = 0; v < n; ++v) offsets_[v + 1] += offsets_[v];
    incident_.resize(offsets_[n]);
    std::vector<Index> fill(offsets_.begin(), offsets_.end() - 1);
    for (const auto& block : found)
      for (const auto& pair : block) incident_[fill[pair[0]]++] = pair[1];
    rewritten_.clear();
    extra_.clear();
  }

  // After the polygon with these element slots was re-triangulated. What
  // makes this work: a polygon always has the same slots, and any
  // triangulation of it uses all of its corners, so the set of nodes its
  // elements hold never changes; only which element holds which does. The
  // first time, its slots leave the lists built and every node of the
  // polygon gets all of them; a visit keeps those that hold the node.
  void polygonRewritten(const PairMesh& m, const std::vector<std::size_t>& slots) {
    if (slots.empty()) return;
    if (m.tets.size() != elements_)
      throw std::logic_error("pair-mesh: the incidence was built for another element count");
    if (rewritten_.empty()) rewritten_.assign(m.tets.size(), 0);
    if (rewritten_[slots[0]]) return;  // its nodes already list all its slots
    std::vector<Index> nodes;
    for (std::size_t i : slots) {
      rewritten_[i] = 1;
      for (Index v : m.tets[i])
        if (kept_[v]) nodes.push_back(v);
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    for (Index v : nodes) {
      std::vector<Index>& list = extra_[v];
      for (std::size_t i : slots) list.push_back(static_cast<Index>(i));
      std::sort(list.begin(), list.end());
    }
  }

  // f(element) for each element holding v, in increasing element order (the
  // order of a fresh build: the repair's choices do not depend on how the
  // lists were kept).
  template <typename F>
  void forEach(const PairMesh& m, Index v, F&& f) const {
    if (v >= kept_.size() || !kept_[v]) throw std::logic_error("pair-mesh: incidence asked for a node not built for");
    Index k = offsets_[v];
    const Index end = offsets_[v + 1];
    if (rewritten_.empty()) {
      for (; k < end; ++k) f(incident_[k]);
      return;
    }
    static const std::vector<Index> kNone;
    const auto found = extra_.find(v);
    const std::vector<Index>& extra = found == extra_.end() ? kNone : found->second;
    std::size_t j = 0;
    while (k < end || j < extra.size()) {
      if (j == extra.size() || (k < end && incident_[k] < extra[j])) {
        const Index i = incident_[k++];
        if (!rewritten_[i]) f(i);
      } else {
        const Index i = extra[j++];
        const auto& t = m.tets[i];
        if (t[0] == v || t[1] == v || t[2] == v || t[3] == v) f(i);
      }
    }
  }

 private:
  std::vector<std::uint8_t> kept_;  // per node: has a list
  std::size_t elements_ = 0;         // the element count it was built for
  std::vector<Index> offsets_, incident_;
  // Per element: its polygon was re-triangulated (empty while none was).
  std::vector<std::uint8_t> rewritten_;
  // Per node of such polygons: their element slots, sorted.
  std::unordered_map<Index, std::vector<Index>> extra_;
};

}  // namespace cadmedial
