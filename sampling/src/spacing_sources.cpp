#include "spacing_sources.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "cadmedial/kd_tree.hpp"

namespace cadmedial {

// The sources in the project's k-d tree, each node keeping the finest
// spacing below it, so that a query skips a node whose best possible answer
// (that spacing, graded over the box's distance) cannot beat the best so
// far. CGAL's incremental nearest-first search did the same walk with a heap
// allocated per query: a quarter of the lever's sampling time.
struct SpacingSources::Tree {
  struct Point {
    Vec3 position;
    double spacing;
  };
  struct ByFinestSpacing {
    static const Vec3& position(const Point& p) { return p.position; }
    static double value(const Point& p) { return p.spacing; }
    static double merge(double a, double b) { return std::min(a, b); }
    static constexpr double kNoValue = std::numeric_limits<double>::infinity();
  };
  KdTree<Point, ByFinestSpacing> points;
};

SpacingSources::SpacingSources(std::vector<Source> sources, double grading)
    : tree_(std::make_unique<Tree>()),
      grading_(grading),
      finest_(std::numeric_limits<double>::infinity()) {
  std::vector<Tree::Point> points;
  points.reserve(sources.size());
  for (const Source& s : sources) {
    points.push_back({Vec3{s.point.X(), s.point.Y(), s.point.Z()}, s.spacing});
    finest_ = std::min(finest_, s.spacing);
  }
  tree_->points = KdTree<Tree::Point, Tree::ByFinestSpacing>(std::move(points));
}

SpacingSources::~SpacingSources() = default;

// The minimum is over every source; nodes are skipped only when their bound,
// computed with the same steps on numbers no larger (grading >= 0), is
// already >= the best, so the answer is that of a scan of all sources.
double SpacingSources::allowedNear(const gp_Pnt& p, double slack, double upTo) const {
  const Vec3 q{p.X(), p.Y(), p.Z()};
  auto graded = [&](double spacing, double squared) {
    return spacing + grading_ * std::max(0.0, std::sqrt(squared) - slack);
  };
  double best = upTo;
  using Node = decltype(tree_->points)::Node;
  tree_->points.search(
      [&](const Node& node) { return graded(node.summary, tree_->points.squaredBoxDistance(node, q)); },
      [&](double bound) { return bound < best; },
      [&](const Tree::Point& s) {
        const double dx = q[0] - s.position[0], dy = q[1] - s.position[1], dz = q[2] - s.position[2];
        best = std::min(best, graded(s.spacing, dx * dx + dy * dy + dz * dz));
        return false;
      });
  return best;
}

}  // namespace cadmedial
