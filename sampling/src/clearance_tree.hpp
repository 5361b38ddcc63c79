// Small trees of samples, one per hash-grid cell of SampleBuilder, that
// answer "does any sample block this ball?" without scanning a crowded cell.
//
// The grid's cells are sized to the largest exclusion radius anywhere, so in
// graded parts (a lever's fillets next to its broad faces) one cell held
// hundreds of fine samples and every dart scanned them all (417 entries per
// query on the lever). A cell now splits into eight when it holds more than
// kLeafCapacity samples; every node keeps the tight box of its samples and
// the largest exclusion radius below it, and a query skips a node whose box
// lies at least max(radius, that largest radius) away. Answers are exact and
// equal to a full scan's: see `anyBlocks`.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <vector>

#include "cadmedial/sample_set.hpp"

namespace cadmedial {

// A sample as the trees keep it: position and exclusion next to the id, so a
// query reads contiguous entries instead of chasing ids into the SampleSet.
struct ClearanceEntry {
  double x, y, z, exclusion;
  Index id;
};

class ClearanceTrees {
 public:
  // A new, empty tree; returns its root.
  Index newTree() {
    nodes_.emplace_back();
    return static_cast<Index>(nodes_.size() - 1);
  }

  void insert(Index root, const ClearanceEntry& e) {
    Index n = root;
    for (int depth = 0;; ++depth) {
      Node& node = nodes_[n];
      node.include(e);
      if (node.firstChild != kNoIndex) {
        n = node.firstChild + node.childOf(e.x, e.y, e.z);
        continue;
      }
      node.entries.push_back(e);
      if (node.entries.size() > kLeafCapacity && depth < kMaxDepth) split(n);
      return;
    }
  }

  // Sets the exclusion radius of sample `id` at (x, y, z) in the tree of
  // `root`. A node's largest radius is only ever raised: a stale larger one
  // prunes less but never wrongly.
  void setExclusion(Index root, Index id, double x, double y, double z, double r) {
    Index n = root;
    while (true) {
      Node& node = nodes_[n];
      node.maxExclusion = std::max(node.maxExclusion, r);
      if (node.firstChild == kNoIndex) break;
      n = node.firstChild + node.childOf(x, y, z);
    }
    for (ClearanceEntry& q : nodes_[n].entries)
      if (q.id == id) q.exclusion = r;
  }

  // True iff some sample q (other than `ignore`) of the tree has
  // |p - q| < max(radius, exclusion(q)), or < radius when exclusions are not
  // honoured. A node is skipped when its box is at least max(radius, its
  // largest exclusion) from p, a bound on every limit below it. The box test
  // uses the same floating-point steps as the sample test on numbers that
  // are no larger (rounding is monotone), so it never skips a blocking sample.
  bool anyBlocks(Index root, double px, double py, double pz, double radius, Index ignore,
                 bool honourExclusion) const {
    // The root is not box-tested: the grid visits only cells within reach,
    // and most roots are leaves of a few samples, read as one short scan.
    std::array<Index, 8 * kMaxDepth + 1> stack;
    std::size_t top = 0;
    stack[top++] = root;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      if (node.firstChild != kNoIndex) {
        for (Index c = node.firstChild; c < node.firstChild + 8; ++c) {
          const Node& child = nodes_[c];
          const double reach = honourExclusion ? std::max(radius, child.maxExclusion) : radius;
          if (child.squaredDistance(px, py, pz) < reach * reach) stack[top++] = c;
        }
        continue;
      }
      for (const ClearanceEntry& q : node.entries) {
        if (q.id == ignore) continue;
        const double dx = q.x - px, dy = q.y - py, dz = q.z - pz;
        const double limit = honourExclusion ? std::max(radius, q.exclusion) : radius;
        if (dx * dx + dy * dy + dz * dz < limit * limit) return true;
      }
    }
    return false;
  }

  void clear() { nodes_.clear(); }
  std::size_t nodeCount() const { return nodes_.size(); }

 private:
  // Small enough that a crowded cell's query reads a few short leaves, large
  // enough that uniformly sampled cells (a handful of samples) never split.
  static constexpr std::size_t kLeafCapacity = 24;
  // Coincident samples cannot be told apart by splitting; stop.
  static constexpr int kMaxDepth = 12;

  struct Node {
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    // What a query reads first, then the box (children only) and the split.
    Index firstChild = kNoIndex;  // eight consecutive children, or a leaf
    std::vector<ClearanceEntry> entries;
    double maxExclusion = 0;
    // Tight box of the samples below (empty: +inf..-inf, never within reach).
    double lo[3] = {kInf, kInf, kInf}, hi[3] = {-kInf, -kInf, -kInf};
    double splitAt[3] = {0, 0, 0};

    void include(const ClearanceEntry& e) {
      lo[0] = std::min(lo[0], e.x), hi[0] = std::max(hi[0], e.x);
      lo[1] = std::min(lo[1], e.y), hi[1] = std::max(hi[1], e.y);
      lo[2] = std::min(lo[2], e.z), hi[2] = std::max(hi[2], e.z);
      maxExclusion = std::max(maxExclusion, e.exclusion);
    }
    Index childOf(double x, double y, double z) const {
      return (x < splitAt[0] ? 0 : 1) | (y < splitAt[1] ? 0 : 2) | (z < splitAt[2] ? 0 : 4);
    }
    // Squared distance from p to the box, summed in the sample test's order.
    double squaredDistance(double px, double py, double pz) const {
      const double dx = px < lo[0] ? lo[0] - px : (px > hi[0] ? px - hi[0] : 0);
      const double dy = py < lo[1] ? lo[1] - py : (py > hi[1] ? py - hi[1] : 0);
      const double dz = pz < lo[2] ? lo[2] - pz : (pz > hi[2] ? pz - hi[2] : 0);
      return dx * dx + dy * dy + dz * dz;
    }
  };

  void split(Index n) {
    const Index first = static_cast<Index>(nodes_.size());
    nodes_.resize(nodes_.size() + 8);  // may move nodes_: index, don't hold references
    Node& node = nodes_[n];
    for (int a = 0; a < 3; ++a) node.splitAt[a] = 0.5 * (node.lo[a] + node.hi[a]);
    node.firstChild = first;
    for (const ClearanceEntry& e : node.entries) {
      Node& child = nodes_[first + node.childOf(e.x, e.y, e.z)];
      child.include(e);
      child.entries.push_back(e);
    }
    std::vector<ClearanceEntry>().swap(node.entries);
  }

  std::vector<Node> nodes_;
};

}  // namespace cadmedial
