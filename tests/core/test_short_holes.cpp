// fillShortHoles on hand-built sheets: a hole whose rim is shorter than a
// medial ball on it is closed; a long rim (a real tunnel), a rim through a
// pinch vertex and the mouth of a pocket are left open.
#include <algorithm>
#include <array>
#include <set>

#include <gtest/gtest.h>

#include "cadmedial/polygon_complex.hpp"
#include "complex_builders.hpp"

using namespace cadmedial;

namespace {

// The points and squares of an n x n grid of unit squares in the plane
// z = 0 (vertex (i, j) is i (n + 1) + j), without the squares (i, j) listed
// in `missing`.
struct Grid {
  std::vector<Vec3> points;
  std::vector<std::vector<Index>> squares;
};
Grid grid(int n, const std::set<std::pair<int, int>>& missing) {
  Grid g;
  auto id = [n](int i, int j) { return Index(i * (n + 1) + j); };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) g.points.push_back({double(i), double(j), 0});
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (!missing.count({i, j})) g.squares.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return g;
}

MedialComplex gridSheet(int n, double radius, const std::set<std::pair<int, int>>& missing) {
  const Grid g = grid(n, missing);
  return sheetOf(g.points, radius, g.squares);
}

std::size_t fillOn(MedialComplex& mc) {
  ComplexEdges edges = buildComplexEdges(mc);
  return fillShortHoles(mc, edges);
}

// fillShortHoles keeps the edge table up to date: the same as built afresh.
void expectEdgesCurrent(const MedialComplex& mc, const ComplexEdges& edges) {
  const ComplexEdges fresh = buildComplexEdges(mc);
  EXPECT_EQ(edges.vertices, fresh.vertices);
  EXPECT_EQ(edges.polygonCount, fresh.polygonCount);
  EXPECT_EQ(edges.firstPolygon, fresh.firstPolygon);
  EXPECT_EQ(edges.secondPolygon, fresh.secondPolygon);
  EXPECT_EQ(edges.slotEdge, fresh.slotEdge);
  EXPECT_EQ(edges.borderEdges, fresh.borderEdges);
  EXPECT_EQ(edges.manifoldEdges, fresh.manifoldEdges);
  EXPECT_EQ(edges.junctionEdges, fresh.junctionEdges);
}

long long loopsOf(const MedialComplex& mc) { return computeTopology(mc, buildComplexEdges(mc), 1000).beta1; }

}  // namespace

TEST(ShortHoles, AHoleInsideABallIsClosedByOnePolygonOnItsRim) {
  // One missing unit square: rim length 4 < radius 5.
  MedialComplex mc = gridSheet(4, 5.0, {{1, 2}});
  ASSERT_EQ(loopsOf(mc), 1);
  const std::size_t polygonsBefore = mc.polygonCount(), verticesBefore = mc.vertices.size();
  ComplexEdges edges = buildComplexEdges(mc);
  EXPECT_EQ(fillShortHoles(mc, edges), 1u);
  expectEdgesCurrent(mc, edges);
  EXPECT_EQ(mc.vertices.size(), verticesBefore);  // no vertex added, so medialness is untouched
  ASSERT_EQ(mc.polygonCount(), polygonsBefore + 1);
  const std::size_t fill = polygonsBefore;
  EXPECT_EQ(mc.provenance[fill], PolygonProvenance::HoleFill);
  EXPECT_EQ(mc.provenanceSamples.size(), mc.polygonCount());
  const std::set<Index> rim(mc.polygonVertices.begin() + mc.polygonOffsets[fill],
                            mc.polygonVertices.begin() + mc.polygonOffsets[fill + 1]);
  EXPECT_EQ(rim, (std::set<Index>{1 * 5 + 2, 2 * 5 + 2, 2 * 5 + 3, 1 * 5 + 3}));
  EXPECT_EQ(loopsOf(mc), 0);
}

TEST(ShortHoles, ARimLongerThanEveryBallOnItIsATunnelAndStaysOpen) {
  // Same hole, radius 3 < rim length 4: the loop may go round a real tunnel.
  MedialComplex mc = gridSheet(4, 3.0, {{1, 2}});
  EXPECT_EQ(fillOn(mc), 0u);
  EXPECT_EQ(loopsOf(mc), 1);
  // One large ball on the rim is not enough (it may reach through a wall
  // thinner than the sampling resolves); half the rim's are.
  mc.radius[1 * 5 + 2] = 4.5;
  EXPECT_EQ(fillOn(mc), 0u);
  mc.radius[2 * 5 + 3] = 4.5;
  EXPECT_EQ(fillOn(mc), 1u);
  EXPECT_EQ(loopsOf(mc), 0);
}

TEST(ShortHoles, SeveralHolesAreClosedAndTheEdgeTableFollows) {
  MedialComplex mc = gridSheet(5, 5.0, {{1, 1}, {3, 3}, {1, 3}});
  ASSERT_EQ(loopsOf(mc), 3);
  ComplexEdges edges = buildComplexEdges(mc);
  EXPECT_EQ(fillShortHoles(mc, edges), 3u);
  expectEdgesCurrent(mc, edges);
  EXPECT_EQ(loopsOf(mc), 0);
}

TEST(ShortHoles, OfATubesTwoShortMouthsOneIsClosed) {
  // A square tube of unit side and length: one loop. Closing one mouth
  // kills it; closing both would enclose a void.
  std::vector<Vec3> corners;
  for (int k = 0; k < 8; ++k) corners.push_back({double(k % 4 == 1 || k % 4 == 2), double(k % 4 >= 2), double(k / 4)});
  std::vector<std::vector<Index>> sides;
  for (Index i = 0; i < 4; ++i) sides.push_back({i, (i + 1) % 4, (i + 1) % 4 + 4, i + 4});
  MedialComplex mc = sheetOf(corners, 5, sides);
  ASSERT_EQ(loopsOf(mc), 1);
  ComplexEdges edges = buildComplexEdges(mc);
  EXPECT_EQ(fillShortHoles(mc, edges), 1u);
  expectEdgesCurrent(mc, edges);
  const ComplexTopology t = computeTopology(mc, edges, 1000);
  EXPECT_EQ(t.beta1, 0);
  EXPECT_EQ(t.beta2, 0);
  EXPECT_EQ(mc.polygonCount(), 5u);
  EXPECT_EQ(mc.provenance[4], PolygonProvenance::HoleFill);
}

TEST(ShortHoles, RimsThroughAPinchVertexAreLeftOpen) {
  // Squares (1,1) and (2,2) of a 4 x 4 grid share the vertex P = (2,2):
  // four border edges there, so neither rim is a simple cycle of border
  // edges, and neither is closed even under balls large enough for both
  // (8 < 10). The walk is made to start at P, along the first hole's edge
  // P-(2,1) (P is vertex 0 and that edge the first polygon's first side):
  // from there, a walk that went on through P would come back to P round
  // the first hole alone and close it.
  Grid g = grid(4, {{1, 1}, {2, 2}});
  const Index pinch = 2 * 5 + 2, below = 2 * 5 + 1;
  std::swap(g.points[0], g.points[pinch]);
  for (auto& square : g.squares)
    for (Index& v : square) v = v == pinch ? 0 : v == 0 ? pinch : v;
  for (std::size_t q = 0; q < g.squares.size(); ++q) {
    auto& square = g.squares[q];
    const auto at = std::find(square.begin(), square.end(), Index(0));
    if (at == square.end()) continue;
    std::rotate(square.begin(), at, square.end());
    if (square[1] != below) continue;  // square (2,1): (P, (2,1), (3,1), (3,2))
    std::swap(g.squares[0], g.squares[q]);
    break;
  }
  MedialComplex mc = sheetOf(g.points, 10.0, g.squares);
  const ComplexEdges edges = buildComplexEdges(mc);
  ASSERT_EQ(edges.vertices[0], (std::array<Index, 2>{0, below}));
  ASSERT_EQ(edges.polygonCount[0], 1u);
  ASSERT_EQ(loopsOf(mc), 2);
  EXPECT_EQ(fillOn(mc), 0u);
  EXPECT_EQ(loopsOf(mc), 2);
}

TEST(ShortHoles, TheMouthOfAPocketStaysOpen) {
  // A unit cube's surface without its top: closing the mouth would enclose a
  // void (β2 = 1) instead of removing a loop.
  std::vector<Vec3> corners;
  for (int k = 0; k < 8; ++k) corners.push_back({double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)});
  MedialComplex mc = sheetOf(corners, 5, {{0, 1, 3, 2}, {0, 1, 5, 4}, {1, 3, 7, 5}, {3, 2, 6, 7}, {2, 0, 4, 6}});
  const std::size_t before = mc.polygonCount();
  ComplexEdges edges = buildComplexEdges(mc);
  EXPECT_EQ(fillShortHoles(mc, edges), 0u);  // filled, then taken out again
  EXPECT_EQ(mc.polygonCount(), before);
  expectEdgesCurrent(mc, edges);
  const ComplexTopology t = computeTopology(mc, buildComplexEdges(mc), 1000);
  EXPECT_EQ(t.beta2, 0);
}

TEST(ShortHoles, TheOuterRimOfASmallDiskIsNotClosedIntoASphere) {
  // A lone 1 x 1 sheet under a big ball: its outer border is a short simple
  // cycle too, but a second polygon on it would enclose a void.
  MedialComplex mc = gridSheet(1, 5.0, {});
  EXPECT_EQ(fillOn(mc), 0u);
  EXPECT_EQ(mc.polygonCount(), 1u);
}
