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
#include <limits>
#include <utility>
#include <vector>

#include "cadmedial/kd_tree.hpp"
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

  explicit BallTree(std::vector<Ball> balls) : tree_(std::move(balls)) {}

  // Smallest gap |p - c| - r over all balls (+inf without balls); the search
  // stops as soon as a gap <= stopAt is found (then the result is only known
  // to be <= stopAt). Balls whose centre is nearer p than skipWithin are
  // left out (a point's own ball and its near copies).
  double minGap(const Vec3& p, double stopAt, double skipWithin = -1) const {
    double best = std::numeric_limits<double>::infinity();
    tree_.search([&](const Tree::Node& node) { return bound(node, p); },
                 [&](double nodeBound) { return !(nodeBound >= best); },  // a NaN bound is searched, as before
                 [&](const Ball& ball) {
                   const double d = distance(p, ball.centre);
                   if (d < skipWithin) return false;
                   best = std::min(best, d - ball.radius);
                   return best <= stopAt;
                 });
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
    bool found = false;
    tree_.search([&](const Tree::Node& node) { return bound(node, p); },
                 [&](double nodeBound) { return nodeBound <= limit; },
                 [&](const Ball& ball) {
                   const double d = distance(p, ball.centre);
                   found = d >= skipWithin && d - ball.radius <= limit;
                   return found;
                 });
    return found;
  }

 private:
  struct ByLargestRadius {
    static const Vec3& position(const Ball& b) { return b.centre; }
    static double value(const Ball& b) { return b.radius; }
    static double merge(double a, double b) { return std::max(a, b); }
    static constexpr double kNoValue = 0;  // radii are >= 0
  };
  using Tree = KdTree<Ball, ByLargestRadius>;
  // A node's bound: the distance to its box minus its largest radius.
  static double bound(const Tree::Node& node, const Vec3& p) {
    return std::sqrt(Tree::squaredBoxDistance(node, p)) - node.summary;
  }
  Tree tree_;
};

}  // namespace cadmedial
