#include "spacing_sources.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace cadmedial {

// A k-d tree whose every node keeps the tight box of its sources and the
// finest spacing among them, so that a query skips a node whose best possible
// answer (that spacing, graded over the box's distance) cannot beat the best
// so far. CGAL's incremental nearest-first search did the same walk with a
// heap allocated per query: a quarter of the lever's sampling time.
struct SpacingSources::Tree {
  static constexpr std::size_t kLeafSize = 8;
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  struct Point {
    double x, y, z, spacing;
  };
  struct Node {
    double lo[3] = {kInf, kInf, kInf}, hi[3] = {-kInf, -kInf, -kInf};
    double finest = kInf;
    std::uint32_t begin = 0, end = 0;  // leaf: points[begin, end)
    std::uint32_t left = 0, right = 0;  // inner: children (0: none, the root is never a child)
  };
  std::vector<Point> points;  // in leaf order
  std::vector<Node> nodes;

  std::uint32_t build(std::uint32_t begin, std::uint32_t end) {
    const auto n = static_cast<std::uint32_t>(nodes.size());
    nodes.emplace_back();
    Node node;
    node.begin = begin, node.end = end;
    for (std::uint32_t i = begin; i < end; ++i) {
      const Point& q = points[i];
      const double c[3] = {q.x, q.y, q.z};
      for (int a = 0; a < 3; ++a) node.lo[a] = std::min(node.lo[a], c[a]), node.hi[a] = std::max(node.hi[a], c[a]);
      node.finest = std::min(node.finest, q.spacing);
    }
    if (end - begin > kLeafSize) {
      int axis = 0;
      for (int a = 1; a < 3; ++a)
        if (node.hi[a] - node.lo[a] > node.hi[axis] - node.lo[axis]) axis = a;
      const std::uint32_t mid = begin + (end - begin) / 2;
      std::nth_element(points.begin() + begin, points.begin() + mid, points.begin() + end,
                       [axis](const Point& a, const Point& b) {
                         return (axis == 0 ? a.x : axis == 1 ? a.y : a.z) < (axis == 0 ? b.x : axis == 1 ? b.y : b.z);
                       });
      node.left = build(begin, mid);
      node.right = build(mid, end);
    }
    nodes[n] = node;
    return n;
  }

  // Squared distance from p to a node's box, summed in the source test's
  // order: it never exceeds the squared distance to a source inside (each
  // step is monotone in its arguments under rounding).
  static double squaredDistance(const Node& node, const double p[3]) {
    double d[3];
    for (int a = 0; a < 3; ++a) d[a] = p[a] < node.lo[a] ? node.lo[a] - p[a] : (p[a] > node.hi[a] ? p[a] - node.hi[a] : 0);
    return d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  }
};

SpacingSources::SpacingSources(std::vector<Source> sources, double grading)
    : tree_(std::make_unique<Tree>()),
      grading_(grading),
      finest_(std::numeric_limits<double>::infinity()) {
  tree_->points.reserve(sources.size());
  for (const Source& s : sources) {
    tree_->points.push_back({s.point.X(), s.point.Y(), s.point.Z(), s.spacing});
    finest_ = std::min(finest_, s.spacing);
  }
  if (!tree_->points.empty()) {
    // Leaves hold 4-8 points (halving ranges over 8), so up to 2n/4 nodes.
    tree_->nodes.reserve(tree_->points.size() / 2 + 1);
    tree_->build(0, static_cast<std::uint32_t>(tree_->points.size()));
  }
}

SpacingSources::~SpacingSources() = default;

// The minimum is over every source; nodes are skipped only when their bound,
// computed with the same steps on numbers no larger (grading >= 0), is
// already >= the best, so the answer is that of a scan of all sources.
double SpacingSources::allowedNear(const gp_Pnt& p, double slack, double upTo) const {
  const Tree& t = *tree_;
  if (t.nodes.empty()) return upTo;
  const double q[3] = {p.X(), p.Y(), p.Z()};
  auto graded = [&](double spacing, double squared) {
    return spacing + grading_ * std::max(0.0, std::sqrt(squared) - slack);
  };
  double best = upTo;
  // Depth-first, nearer child first; bounds travel with the stack entries
  // and are checked again when popped (best may have dropped since).
  struct Pending {
    std::uint32_t node;
    double bound;
  };
  // Each pop pushes at most two children: at most one entry per level
  // waits, plus the one popped next; depth <= log2(n / 4) < 31.
  std::array<Pending, 64> stack;
  std::size_t top = 0;
  stack[top++] = {0, graded(t.nodes[0].finest, Tree::squaredDistance(t.nodes[0], q))};
  while (top > 0) {
    const Pending pending = stack[--top];
    if (pending.bound >= best) continue;
    const Tree::Node& node = t.nodes[pending.node];
    if (node.left == 0) {
      for (std::uint32_t i = node.begin; i < node.end; ++i) {
        const Tree::Point& s = t.points[i];
        const double dx = q[0] - s.x, dy = q[1] - s.y, dz = q[2] - s.z;
        best = std::min(best, graded(s.spacing, dx * dx + dy * dy + dz * dz));
      }
      continue;
    }
    Pending near{node.left, graded(t.nodes[node.left].finest, Tree::squaredDistance(t.nodes[node.left], q))};
    Pending far{node.right, graded(t.nodes[node.right].finest, Tree::squaredDistance(t.nodes[node.right], q))};
    if (far.bound < near.bound) std::swap(near, far);
    if (far.bound < best) stack[top++] = far;
    if (near.bound < best) stack[top++] = near;
  }
  return best;
}

}  // namespace cadmedial
