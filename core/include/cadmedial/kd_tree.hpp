// A static k-d tree for branch-and-bound searches over points that carry a
// value: each node keeps the tight box of its points and a summary of their
// values (the largest ball radius in BallTree, the finest spacing in
// sampling's SpacingSources). A search gives each node a bound from its box
// and summary, and skips a node whose bound cannot matter any more.
//
// Layout: a leaf holds up to 8 items; a node splits at the median of its
// widest axis. Nodes are stored in pre-order (a node, its left subtree, its
// right subtree), so each subtree's place is known before it is built and
// the two halves of a large range are built in parallel into the same array
// a serial build makes.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include <tbb/parallel_invoke.h>

#include "cadmedial/sample_set.hpp"

namespace cadmedial {

// Positions are expected finite: a node's box starts at its first item's
// position, so a NaN there makes the node's bound NaN, and `open` decides
// whether such a node is searched.
//
// Traits: `static const Vec3& position(const Item&)`, `static double
// value(const Item&)`, `static double merge(double, double)` (associative,
// e.g. max or min) and `static constexpr double kNoValue` (merge's identity
// for the values that occur).
template <class Item, class Traits>
class KdTree {
 public:
  struct Node {
    Vec3 lo, hi;
    double summary = Traits::kNoValue;  // merge of the values below
    std::uint32_t begin = 0, end = 0;   // items[begin, end)
    std::int32_t left = -1, right = -1;  // children; -1 for a leaf
  };

  KdTree() = default;
  explicit KdTree(std::vector<Item> items) : items_(std::move(items)) {
    if (items_.empty()) return;
    const auto n = static_cast<std::uint32_t>(items_.size());
    nodes_.resize(nodeCount(n));
    build(0, n, 0);
  }

  bool empty() const { return nodes_.empty(); }
  const std::vector<Item>& items() const { return items_; }  // in leaf order

  // Squared distance from p to a node's box, per axis the gap outside
  // [lo, hi], summed x + y + z like a point-to-point distance: it never
  // exceeds the squared distance to an item inside (each step is monotone
  // in its arguments under rounding), which makes the bounds exact.
  static double squaredBoxDistance(const Node& node, const Vec3& p) {
    double s = 0;
    for (int k = 0; k < 3; ++k) {
      const double d = std::max({node.lo[k] - p[k], 0.0, p[k] - node.hi[k]});
      s += d * d;
    }
    return s;
  }

  // Depth-first, the nearer child (smaller bound; the right one on a tie)
  // first. bound(node) -> double; open(bound) says whether a node with that
  // bound may still matter: it is asked when a node would be pushed and
  // again when it is popped, as the search may have tightened since;
  // visit(item) -> true ends the search.
  template <class Bound, class Open, class Visit>
  void search(Bound&& bound, Open&& open, Visit&& visit) const {
    if (nodes_.empty()) return;
    // Each pop pushes at most two children, so at most one entry per level
    // waits plus the one popped next: a fixed array does (a growing vector
    // cost several allocations per query).
    std::pair<double, std::uint32_t> stack[kMaxDepth + 2];
    std::size_t size = 0;
    const double rootBound = bound(nodes_[0]);
    if (open(rootBound)) stack[size++] = {rootBound, 0};
    while (size > 0) {
      const auto [nodeBound, id] = stack[--size];
      if (!open(nodeBound)) continue;
      const Node& node = nodes_[id];
      if (node.left < 0) {
        for (std::uint32_t k = node.begin; k < node.end; ++k)
          if (visit(items_[k])) return;
        continue;
      }
      const double l = bound(nodes_[node.left]), r = bound(nodes_[node.right]);
      const bool leftNearer = l < r;
      const double nearBound = leftNearer ? l : r, farBound = leftNearer ? r : l;
      const auto nearId = static_cast<std::uint32_t>(leftNearer ? node.left : node.right);
      const auto farId = static_cast<std::uint32_t>(leftNearer ? node.right : node.left);
      if (open(farBound)) stack[size++] = {farBound, farId};
      if (open(nearBound)) stack[size++] = {nearBound, nearId};
    }
  }

 private:
  // Levels: halving from 2^32 items to leaves of <= 8 takes 30.
  static constexpr std::size_t kMaxDepth = 32;
  static constexpr std::uint32_t kLeafSize = 8;
  // Below this many items a subtree is built serially (a task costs more).
  static constexpr std::uint32_t kParallelBuild = 4096;

  static std::uint32_t nodeCount(std::uint32_t n) {
    if (n <= kLeafSize) return 1;
    return 1 + nodeCount(n / 2) + nodeCount(n - n / 2);
  }

  void build(std::uint32_t begin, std::uint32_t end, std::uint32_t id) {
    Node& node = nodes_[id];
    node.begin = begin;
    node.end = end;
    node.lo = node.hi = Traits::position(items_[begin]);
    for (std::uint32_t k = begin; k < end; ++k) {
      const Vec3& c = Traits::position(items_[k]);
      for (int j = 0; j < 3; ++j) {
        node.lo[j] = std::min(node.lo[j], c[j]);
        node.hi[j] = std::max(node.hi[j], c[j]);
      }
      node.summary = Traits::merge(node.summary, Traits::value(items_[k]));
    }
    if (end - begin <= kLeafSize) return;
    int axis = 0;
    for (int j = 1; j < 3; ++j)
      if (node.hi[j] - node.lo[j] > node.hi[axis] - node.lo[axis]) axis = j;
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
                     [axis](const Item& a, const Item& b) {
                       return Traits::position(a)[axis] < Traits::position(b)[axis];
                     });
    const std::uint32_t left = id + 1, right = left + nodeCount(mid - begin);
    node.left = static_cast<std::int32_t>(left);
    node.right = static_cast<std::int32_t>(right);
    if (end - begin >= kParallelBuild) {
      tbb::parallel_invoke([&] { build(begin, mid, left); }, [&] { build(mid, end, right); });
    } else {
      build(begin, mid, left);
      build(mid, end, right);
    }
  }

  std::vector<Item> items_;
  std::vector<Node> nodes_;
};

}  // namespace cadmedial
