// Single steps of the pair-mesh build and repair, on hand-made inputs whose
// right answer is known: the re-triangulation of a folded Voronoi polygon,
// the label of a flat Delaunay cell, and the boundary cells offered for
// relabelling around an inverted element.
#include <gtest/gtest.h>

#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>

#include "cadmedial/pair_mesh.hpp"
#include "mesh_sets.hpp"
#include "synthetic_samples.hpp"
#include "pair_mesh_boundary_cells.hpp"
#include "pair_mesh_builder.hpp"
#include "pair_mesh_facet_triangulation.hpp"
#include "pair_mesh_element_checks.hpp"
#include "pair_mesh_incidence.hpp"

using namespace cadmedial;
using cadmedial::testing::gridBoxSamples;
using cadmedial::testing::orientedSet;

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

// Labels: every finite cell inner (the knife's samples span its whole hull).
std::vector<std::uint8_t> everyFiniteCell(const DelaunayVoronoi& dv) {
  std::vector<std::uint8_t> inner(dv.cellCount(), 0);
  for (Index c = 0; c < dv.cellCount(); ++c) inner[c] = dv.isInfinite(c) ? 0 : 1;
  return inner;
}

// The incidence kept through re-triangulations lists, for every node, the
// same elements in the same order as one built afresh: the repair's choices
// depend on that order. Each Voronoi polygon of a grid box is re-triangulated
// as a fan from another corner, twice (the second time its slots are already
// among those kept aside).
TEST(PairMeshRepairSteps, IncidenceFollowsRetriangulations) {
  const SampleSet samples = gridBoxSamples(5, 0.2);
  const DelaunayVoronoi dv(samples.points);
  PairMeshBuilder builder(dv, samples, nullptr);
  PairMesh m = builder.build(everyFiniteCell(dv));
  auto voronoiNode = [&m](Index v) { return !m.isBoundaryNode(v); };
  // Face-Vertex element slots per polygon, in element order (a's, b's, ...).
  std::map<std::array<Index, 2>, std::vector<std::size_t>> polygons;
  for (std::size_t i = 0; i < m.size(); ++i)
    if (m.type[i] == PairElementType::FaceVertex) polygons[m.medialSimplex[i]].push_back(i);
  NodeIncidence kept;
  kept.build(m, voronoiNode);
  auto listsOf = [&](const NodeIncidence& incidence) {
    std::vector<std::vector<Index>> lists(m.nodes.size());
    for (Index v = 0; v < m.nodes.size(); ++v)
      if (voronoiNode(v)) incidence.forEach(m, v, [&](Index i) { lists[v].push_back(i); });
    return lists;
  };
  std::size_t rewritten = 0, changedLists = 0;
  const auto before = listsOf(kept);
  for (int pass = 1; pass <= 2; ++pass) {
    for (const auto& [key, slots] : polygons) {
      // The polygon from the fan n0, n1, ..., its elements (a, n0, ni, nj).
      const Index a = m.tets[slots[0]][0], b = m.tets[slots[1]][0];
      std::vector<Index> polygon{m.tets[slots[0]][1], m.tets[slots[0]][2]};
      for (std::size_t t = 0; t < slots.size(); t += 2) polygon.push_back(m.tets[slots[t]][3]);
      const std::size_t k = polygon.size();
      if (k < 4) continue;  // one triangulation only
      for (std::size_t t = 0; t + 2 < k; ++t) {  // the fan from corner `pass`
        const Index p = polygon[pass % k], q = polygon[(pass + t + 1) % k], r = polygon[(pass + t + 2) % k];
        m.tets[slots[2 * t]] = {a, p, q, r};
        m.tets[slots[2 * t + 1]] = {b, p, r, q};
      }
      kept.polygonRewritten(m, slots);
      ++rewritten;
    }
    NodeIncidence fresh;
    fresh.build(m, voronoiNode);
    const auto now = listsOf(kept);
    EXPECT_EQ(now, listsOf(fresh)) << "after pass " << pass;
    for (Index v = 0; v < m.nodes.size(); ++v) changedLists += now[v] != before[v] ? 1 : 0;
  }
  EXPECT_GT(rewritten, 10u);
  EXPECT_GT(changedLists, 10u);  // the test re-triangulated something that shows
  // A node it was not built for has no list: asking is an error, not an
  // empty answer.
  EXPECT_THROW(kept.forEach(m, 0, [](Index) {}), std::logic_error);
}

// A build lists each kept node's elements, all of them and in increasing
// order, however it splits the elements for its parallel pass (16384 a
// block: this mesh has several), and only the kept nodes'.
TEST(PairMeshRepairSteps, IncidenceBuildListsEveryElementInOrder) {
  const Vec3 axes{1.0, 0.7, 0.45};
  const SampleSet samples = cadmedial::testing::ellipsoidCloud(axes, 4000, 1);
  const DelaunayVoronoi dv(samples.points);
  PairMeshBuilder builder(dv, samples, nullptr);
  const PairMesh m = builder.build(everyFiniteCell(dv));
  ASSERT_GT(m.size(), 3 * 16384u);
  auto keep = [&m](Index v) { return !m.isBoundaryNode(v) && v % 3 != 0; };
  NodeIncidence incidence;
  incidence.build(m, keep);
  std::vector<std::vector<Index>> byDefinition(m.nodes.size()), listed(m.nodes.size());
  for (std::size_t i = 0; i < m.size(); ++i)
    for (Index v : m.tets[i])
      if (keep(v)) byDefinition[v].push_back(static_cast<Index>(i));
  std::size_t kept = 0;
  for (Index v = 0; v < m.nodes.size(); ++v) {
    if (!keep(v)) {
      EXPECT_THROW(incidence.forEach(m, v, [](Index) {}), std::logic_error);
      continue;
    }
    incidence.forEach(m, v, [&](Index i) { listed[v].push_back(i); });
    ++kept;
  }
  EXPECT_GT(kept, 1000u);
  EXPECT_EQ(listed, byDefinition);
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
  const std::vector<std::uint8_t> inner = everyFiniteCell(dv);
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
    const std::vector<Index> cells = boundaryCellsOfElements(dv, inner, m, invertedElements(m));
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
TEST(PairMeshRepairSteps, RelabellingElementByElementHelpsWhereAllAtOnceDoesNot) {
  // Every finite cell of a knife inner (hostile labels): relabelling the
  // cells of all inverted elements at once helps neither way (the last
  // resort of 2c42da0 kept nothing here), but element by element some
  // trials pay off. Whatever is kept must leave fewer inverted elements and
  // no more needing repair.
  for (double slope : {0.03, 0.3}) {
    const SampleSet samples = knife(slope);
    const DelaunayVoronoi dv(samples.points);
    const std::vector<std::uint8_t> inner = everyFiniteCell(dv);
    PairMesh repairedOnly = buildPairMesh(dv, samples, inner, nullptr, false);
    const std::size_t leftByRepair = repairFlippedElements(repairedOnly, dv);
    ASSERT_GT(leftByRepair, 0u) << slope;
    ASSERT_FALSE(boundaryCellsOfElements(dv, inner, repairedOnly, invertedElements(repairedOnly)).empty()) << slope;
    const PairMesh m = buildPairMesh(dv, samples, inner);
    EXPECT_GT(m.counts.relabelledBoundaryCells, 0u) << slope;
    EXPECT_LT(m.counts.invertedAfterRepair, leftByRepair) << slope;
    EXPECT_EQ(m.counts.invertedAfterRepair, inverted(m)) << slope;
    EXPECT_LE(countElementsNeedingRepair(m.nodes, m.tets), countElementsNeedingRepair(repairedOnly.nodes, repairedOnly.tets))
        << slope;
  }
}

namespace {

// A mesh as sets, free of element order and node numbering: nodes named by
// sample id or by Delaunay cell, elements as sorted tuples of those names.
struct CanonicalMesh {
  std::vector<std::tuple<int, std::array<std::int64_t, 4>, std::array<Index, 2>, std::uint8_t>> elements;
  std::map<std::int64_t, Vec3> positions;
  std::set<std::vector<std::int64_t>> coincident;  // nodes sharing one position (welded), 2 or more
};

CanonicalMesh canonical(const PairMesh& m) {
  auto name = [&](Index n) {
    return m.nodeCell[n] == kNoIndex ? static_cast<std::int64_t>(n) : -1 - static_cast<std::int64_t>(m.nodeCell[n]);
  };
  CanonicalMesh c;
  for (std::size_t i = 0; i < m.size(); ++i) {
    std::array<std::int64_t, 4> t{};
    for (int k = 0; k < 4; ++k) t[k] = name(m.tets[i][k]);
    std::array<Index, 2> medial = m.medialSimplex[i];
    // (a, b, ci, cj) and (b, a, cj, ci) are one Edge-Edge element; which
    // one is built depends on the cell the edge was reached from.
    if (m.type[i] == PairElementType::EdgeEdge && t[0] > t[1]) {
      std::swap(t[0], t[1]);
      std::swap(t[2], t[3]);
      std::swap(medial[0], medial[1]);
    }
    c.elements.emplace_back(static_cast<int>(m.type[i]), t, medial, m.onSheets[i]);
  }
  std::sort(c.elements.begin(), c.elements.end());
  std::map<Vec3, std::vector<std::int64_t>> at;
  for (Index n = 0; n < m.nodes.size(); ++n) {
    c.positions[name(n)] = m.nodes[n];
    at[m.nodes[n]].push_back(name(n));
  }
  for (auto& [p, names] : at)
    if (names.size() > 1) {
      std::sort(names.begin(), names.end());
      c.coincident.insert(names);
    }
  return c;
}

}  // namespace

// Relabelling cells in place gives the mesh a rebuild with the new labels
// gives: the same elements on the same nodes, the same boundary (here before any repair, when both must agree). Positions agree
// to the weld tolerance (1e-8 of the extent: a welded cluster may take
// another member's position) and the same nodes share a position. Sets of
// cells: those around inverted elements that the last resort offers, sets
// that leave holes and pinches inside the knife and, from a knife with such
// holes, sets that fill some holes (cells going inner) while opening
// others; the same on a grid box, whose cospherical samples make welded
// clusters.
TEST(PairMeshRepairSteps, LocalRelabellingEqualsARebuild) {
  std::size_t goingInner = 0, weldedClusters = 0;
  for (const SampleSet& samples : {knife(0.3), gridBoxSamples(5, 0.2)}) {
    const DelaunayVoronoi dv(samples.points);
    const std::vector<std::uint8_t> full = everyFiniteCell(dv);
    std::vector<std::uint8_t> holed = full;
    for (Index c = 0; c < dv.cellCount(); c += 5) holed[c] = 0;
    PairMeshBuilder builder(dv, samples, nullptr);
    PairMesh repaired = builder.build(full);
    repairFlippedElements(repaired, dv);
    struct Case {
      const std::vector<std::uint8_t>* before;
      std::vector<Index> cells;
    };
    std::vector<Case> cases;
    if (const auto offered = boundaryCellsOfElements(dv, full, repaired, invertedElements(repaired)); !offered.empty())
      cases.push_back({&full, offered});
    for (Index stride : {3u, 7u, 50u}) {
      std::vector<Index> every;
      for (Index c = 0; c < dv.cellCount(); c += stride)
        if (full[c]) every.push_back(c);
      cases.push_back({&full, every});
    }
    for (Index stride : {10u, 15u, 35u}) {  // every second hole filled (stride 10), with others opened
      std::vector<Index> flip;
      for (Index c = 0; c < dv.cellCount(); c += stride)
        if (!dv.isInfinite(c)) flip.push_back(c);
      for (Index c = 3; c < dv.cellCount() && stride != 10; c += 11)
        if (holed[c]) flip.push_back(c);
      std::sort(flip.begin(), flip.end());
      flip.erase(std::unique(flip.begin(), flip.end()), flip.end());
      cases.push_back({&holed, flip});
    }
    Vec3 lo = samples.points[0], hi = samples.points[0];
    for (const Vec3& p : samples.points)
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    const double tolerance = 1e-8 * std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                              (hi[2] - lo[2]) * (hi[2] - lo[2]));
    for (const auto& [before, cells] : cases) {
      ASSERT_FALSE(cells.empty());
      std::vector<std::uint8_t> after = *before;
      for (Index c : cells) {
        after[c] = (*before)[c] ? 0 : 1;
        goingInner += after[c];
      }
      PairMesh local = builder.build(*before);
      ASSERT_TRUE(builder.relabel(local, after, cells));
      const PairMesh rebuilt = builder.build(after);
      const CanonicalMesh a = canonical(local), b = canonical(rebuilt);
      EXPECT_EQ(a.elements, b.elements) << cells.size();
      EXPECT_EQ(a.coincident, b.coincident) << cells.size();
      weldedClusters += b.coincident.size();
      ASSERT_EQ(a.positions.size(), b.positions.size());
      for (const auto& [n, p] : a.positions)
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[k], b.positions.at(n)[k], 2 * tolerance) << n;
      EXPECT_EQ(orientedSet(local.boundaryTriangles), orientedSet(rebuilt.boundaryTriangles));
      EXPECT_EQ(local.counts.innerCells, rebuilt.counts.innerCells);
      EXPECT_EQ(local.counts.faceVertex, rebuilt.counts.faceVertex);
      EXPECT_EQ(local.counts.edgeEdge, rebuilt.counts.edgeEdge);
      EXPECT_EQ(local.counts.vertexFace, rebuilt.counts.vertexFace);
      EXPECT_EQ(local.counts.boundaryTriangles, rebuilt.counts.boundaryTriangles);
      const PairMeshValidity v = checkPairMesh(local);
      EXPECT_EQ(v.boundaryEdgesNotShared, 0u);
      EXPECT_EQ(v.boundaryTrianglesNotInOneVertexFace, 0u);
    }
  }
  EXPECT_GT(goingInner, 50u);
  EXPECT_GT(weldedClusters, 0u);  // the grid box's welds were exercised
}

// Only the listed cells may change side, each listed once.
TEST(PairMeshRepairSteps, LocalRelabellingRejectsInconsistentLabels) {
  const SampleSet samples = knife(0.3);
  const DelaunayVoronoi dv(samples.points);
  const std::vector<std::uint8_t> inner = everyFiniteCell(dv);
  PairMeshBuilder builder(dv, samples, nullptr);
  const PairMesh built = builder.build(inner);
  Index a = 0;
  while (dv.isInfinite(a)) ++a;
  Index b = a + 1;
  while (dv.isInfinite(b)) ++b;
  std::vector<std::uint8_t> after = inner;
  after[a] = after[b] = 0;
  PairMesh m = built;
  EXPECT_THROW(builder.relabel(m, after, {a}), std::invalid_argument);     // b changed, not listed
  EXPECT_THROW(builder.relabel(m, after, {a, b, a}), std::invalid_argument);  // listed twice
  EXPECT_THROW(builder.relabel(m, inner, {a}), std::invalid_argument);     // listed, not changed
  EXPECT_EQ(m.tets, built.tets);
  EXPECT_TRUE(builder.relabel(m, after, {a, b}));
}

namespace {

// The chain identity in exact arithmetic: the elements' signed volumes add
// up to the volume the boundary triangles enclose. (The all-inner knife has
// Voronoi nodes of flat cells very far out, where rounding swamps the
// double sums.)
bool volumesAddUpExactly(const PairMesh& m) {
  using Q = CGAL::Exact_rational;
  auto det = [&](Index o, Index x, Index y, Index z) -> Q {  // Q, not an expression template over r
    std::array<std::array<Q, 3>, 3> r;
    const std::array<Index, 3> corners{x, y, z};
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k)
        r[i][k] = Q(m.nodes[corners[i]][k]) - (o == kNoIndex ? Q(0) : Q(m.nodes[o][k]));
    return r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) - r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
           r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
  };
  Q elements = 0, enclosed = 0;
  for (const auto& t : m.tets) elements += det(t[0], t[1], t[2], t[3]);
  for (const auto& t : m.boundaryTriangles) enclosed += det(kNoIndex, t[0], t[1], t[2]);
  return elements == enclosed;
}

}  // namespace

// Relabelling in place on a repaired mesh with split edges (a -> m -> b):
// a split on an edge of the relabelled cell is undone (m and the elements
// through it go; the boundary facets on ab that stay, and ab itself, get
// their elements back), and so is a split on another edge of a facet
// restored that way; every other split stays where it is. The result must
// still be a closed complex whose volumes add up exactly to the enclosed
// volume. (Every split here is of an edge between two samples, split once:
// nothing is declined.)
TEST(PairMeshRepairSteps, LocalRelabellingUndoesSplitEdges) {
  const SampleSet samples = knife();
  const DelaunayVoronoi dv(samples.points);
  const std::vector<std::uint8_t> inner = everyFiniteCell(dv);
  PairMeshBuilder builder(dv, samples, nullptr);
  PairMesh repaired = builder.build(inner);
  repairFlippedElements(repaired, dv);
  ASSERT_GT(repaired.counts.splitEdges, 0u);
  ASSERT_TRUE(volumesAddUpExactly(repaired));
  // The ends of each split node (from its Edge-Edge halves): here every
  // split is of an edge between two samples.
  std::map<std::pair<Index, Index>, Index> splitNodeOf;
  std::map<Index, std::set<Index>> ends;
  for (std::size_t i = 0; i < repaired.size(); ++i)
    if (repaired.type[i] == PairElementType::EdgeEdge)
      for (int k = 0; k < 2; ++k)
        if (!repaired.isSampleNode(repaired.tets[i][k])) ends[repaired.tets[i][k]].insert(repaired.tets[i][1 - k]);
  for (const auto& [m, e] : ends) {
    ASSERT_EQ(e.size(), 2u);
    ASSERT_TRUE(repaired.isSampleNode(*e.begin()) && repaired.isSampleNode(*e.rbegin()));
    splitNodeOf[{*e.begin(), *e.rbegin()}] = m;
  }
  ASSERT_EQ(splitNodeOf.size(), repaired.counts.splitEdges);
  std::size_t undoneCells = 0, cascaded = 0;
  for (Index c = 0; c < dv.cellCount(); ++c) {
    if (!inner[c]) continue;
    std::set<Index> undoneNodes;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const Index a = dv.cellSample(c, i), b = dv.cellSample(c, j);
        const auto it = splitNodeOf.find({std::min(a, b), std::max(a, b)});
        if (it != splitNodeOf.end()) undoneNodes.insert(it->second);
      }
    std::vector<std::uint8_t> after = inner;
    after[c] = 0;
    PairMesh m = repaired;
    ASSERT_TRUE(builder.relabel(m, after, {c})) << c;
    // Gone: the cell's Voronoi node and the undone split nodes (at least
    // those on the cell's edges); the other split nodes stay, in place.
    std::set<std::array<double, 3>> boundaryAfter;
    for (Index n = static_cast<Index>(m.sampleNodes); n < m.nodes.size(); ++n)
      if (m.isBoundaryNode(n)) boundaryAfter.insert(m.nodes[n]);
    std::size_t kept = 0;
    for (const auto& [edge, node] : splitNodeOf) {
      if (undoneNodes.count(node)) {
        EXPECT_EQ(boundaryAfter.count(repaired.nodes[node]), 0u) << c;
      }
      kept += boundaryAfter.count(repaired.nodes[node]);
    }
    EXPECT_EQ(boundaryAfter.size(), kept) << c;
    EXPECT_EQ(m.nodes.size(), repaired.nodes.size() - 1 - (splitNodeOf.size() - kept)) << c;
    cascaded += splitNodeOf.size() - kept - undoneNodes.size();
    const PairMeshValidity v = checkPairMesh(m);
    EXPECT_EQ(v.boundaryEdgesNotShared, 0u) << c;
    EXPECT_EQ(v.boundaryTrianglesNotInOneVertexFace, 0u) << c;
    if (!undoneNodes.empty()) {  // (slow: only where a split was undone)
      EXPECT_TRUE(volumesAddUpExactly(m)) << c;
    }
    undoneCells += undoneNodes.empty() ? 0 : 1;
  }
  EXPECT_GT(undoneCells, 10u);
  EXPECT_GT(cascaded, 0u);
}

// The repair's per-element flags (elementNeedsRepair) are carried through
// the edge splits and the in-place relabelling instead of tested again on
// every element; they must stay equal to a fresh test of every element:
// after a repair that split edges (the knife), and after relabelling cells
// of it (splits undone, elements dropped and added) and of the knife and a
// grid box as built (many elements to repair, whose entries must follow the
// compaction).
TEST(PairMeshRepairSteps, RepairFlagsFollowSplitsAndRelabelling) {
  auto mismatches = [](const PairMesh& m, const std::vector<std::uint8_t>& flags) {
    if (flags.size() != m.size()) return m.size() + 1;
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < m.size(); ++i) wrong += flags[i] != (elementNeedsRepair(m.nodes, m.tets[i]) ? 1 : 0);
    return wrong;
  };
  auto flagsOf = [](const PairMesh& m) {
    std::vector<std::uint8_t> flags(m.size());
    for (std::size_t i = 0; i < m.size(); ++i) flags[i] = elementNeedsRepair(m.nodes, m.tets[i]) ? 1 : 0;
    return flags;
  };
  {
    const SampleSet samples = knife();
    const DelaunayVoronoi dv(samples.points);
    const std::vector<std::uint8_t> inner = everyFiniteCell(dv);
    PairMeshBuilder builder(dv, samples, nullptr);
    PairMesh repaired = builder.build(inner);
    std::vector<std::uint8_t> flags;
    repairFlippedElements(repaired, dv, {}, nullptr, &flags);
    ASSERT_GT(repaired.counts.splitEdges, 0u);
    EXPECT_EQ(mismatches(repaired, flags), 0u);
    // A repair given current flags (of the knife as built: many elements
    // to repair) ends as one that tests every element.
    const PairMesh built = builder.build(inner);
    PairMesh given = built, fresh = built;
    std::vector<std::uint8_t> givenFlags = flagsOf(built);
    ASSERT_GT(std::count(givenFlags.begin(), givenFlags.end(), 1), 10);
    RepairOptions quiet, quietGiven;
    quiet.weldCloseNodes = quiet.countInvertedBefore = false;
    quietGiven = quiet;
    quietGiven.flagsAreCurrent = true;
    std::size_t needingGiven = 0, needingFresh = 0;
    EXPECT_EQ(repairFlippedElements(given, dv, quietGiven, &needingGiven, &givenFlags),
              repairFlippedElements(fresh, dv, quiet, &needingFresh));
    EXPECT_EQ(needingGiven, needingFresh);
    EXPECT_GT(given.counts.splitEdges, 0u);
    EXPECT_TRUE(given.tets == fresh.tets);
    EXPECT_TRUE(given.nodes == fresh.nodes);
    EXPECT_EQ(mismatches(given, givenFlags), 0u);
    // Current flags of the wrong size are refused, not read.
    std::vector<std::uint8_t> short_(built.size() - 1, 0);
    PairMesh refused = built;
    EXPECT_THROW(repairFlippedElements(refused, dv, quietGiven, nullptr, &short_), std::invalid_argument);
    std::size_t relabelled = 0;
    for (Index c = 0; c < dv.cellCount(); c += 7) {
      if (!inner[c]) continue;
      std::vector<std::uint8_t> after = inner;
      after[c] = 0;
      PairMesh m = repaired;
      std::vector<std::uint8_t> mFlags = flags;
      if (!builder.relabel(m, after, {c}, &mFlags)) continue;
      EXPECT_EQ(mismatches(m, mFlags), 0u) << c;
      ++relabelled;
    }
    EXPECT_GT(relabelled, 10u);
  }
  std::size_t flaggedKept = 0;
  for (const SampleSet& samples : {knife(0.3), gridBoxSamples(5, 0.2)}) {
    const DelaunayVoronoi dv(samples.points);
    const std::vector<std::uint8_t> full = everyFiniteCell(dv);
    PairMeshBuilder builder(dv, samples, nullptr);
    for (Index stride : {3u, 7u, 50u}) {
      std::vector<Index> cells;
      std::vector<std::uint8_t> after = full;
      for (Index c = 0; c < dv.cellCount(); c += stride)
        if (full[c]) cells.push_back(c), after[c] = 0;
      PairMesh m = builder.build(full);
      std::vector<std::uint8_t> flags = flagsOf(m);
      ASSERT_TRUE(builder.relabel(m, after, cells, &flags));
      EXPECT_EQ(mismatches(m, flags), 0u) << stride;
      flaggedKept += std::count(flags.begin(), flags.end(), 1);
    }
  }
  EXPECT_GT(flaggedKept, 100u);
}

namespace {

// The cusp of the lever (bm2_ec_lever-A), made exact: the box
// [-1, 1] × [0, 1] × [0, 0.6] minus the cylinder x² + (z - 0.4)² < 0.4²
// (axis along y), which touches the bottom face along x = 0. On both sides
// of that line the material is a knife thinner than any spacing.
constexpr double kCuspRadius = 0.4, kCuspTop = 0.6;

bool insideCuspBlock(const Vec3& p) {
  if (p[0] <= -1 || p[0] >= 1 || p[1] <= 0 || p[1] >= 1 || p[2] <= 0 || p[2] >= kCuspTop) return false;
  return p[0] * p[0] + (p[2] - kCuspRadius) * (p[2] - kCuspRadius) > kCuspRadius * kCuspRadius;
}

// The exact labels: a cell is inner when its circumcenter is in the block.
std::vector<std::uint8_t> cuspBlockLabels(const DelaunayVoronoi& dv) {
  std::vector<std::uint8_t> inner(dv.cellCount(), 0);
  for (Index c = 0; c < dv.cellCount(); ++c)
    inner[c] = !dv.isInfinite(c) && insideCuspBlock(dv.circumcenter(c)) ? 1 : 0;
  return inner;
}

double cuspBlockVolume() {
  const double r = kCuspRadius, d = kCuspTop - kCuspRadius;  // chord at z = top, d above the axis
  const double capAbove = r * r * std::acos(d / r) - d * std::sqrt(r * r - d * d);
  return 2 * 1 * kCuspTop - (M_PI * r * r - capAbove);
}

// Samples at spacing h: grids on the faces and on the cylinder (by angle),
// the inner grid points of the bottom face and of the cylinder moved by up
// to ±jitter × h along the surface (a hash of the seed and the point's
// index: the same on every platform).
SampleSet cuspBlock(double h, unsigned seed, double jitter = 0.3) {
  SampleSet s;
  s.spacing = h;
  std::uint64_t state = seed * 0x9E3779B97F4A7C15ull + 1;
  auto shift = [&]() {
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;  // xorshift64
    return jitter * h * (2.0 * static_cast<double>(state >> 11) / 9007199254740992.0 - 1);
  };
  const double r = kCuspRadius, top = kCuspTop;
  auto outsideCylinder = [&](double x, double z) { return x * x + (z - r) * (z - r) >= r * r; };
  const int nx = static_cast<int>(std::ceil(2 / h)), ny = static_cast<int>(std::ceil(1 / h)),
            nz = static_cast<int>(std::ceil(top / h));
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j <= ny; ++j) {
      const double x = -1 + 2.0 * i / nx, y = 1.0 * j / ny;
      const bool rim = i == 0 || i == nx || j == 0 || j == ny;
      const double xb = rim ? x : x + shift(), yb = rim ? y : y + shift();
      if (outsideCylinder(xb, 0)) s.points.push_back({xb, yb, 0});
      if (outsideCylinder(x, top)) s.points.push_back({x, y, top});
    }
  for (int i = 0; i <= nx; ++i)
    for (int k = 1; k < nz; ++k) {
      const double x = -1 + 2.0 * i / nx, z = top * k / nz;
      if (!outsideCylinder(x, z)) continue;
      s.points.push_back({x, 0, z});
      s.points.push_back({x, 1, z});
    }
  for (int j = 0; j <= ny; ++j)
    for (int k = 1; k < nz; ++k) {
      const double y = 1.0 * j / ny, z = top * k / nz;
      s.points.push_back({-1, y, z});
      s.points.push_back({1, y, z});
    }
  const double thetaMax = M_PI - std::acos((top - r) / r);  // angle from the touching line up to z = top
  const int na = static_cast<int>(std::ceil(2 * thetaMax * r / h));
  for (int a = 1; a < na; ++a) {
    const double theta = -thetaMax + 2 * thetaMax * a / na;
    if (std::abs(theta) < 1e-12) continue;  // the touching line: on the bottom grid already
    for (int j = 0; j <= ny; ++j) {
      const bool rim = j == 0 || j == ny;
      const double t = rim ? theta : theta + shift() / r, y = rim ? 1.0 * j / ny : 1.0 * j / ny + shift();
      s.points.push_back({r * std::sin(t), y, r - r * std::cos(t)});
    }
  }
  return s;
}

}  // namespace

// The accepted last resort: in the cusp the repair alone leaves elements
// inverted for some samplings; relabelling the boundary cells around them
// leaves none, and the mesh stays a valid partition of a volume within 1 %
// of the exact solid's. Over all samplings the relabelling must have been
// used (by eight of the twelve, measured 2026-12-01) and every
// mesh must end valid.
TEST(PairMeshRepairSteps, RelabellingInTheCuspLeavesNothingInverted) {
  std::size_t helped = 0;
  for (double h : {0.07, 0.05})
    for (unsigned seed = 1; seed <= 6; ++seed) {
      const SampleSet samples = cuspBlock(h, seed);
      const DelaunayVoronoi dv(samples.points);
      const std::vector<std::uint8_t> inner = cuspBlockLabels(dv);
      PairMesh repairedOnly = buildPairMesh(dv, samples, inner, nullptr, false);
      const std::size_t leftByRepair = repairFlippedElements(repairedOnly, dv);
      const PairMesh m = buildPairMesh(dv, samples, inner);
      const PairMeshValidity v = checkPairMesh(m);
      EXPECT_EQ(m.counts.invertedAfterRepair, 0u) << h << " " << seed;
      EXPECT_TRUE(v.valid()) << h << " " << seed;
      EXPECT_NEAR(v.enclosedVolume, cuspBlockVolume(), 0.01 * cuspBlockVolume()) << h << " " << seed;
      if (leftByRepair > 0) {
        EXPECT_GT(m.counts.relabelledBoundaryCells, 0u) << h << " " << seed;
        ++helped;
      } else {
        EXPECT_EQ(m.counts.relabelledBoundaryCells, 0u) << h << " " << seed;
      }
    }
  EXPECT_GT(helped, 0u);
}

// Every sampling of the cusp block over 4 spacings × 2 jitters × 12 seeds
// that the repair alone leaves with inverted elements (38 of 96) ends valid,
// with none inverted and the volume kept within 1e-3. Two of them (h = 0.12
// seed 2, h = 0.08 seed 12, jitter 0.45) needed outer cells going inner
// until 2026-12-02; element-by-element trials going outer now suffice
// (the going-inner path is exercised by NIST CTC-01 in the CLI tests).
TEST(PairMeshRepairSteps, EveryCuspSamplingEndsValid) {
  std::size_t repaired = 0;
  for (double jitter : {0.3, 0.45})
    for (double h : {0.06, 0.08, 0.1, 0.12})
      for (unsigned seed = 1; seed <= 12; ++seed) {
        SCOPED_TRACE(::testing::Message() << "jitter " << jitter << " h " << h << " seed " << seed);
        const SampleSet samples = cuspBlock(h, seed, jitter);
        const DelaunayVoronoi dv(samples.points);
        const std::vector<std::uint8_t> inner = cuspBlockLabels(dv);
        PairMesh repairedOnly = buildPairMesh(dv, samples, inner, nullptr, false);
        std::size_t needing = 0;
        const std::size_t left = repairFlippedElements(repairedOnly, dv, {}, &needing);
        // The repair counts from the flags it keeps as nodes move and edges
        // split, not by testing every element again: the counts must be
        // the mesh's (the relabelling trials decide on them).
        EXPECT_EQ(needing, countElementsNeedingRepair(repairedOnly.nodes, repairedOnly.tets));
        EXPECT_EQ(left, inverted(repairedOnly));
        if (left == 0) continue;
        ++repaired;
        const PairMesh m = buildPairMesh(dv, samples, inner);
        EXPECT_EQ(m.counts.invertedAfterRepair, 0u);
        EXPECT_GT(m.counts.relabelledBoundaryCells, 0u);
        const PairMeshValidity v = checkPairMesh(m);
        EXPECT_TRUE(v.valid());
        const double before = checkPairMesh(repairedOnly).enclosedVolume;
        EXPECT_NEAR(v.enclosedVolume, before, 1e-3 * before);
      }
  EXPECT_GE(repaired, 30u);  // the sweep still reaches the last resort
}

// Hostile labels: the all-inner knife with every fifth cell outer (holes
// everywhere, nodes of nearly flat cells 1e16 away). The exact LP over such
// coordinates ran for minutes per node; the repair must finish (0.25 s
// measured; the bound is 240 times that, not a benchmark) and leave a
// consistent mesh.
TEST(PairMeshRepairSteps, RepairFinishesOnHostileLabels) {
  const SampleSet samples = knife(0.3);
  const DelaunayVoronoi dv(samples.points);
  std::vector<std::uint8_t> holed(dv.cellCount(), 0);
  for (Index c = 0; c < dv.cellCount(); ++c) holed[c] = !dv.isInfinite(c) && c % 5 != 0 ? 1 : 0;
  const auto start = std::chrono::steady_clock::now();
  const PairMesh m = buildPairMesh(dv, samples, holed);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 60.0);
  const PairMeshValidity v = checkPairMesh(m);
  EXPECT_EQ(v.boundaryEdgesNotShared, 0u);
  EXPECT_TRUE(volumesAddUpExactly(m));
}

// The repair takes its count of inverted elements before repair from the
// pass that flags the elements needing it, and the weld of close Voronoi
// nodes then keeps those flags current itself (read before a cluster's
// move, written by the pass that accepts it), instead of every element
// being tested again. The repair must end exactly as when the flags are
// computed afresh after the weld (the count switched off), and the count
// must be that of the mesh as built. On these ellipsoid clouds the weld
// changes whether some elements need repair; with the changed elements'
// flags left as they were before the weld, the meshes differ (seed 3 at
// 4000 points, 2026-12-07). This is the test of the weld's kept flags.
// Both sides run the same node moves, so this does not check those against
// the code before; byte-identical outputs on the bundled and public parts
// did.
TEST(PairMeshRepairSteps, CountBeforeRepairLeavesTheRepairAsItWas) {
  const Vec3 axes{1.0, 0.7, 0.45};
  auto inside = [&](const Vec3& p) {
    return p[0] * p[0] / (axes[0] * axes[0]) + p[1] * p[1] / (axes[1] * axes[1]) + p[2] * p[2] / (axes[2] * axes[2]) < 1;
  };
  std::size_t welded = 0;
  for (std::size_t count : {4000, 8000})
    for (unsigned seed = 1; seed <= 3; ++seed) {
      SCOPED_TRACE(::testing::Message() << count << " points, seed " << seed);
      const SampleSet samples = cadmedial::testing::ellipsoidCloud(axes, count, seed);
      const DelaunayVoronoi dv(samples.points);
      std::vector<std::uint8_t> inner(dv.cellCount(), 0);
      for (Index k = 0; k < dv.cellCount(); ++k)
        if (!dv.isInfinite(k)) inner[k] = inside(dv.circumcenter(k)) ? 1 : 0;
      PairMesh counted = buildPairMesh(dv, samples, inner, nullptr, false);
      PairMesh fresh = counted;
      const std::size_t invertedAsBuilt = inverted(counted);
      RepairOptions withoutCount;
      withoutCount.countInvertedBefore = false;
      std::size_t needingCounted = 0, needingFresh = 0;
      const std::size_t leftCounted = repairFlippedElements(counted, dv, {}, &needingCounted);
      const std::size_t leftFresh = repairFlippedElements(fresh, dv, withoutCount, &needingFresh);
      EXPECT_EQ(leftCounted, leftFresh);
      EXPECT_EQ(needingCounted, needingFresh);
      EXPECT_EQ(counted.counts.invertedBeforeRepair, invertedAsBuilt);
      EXPECT_EQ(counted.counts.weldedNodes, fresh.counts.weldedNodes);
      EXPECT_TRUE(counted.tets == fresh.tets);
      EXPECT_TRUE(counted.nodes == fresh.nodes);
      welded += counted.counts.weldedNodes;
    }
  EXPECT_GT(welded, 0u);
}
