// Single steps of the pair-mesh build and repair, on hand-made inputs whose
// right answer is known: the re-triangulation of a folded Voronoi polygon,
// and the label of a flat Delaunay cell.
#include <gtest/gtest.h>

#include "cadmedial/pair_mesh.hpp"
#include "pair_mesh_facet_triangulation.hpp"

using namespace cadmedial;

namespace {

// Face-Vertex pyramids of one interior Delaunay edge a = (0, 0, -1),
// b = (0, 0, 1) over a non-convex Voronoi polygon in z = 0,
// A (1, 0) -> B (0, 2) -> C (-1, 0) -> D (0, 1), counter-clockwise with D
// reflex. The fan from A has (A, C, D) clockwise, so its two elements are
// negative; the fan from D is positive everywhere.
PairMesh chevronPyramids() {
  PairMesh m;
  m.nodes = {{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {0, 2, 0}, {-1, 0, 0}, {0, 1, 0}};
  m.sampleNodes = 2;
  m.boundaryNode = {1, 1, 0, 0, 0, 0};
  m.nodeCell = {kNoIndex, kNoIndex, 0, 1, 2, 3};
  const Index a = 0, b = 1, A = 2, B = 3, C = 4, D = 5;
  for (const auto& [p, q, r] : {std::array<Index, 3>{A, B, C}, std::array<Index, 3>{A, C, D}}) {
    m.tets.push_back({a, p, q, r});
    m.tets.push_back({b, p, r, q});
    for (Index apex : {a, b}) {
      m.type.push_back(PairElementType::FaceVertex);
      m.medialSimplex.push_back({0, 1});
      m.boundarySimplex.push_back({apex, kNoIndex, kNoIndex});
      m.onSheets.push_back(0);
    }
  }
  return m;
}

std::size_t inverted(const PairMesh& m) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < m.size(); ++i) n += isInverted(m, i) ? 1 : 0;
  return n;
}

double volumeSum(const PairMesh& m) {
  double s = 0;
  for (std::size_t i = 0; i < m.size(); ++i) s += tetVolume(m, i);
  return s;
}

}  // namespace

TEST(PairMeshRepairSteps, FoldedVoronoiPolygonGetsAPositiveTriangulation) {
  PairMesh m = chevronPyramids();
  ASSERT_EQ(inverted(m), 2u);
  const double before = volumeSum(m);
  EXPECT_EQ(retriangulateFaceVertexPolygons(m), 1u);
  EXPECT_EQ(inverted(m), 0u);
  // Same polygon, so the same double pyramid: area 1 × height 2 / 3.
  EXPECT_NEAR(volumeSum(m), before, 1e-15);
  EXPECT_NEAR(volumeSum(m), 2.0 / 3.0, 1e-15);
  for (std::size_t i = 0; i < m.size(); ++i) EXPECT_GT(tetVolume(m, i), 0.0) << i;
  // Nothing left to improve: a second pass changes nothing.
  EXPECT_EQ(retriangulateFaceVertexPolygons(m), 0u);
}

TEST(PairMeshRepairSteps, PolygonThatNoTriangulationFixesIsLeftAlone) {
  PairMesh m = chevronPyramids();
  // Apex b below the plane too: every triangle's b-element is negative
  // whatever the triangulation, so none has fewer bad elements than the fan.
  m.nodes[1] = {0, 0, -2};
  const auto tets = m.tets;
  EXPECT_EQ(retriangulateFaceVertexPolygons(m), 0u);
  EXPECT_EQ(m.tets, tets);
}

namespace {

// Four samples of a unit square in z = 0, one corner lifted by `lift`, and
// two far apexes: the square's cell is Delaunay (its small circumsphere is
// empty) and nearly flat for a tiny lift; its four neighbours hold the apexes.
SampleSet squareBetweenApexes(double lift) {
  SampleSet s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, lift}, {0, 1, 0}, {0.5, 0.5, 10}, {0.5, 0.5, -10}};
  return s;
}

Index squareCell(const DelaunayVoronoi& dv) {
  for (Index c = 0; c < dv.cellCount(); ++c) {
    if (dv.isInfinite(c)) continue;
    bool square = true;
    for (int i = 0; i < 4; ++i) square = square && dv.cellSample(c, i) < 4;
    if (square) return c;
  }
  return kNoIndex;
}

}  // namespace

TEST(PairMeshRepairSteps, FlatCellTakesItsNeighboursSide) {
  const SampleSet samples = squareBetweenApexes(1e-14);
  const DelaunayVoronoi dv(samples.points);
  const Index flat = squareCell(dv);
  ASSERT_NE(flat, kNoIndex);
  // Only the flat cell inner: the boundary would be its four faces, two
  // facing up and two down over the same square (a fold).
  std::vector<std::uint8_t> inner(dv.cellCount(), 0);
  inner[flat] = 1;
  const PairMesh m = buildPairMesh(dv, samples, inner);
  EXPECT_EQ(m.counts.relabelledFlatCells, 1u);
  EXPECT_EQ(m.size(), 0u);
  EXPECT_EQ(m.boundaryTriangles.size(), 0u);
}

TEST(PairMeshRepairSteps, ThickCellKeepsTheClassifiersSide) {
  const SampleSet samples = squareBetweenApexes(1e-3);
  const DelaunayVoronoi dv(samples.points);
  const Index cell = squareCell(dv);
  ASSERT_NE(cell, kNoIndex);
  std::vector<std::uint8_t> inner(dv.cellCount(), 0);
  inner[cell] = 1;
  const PairMesh m = buildPairMesh(dv, samples, inner, nullptr, false);
  EXPECT_EQ(m.counts.relabelledFlatCells, 0u);
  EXPECT_EQ(m.boundaryTriangles.size(), 4u);
  EXPECT_EQ(m.counts.vertexFace, 4u);
}
