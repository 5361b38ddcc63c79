// Single steps of the pair-mesh build and repair, on hand-made inputs whose
// right answer is known: the re-triangulation of a folded Voronoi polygon,
// the label of a flat Delaunay cell, and the boundary cells offered for
// relabelling around an inverted element.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cadmedial/pair_mesh.hpp"
#include "pair_mesh_boundary_cells.hpp"
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

namespace {

// Samples of a wedge (a knife): two 9 × 9 grids, z = 0 and z = slope x,
// from x = 0.1 to x = 0.9 (0.003 to 0.027 thick for slope 0.03).
SampleSet knife(double slope = 0.03) {
  SampleSet s;
  for (int i = 1; i <= 9; ++i)
    for (int j = 1; j <= 9; ++j) {
      const double x = 0.1 * i, y = 0.1 * j;
      s.points.push_back({x, y, 0});
      s.points.push_back({x, y + 0.013, slope * x});  // shifted: no four cospherical
    }
  return s;
}

// Inner cells around every edge of the triangulation form at most one run.
std::size_t nonManifoldEdges(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner) {
  std::size_t bad = 0;
  const auto& dt = dv.triangulation();
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    auto circ = dt.incident_cells(*e);
    const auto start = circ;
    auto isInner = [&](const auto& c) {
      const Index id = DelaunayVoronoi::cellId(c);
      return !dv.isInfinite(id) && inner[id] != 0;
    };
    int changes = 0;
    bool previous = isInner(start);
    do {
      ++circ;
      changes += isInner(circ) != previous ? 1 : 0;
      previous = isInner(circ);
    } while (circ != start);
    bad += changes > 2 ? 1 : 0;
  }
  return bad;
}

}  // namespace

// Each boundary facet in turn gets the Voronoi node of its cell pushed far out
// through it (its Vertex-Face element inverted). The cells offered for
// relabelling include that cell, and the boundary stays manifold at every
// edge: in the thin wedge many cells can only go together with the runs of
// cells they cut off around an edge (without those, 155 of the 263 are
// offered).
TEST(PairMeshRepairSteps, RelabelledBoundaryCellsKeepEveryEdgeManifold) {
  const SampleSet samples = knife();
  const DelaunayVoronoi dv(samples.points);
  std::vector<std::uint8_t> inner(dv.cellCount(), 0);
  for (Index c = 0; c < dv.cellCount(); ++c) inner[c] = dv.isInfinite(c) ? 0 : 1;
  ASSERT_EQ(nonManifoldEdges(dv, inner), 0u);
  const PairMesh built = buildPairMesh(dv, samples, inner, nullptr, false);
  ASSERT_EQ(built.counts.relabelledFlatCells, 0u);  // `inner` is the mesh's own labels
  std::size_t tried = 0, offered = 0;
  for (std::size_t i = 0; i < built.size(); ++i) {
    if (built.type[i] != PairElementType::VertexFace) continue;
    PairMesh m = built;
    const auto& t = m.tets[i];
    const Vec3 &x = m.nodes[t[1]], &y = m.nodes[t[2]], &z = m.nodes[t[3]];
    const Vec3 u{y[0] - x[0], y[1] - x[1], y[2] - x[2]}, v{z[0] - x[0], z[1] - x[1], z[2] - x[2]};
    const Vec3 n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 1e-9)) continue;  // three collinear samples of a grid row
    for (double side : {10.0, -10.0}) {  // the side that inverts it (outward)
      for (int k = 0; k < 3; ++k) m.nodes[t[0]][k] = (x[k] + y[k] + z[k]) / 3 + side * n[k] / len;
      if (isInverted(m, i)) break;
    }
    ASSERT_TRUE(isInverted(m, i)) << i;
    const Index cell = m.nodeCell[t[0]];
    const std::vector<Index> cells = boundaryCellsOfInvertedElements(dv, inner, m);
    ++tried;
    std::vector<std::uint8_t> relabelled = inner;
    for (Index c : cells) {
      EXPECT_NE(inner[c], 0) << "only inner cells are offered";
      relabelled[c] = 0;
    }
    EXPECT_EQ(nonManifoldEdges(dv, relabelled), 0u) << "element " << i;
    if (std::find(cells.begin(), cells.end(), cell) != cells.end()) ++offered;
  }
  EXPECT_GT(tried, 100u);
  EXPECT_EQ(offered, tried);
}

// The whole knife inner: the repair alone leaves elements inverted (its
// cospherical grids), and relabelling the boundary cells around them is
// tried but refused, for two reasons: with the thin knife (slope 0.03) the
// cells hold more than 1e-3 of the volume (the budget); with the thick one
// (0.3) the rebuilt mesh has more inverted elements (86 against 56). Either
// way the mesh is the repaired one, untouched. (The accepted case, where
// fewer stay inverted, is on real parts: pmi1 and the lever in
// tests/pairmesh/test_pair_mesh_cli.py.)
TEST(PairMeshRepairSteps, RelabellingThatDoesNotHelpIsRefused) {
  for (double slope : {0.03, 0.3}) {
    const SampleSet samples = knife(slope);
    const DelaunayVoronoi dv(samples.points);
    std::vector<std::uint8_t> inner(dv.cellCount(), 0);
    for (Index c = 0; c < dv.cellCount(); ++c) inner[c] = dv.isInfinite(c) ? 0 : 1;
    PairMesh repairedOnly = buildPairMesh(dv, samples, inner, nullptr, false);
    const std::size_t leftByRepair = repairFlippedElements(repairedOnly, dv);
    ASSERT_GT(leftByRepair, 0u) << slope;
    ASSERT_FALSE(boundaryCellsOfInvertedElements(dv, inner, repairedOnly).empty()) << slope;
    const PairMesh m = buildPairMesh(dv, samples, inner);
    EXPECT_EQ(m.counts.relabelledBoundaryCells, 0u) << slope;
    EXPECT_EQ(m.counts.invertedAfterRepair, leftByRepair) << slope;
    EXPECT_EQ(m.tets, repairedOnly.tets) << slope;
    EXPECT_EQ(m.nodes, repairedOnly.nodes) << slope;
  }
}
