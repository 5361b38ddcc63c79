// fillShortHoles on hand-built sheets: a hole whose rim is shorter than a
// medial ball on it is closed; a long rim (a real tunnel), a rim through a
// pinch vertex and the mouth of a pocket are left open.
#include <set>

#include <gtest/gtest.h>

#include "cadmedial/polygon_complex.hpp"

using namespace cadmedial;

namespace {

// An n x n grid of unit squares in the plane z = 0, every vertex with medial
// radius `radius`, without the squares (i, j) listed in `missing`.
MedialComplex gridSheet(int n, double radius, const std::set<std::pair<int, int>>& missing) {
  MedialComplex mc;
  auto id = [n](int i, int j) { return Index(i * (n + 1) + j); };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      mc.vertices.push_back({double(i), double(j), 0});
      mc.radius.push_back(radius);
      mc.vertexCell.push_back(id(i, j));
      mc.vertexSample.push_back(kNoIndex);
    }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (missing.count({i, j})) continue;
      for (Index v : {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}) mc.polygonVertices.push_back(v);
      mc.polygonOffsets.push_back(Index(mc.polygonVertices.size()));
      mc.provenance.push_back(PolygonProvenance::DelaunayEdgeFacet);
      mc.provenanceSamples.push_back({0, 1});
    }
  return mc;
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
  MedialComplex mc;
  for (int k = 0; k < 8; ++k) {
    const int i = k % 4;
    mc.vertices.push_back({double(i == 1 || i == 2), double(i >= 2), double(k / 4)});
    mc.radius.push_back(5);
    mc.vertexCell.push_back(Index(k));
    mc.vertexSample.push_back(kNoIndex);
  }
  for (Index i = 0; i < 4; ++i) {
    for (Index v : {i, (i + 1) % 4, (i + 1) % 4 + 4, i + 4}) mc.polygonVertices.push_back(v);
    mc.polygonOffsets.push_back(Index(mc.polygonVertices.size()));
    mc.provenance.push_back(PolygonProvenance::DelaunayEdgeFacet);
    mc.provenanceSamples.push_back({0, 1});
  }
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
  // Squares (1,1) and (2,2) share the vertex (2,2): four border edges there,
  // so neither rim is a simple cycle of border edges, and neither is closed
  // even under balls large enough for both (8 < 10).
  MedialComplex mc = gridSheet(4, 10.0, {{1, 1}, {2, 2}});
  ASSERT_EQ(loopsOf(mc), 2);
  EXPECT_EQ(fillOn(mc), 0u);
  EXPECT_EQ(loopsOf(mc), 2);
}

TEST(ShortHoles, TheMouthOfAPocketStaysOpen) {
  // A unit cube's surface without its top: closing the mouth would enclose a
  // void (β2 = 1) instead of removing a loop.
  MedialComplex mc;
  for (int k = 0; k < 8; ++k) {
    mc.vertices.push_back({double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)});
    mc.radius.push_back(5);
    mc.vertexCell.push_back(Index(k));
    mc.vertexSample.push_back(kNoIndex);
  }
  const std::vector<std::vector<Index>> walls = {{0, 1, 3, 2}, {0, 1, 5, 4}, {1, 3, 7, 5}, {3, 2, 6, 7}, {2, 0, 4, 6}};
  for (const auto& q : walls) {
    mc.polygonVertices.insert(mc.polygonVertices.end(), q.begin(), q.end());
    mc.polygonOffsets.push_back(Index(mc.polygonVertices.size()));
    mc.provenance.push_back(PolygonProvenance::DelaunayEdgeFacet);
    mc.provenanceSamples.push_back({0, 1});
  }
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
