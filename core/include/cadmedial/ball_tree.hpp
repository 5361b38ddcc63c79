// Balls (centre, radius) in a bounding-volume hierarchy over their centres,
// for min_v(|p - c_v| - r_v) by branch and bound: a node's bound is the
// distance to its centres' box minus its largest radius. Coverage of a
// boundary by medial balls (DESIGN.md §6) asks exactly this per boundary
// point; used by sampling/'s evaluation and by the analytic MEDIAL tests.
// Fringe thinning and the small-island test ask the yes/no form
// (hasGapAtMost): is some ball within a given gap of a point?
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include <tbb/parallel_invoke.h>

#include "cadmedial/sample_set.hpp"

namespace cadmedial {

class BallTree {
 public:
  struct Ball {
    Vec3 centre;
    double radius;
  };
  // |a - b| exactly as the search computes it, so that a caller testing a
  // few balls itself before a search gets the search's answer for them.
  static double distance(const Vec3& a, const Vec3& b) {
    const double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
    return std::sqrt(x * x + y * y + z * z);
  }

  explicit BallTree(std::vector<Ball> balls) : balls_(std::move(balls)) {
    if (balls_.empty()) return;
    const auto n = static_cast<std::uint32_t>(balls_.size());
    nodes_.resize(nodeCount(n));
    build(0, n, 0);
  }

  // Smallest gap |p - c| - r over all balls (+inf without balls); the search
  // stops as soon as a gap <= stopAt is found (then the result is only known
  // to be <= stopAt). Balls whose centre is nearer p than skipWithin are
  // left out (a point's own ball and its near copies).
  double minGap(const Vec3& p, double stopAt, double skipWithin = -1) const {
    double best = std::numeric_limits<double>::infinity();
    if (nodes_.empty()) return best;
    // Depth-first with the nearer child on top: the stack holds at most one
    // entry per level plus one (each pop pushes two), and the median split
    // keeps the tree ~log2(n / 8) deep, so a fixed array does (a growing
    // vector cost several allocations per query).
    std::pair<double, std::uint32_t> stack[kMaxDepth + 2];
    std::size_t size = 0;
    stack[size++] = {bound(nodes_[0], p), 0};
    while (size > 0) {
      const auto [lb, i] = stack[--size];
      if (lb >= best) continue;
      const Node& node = nodes_[i];
      if (node.left < 0) {
        for (std::uint32_t k = node.begin; k < node.end; ++k) {
          const double d = distance(p, balls_[k].centre);
          if (d < skipWithin) continue;
          best = std::min(best, d - balls_[k].radius);
          if (best <= stopAt) return best;
        }
        continue;
      }
      const double l = bound(nodes_[node.left], p), r = bound(nodes_[node.right], p);
      // Push the farther child first so the nearer one is searched first.
      if (l < r) {
        stack[size++] = {r, static_cast<std::uint32_t>(node.right)};
        stack[size++] = {l, static_cast<std::uint32_t>(node.left)};
      } else {
        stack[size++] = {l, static_cast<std::uint32_t>(node.left)};
        stack[size++] = {r, static_cast<std::uint32_t>(node.right)};
      }
    }
    return best;
  }

  // Whether some ball (centre not nearer p than skipWithin) has a gap
  // |p - c| - r <= limit: the same answer as minGap(p, limit, skipWithin) <=
  // limit, with the same gaps, but a node is skipped as soon as its bound is
  // over `limit`, not only over the best gap found so far. For a point with
  // no such ball (the usual case in fringe thinning) minGap had to narrow
  // the best gap down to the true minimum first: most of the thinning's
  // time on a torus.
  bool hasGapAtMost(const Vec3& p, double limit, double skipWithin = -1) const {
    if (nodes_.empty()) return false;
    std::uint32_t stack[kMaxDepth + 2];
    std::size_t size = 0;
    if (bound(nodes_[0], p) <= limit) stack[size++] = 0;
    while (size > 0) {
      const Node& node = nodes_[stack[--size]];
      if (node.left < 0) {
        for (std::uint32_t k = node.begin; k < node.end; ++k) {
          const double d = distance(p, balls_[k].centre);
          if (d < skipWithin) continue;
          if (d - balls_[k].radius <= limit) return true;
        }
        continue;
      }
      const double l = bound(nodes_[node.left], p), r = bound(nodes_[node.right], p);
      // The farther child first, so the nearer one is searched first.
      const bool leftNearer = l < r;
      const double farBound = leftNearer ? r : l, nearBound = leftNearer ? l : r;
      const auto far = static_cast<std::uint32_t>(leftNearer ? node.right : node.left);
      const auto near = static_cast<std::uint32_t>(leftNearer ? node.left : node.right);
      if (farBound <= limit) stack[size++] = far;
      if (nearBound <= limit) stack[size++] = near;
    }
    return false;
  }

 private:
  // Levels: halving from 2^32 balls to leaves of <= 8 takes 30.
  static constexpr std::size_t kMaxDepth = 32;
  struct Node {
    Vec3 lo, hi;
    double maxRadius = 0;
    std::uint32_t begin = 0, end = 0;
    std::int32_t left = -1, right = -1;
  };
  static double bound(const Node& n, const Vec3& p) {
    double s = 0;
    for (int k = 0; k < 3; ++k) {
      const double d = std::max({n.lo[k] - p[k], 0.0, p[k] - n.hi[k]});
      s += d * d;
    }
    return std::sqrt(s) - n.maxRadius;
  }
  // Nodes of the subtree over n balls: a leaf holds up to 8, a node splits
  // at the median. The tree is stored in pre-order (a node, its left
  // subtree, its right subtree), so each subtree's place is known before it
  // is built and the two halves of a large range are built in parallel into
  // the same array a serial build would make.
  static std::uint32_t nodeCount(std::uint32_t n) {
    if (n <= 8) return 1;
    return 1 + nodeCount(n / 2) + nodeCount(n - n / 2);
  }
  void build(std::uint32_t begin, std::uint32_t end, std::uint32_t id) {
    Node& node = nodes_[id];
    node.begin = begin;
    node.end = end;
    node.lo = node.hi = balls_[begin].centre;
    for (std::uint32_t k = begin; k < end; ++k) {
      const Vec3& c = balls_[k].centre;
      for (int j = 0; j < 3; ++j) {
        node.lo[j] = std::min(node.lo[j], c[j]);
        node.hi[j] = std::max(node.hi[j], c[j]);
      }
      node.maxRadius = std::max(node.maxRadius, balls_[k].radius);
    }
    if (end - begin <= 8) return;
    int axis = 0;
    for (int j = 1; j < 3; ++j)
      if (node.hi[j] - node.lo[j] > node.hi[axis] - node.lo[axis]) axis = j;
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(balls_.begin() + begin, balls_.begin() + mid, balls_.begin() + end,
                     [axis](const Ball& a, const Ball& b) { return a.centre[axis] < b.centre[axis]; });
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
  // Below this many balls a subtree is built serially (a task costs more).
  static constexpr std::uint32_t kParallelBuild = 4096;
  std::vector<Ball> balls_;
  std::vector<Node> nodes_;
};

}  // namespace cadmedial
