// trianglesCross, which keeps the edge split from folding the boundary:
// crossings and touches of two triangles, with 0, 1 or 2 shared corners,
// against cases worked out by hand.
#include <gtest/gtest.h>

#include "triangle_crossing.hpp"

namespace cadmedial {
namespace {

// Nodes: 0 (0,0,0), 1 (1,0,0), 2 (0,1,0) form the base triangle in z = 0.
std::vector<Vec3> nodesWith(std::vector<Vec3> extra) {
  std::vector<Vec3> nodes{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  nodes.insert(nodes.end(), extra.begin(), extra.end());
  return nodes;
}

TEST(TriangleCrossing, NoSharedCorner) {
  // 3, 4, 5: a triangle piercing the base (through (0.2, 0.2, 0)).
  auto nodes = nodesWith({{0.2, 0.2, -1}, {0.2, 0.2, 1}, {2, 2, 0.5}});
  EXPECT_TRUE(trianglesCross(nodes, {0, 1, 2}, {3, 4, 5}));
  // Lifted above the base: apart.
  nodes = nodesWith({{0.2, 0.2, 0.1}, {0.2, 0.2, 1}, {2, 2, 0.5}});
  EXPECT_FALSE(trianglesCross(nodes, {0, 1, 2}, {3, 4, 5}));
}

TEST(TriangleCrossing, SharedCorner) {
  // Shared corner 0; 3, 4 below and above the base's far edge: the other
  // triangle's far edge pierces the base.
  auto nodes = nodesWith({{0.3, 0.3, -1}, {0.3, 0.3, 1}});
  EXPECT_TRUE(trianglesCross(nodes, {0, 1, 2}, {0, 3, 4}));
  // Both above: they meet only at corner 0.
  nodes = nodesWith({{0.3, 0.3, 0.5}, {0.3, 0.3, 1}});
  EXPECT_FALSE(trianglesCross(nodes, {0, 1, 2}, {0, 3, 4}));
  // Coplanar, the other's edge from 0 inside the base's angle at 0: overlap
  // near 0 though no far edge crosses anything.
  nodes = nodesWith({{0.01, 0.02, 0}, {0.02, 0.01, 0}});
  EXPECT_TRUE(trianglesCross(nodes, {0, 1, 2}, {0, 3, 4}));
  // Coplanar and outside the base's angle: a neighbour in the same plane.
  nodes = nodesWith({{-1, 0.5, 0}, {-1, -0.5, 0}});
  EXPECT_FALSE(trianglesCross(nodes, {0, 1, 2}, {0, 3, 4}));
  // An edge from 0 running along the base's edge 0-1 (out of plane otherwise).
  nodes = nodesWith({{0.5, 0, 0}, {0, 0, 1}});
  EXPECT_TRUE(trianglesCross(nodes, {0, 1, 2}, {0, 3, 4}));
}

TEST(TriangleCrossing, SharedEdge) {
  // Shared edge 0-1. Folded flat onto the base (same side, coplanar): crosses.
  auto nodes = nodesWith({{0.5, 0.5, 0}});
  EXPECT_TRUE(trianglesCross(nodes, {0, 1, 2}, {1, 0, 3}));
  // Coplanar on the other side: an ordinary neighbour.
  nodes = nodesWith({{0.5, -0.5, 0}});
  EXPECT_FALSE(trianglesCross(nodes, {0, 1, 2}, {1, 0, 3}));
  // Bent out of the plane, even sharply back over the base: meets only along 0-1.
  nodes = nodesWith({{0.5, 0.5, 1e-9}});
  EXPECT_FALSE(trianglesCross(nodes, {0, 1, 2}, {1, 0, 3}));
}

TEST(TriangleCrossing, SameTriangleTwiceIsAFin) {
  const auto nodes = nodesWith({});
  EXPECT_TRUE(trianglesCross(nodes, {0, 1, 2}, {2, 1, 0}));
}

}  // namespace
}  // namespace cadmedial
