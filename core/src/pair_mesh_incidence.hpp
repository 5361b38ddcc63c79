// Private to the pair-mesh repair: node -> incident elements, kept current
// through re-triangulations of Voronoi polygons without a pass over all
// elements (on CTC-01 each rebuild was 15 ms, two of the three per repair).
#pragma once

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "cadmedial/pair_mesh.hpp"

namespace cadmedial {

class NodeIncidence {
 public:
  // From every element, for the nodes `keep` accepts only (the others have
  // none).
  template <typename Keep>
  void build(const PairMesh& m, Keep keep) {
    const std::size_t n = m.nodes.size();
    offsets_.assign(n + 1, 0);
    for (const auto& t : m.tets)
      for (Index v : t)
        if (keep(v)) ++offsets_[v + 1];
    for (std::size_t v = 0; v < n; ++v) offsets_[v + 1] += offsets_[v];
    incident_.resize(offsets_[n]);
    std::vector<Index> fill(offsets_.begin(), offsets_.end() - 1);
    for (std::size_t i = 0; i < m.tets.size(); ++i)
      for (Index v : m.tets[i])
        if (keep(v)) incident_[fill[v]++] = static_cast<Index>(i);
    rewritten_.clear();
    extra_.clear();
  }

  // After the polygon with these element slots was re-triangulated (its
  // elements keep their slots and, all together, its nodes; which element
  // holds which node changes). The first time, its slots leave the lists
  // built and every node of the polygon gets all of them, each visit then
  // keeping those that hold the node.
  template <typename Keep>
  void polygonRewritten(const PairMesh& m, const std::vector<std::size_t>& slots, Keep keep) {
    if (slots.empty()) return;
    if (rewritten_.size() != m.tets.size()) rewritten_.assign(m.tets.size(), 0);
    if (rewritten_[slots[0]]) return;  // its nodes already list all its slots
    std::vector<Index> nodes;
    for (std::size_t i : slots) {
      rewritten_[i] = 1;
      for (Index v : m.tets[i])
        if (keep(v)) nodes.push_back(v);
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
  std::vector<Index> offsets_, incident_;
  // Per element: its polygon was re-triangulated (empty while none was).
  std::vector<std::uint8_t> rewritten_;
  // Per node of such polygons: their element slots, sorted.
  std::unordered_map<Index, std::vector<Index>> extra_;
};

}  // namespace cadmedial
