// The one-facet hole fill (core/src/facet_holes.cpp) against a brute-force
// definition: every unselected finite Delaunay edge whose whole ring of
// cells are vertices of the complex, consecutive ones joined by a Voronoi
// edge of the complex. The fill counts votes instead of walking rings, so
// this checks the counting argument on real complexes.
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "cadmedial/medial.hpp"
#include "synthetic_samples.hpp"

using namespace cadmedial;
using namespace cadmedial::testing;

namespace {

// The facets a brute-force ring walk finds in `mc`, as sorted sample pairs.
std::set<std::array<Index, 2>> holesByRingWalk(const DelaunayVoronoi& dv, const SelectedFacets& selected,
                                                 const MedialComplex& mc) {
  std::vector<bool> onComplex(dv.cellCount(), false);
  for (Index c : mc.vertexCell)
    if (c != kNoIndex) onComplex[c] = true;
  std::set<std::array<Index, 2>> voronoiEdges;
  for (std::size_t p = 0; p < mc.polygonCount(); ++p)
    for (Index k = mc.polygonOffsets[p]; k < mc.polygonOffsets[p + 1]; ++k) {
      const Index next = k + 1 < mc.polygonOffsets[p + 1] ? k + 1 : mc.polygonOffsets[p];
      const Index a = mc.vertexCell[mc.polygonVertices[k]], b = mc.vertexCell[mc.polygonVertices[next]];
      if (a != kNoIndex && b != kNoIndex) voronoiEdges.insert({std::min(a, b), std::max(a, b)});
    }
  std::set<std::array<Index, 2>> holes;
  const auto& dt = dv.triangulation();
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const Index a = e->first->vertex(e->second)->info(), b = e->first->vertex(e->third)->info();
    if (selected.find(a, b) != kNoIndex) continue;
    std::vector<Index> ring;
    auto circ = dt.incident_cells(*e);
    const auto start = circ;
    do {
      ring.push_back(DelaunayVoronoi::cellId(circ));
    } while (++circ != start);
    bool hole = ring.size() >= 3;
    for (std::size_t i = 0; i < ring.size() && hole; ++i) {
      const Index c = ring[i], d = ring[(i + 1) % ring.size()];
      hole = !dv.isInfinite(c) && onComplex[c] && voronoiEdges.count({std::min(c, d), std::max(c, d)}) > 0;
    }
    if (hole) holes.insert({std::min(a, b), std::max(a, b)});
  }
  return holes;
}

// A regular n-gon prism: a rod, where the axis is a jumble of facets around
// its centre line and one-facet holes appear.
PlanarSolid rod(int sides, double radius, double length) {
  std::vector<Vec2> outer;
  for (int i = 0; i < sides; ++i) {
    const double t = 2 * M_PI * i / sides;
    outer.push_back({radius * std::cos(t), radius * std::sin(t)});
  }
  return extrudedPolygon("rod", outer, {}, length);
}

}  // namespace

TEST(FacetHoles, FillAddsExactlyTheFacetsARingWalkFinds) {
  std::size_t holesSeen = 0;
  for (const auto& [solid, spacing] : std::vector<std::pair<PlanarSolid, double>>{
           {rod(32, 0.1, 0.3), 0.01}, {rod(32, 0.1, 0.3), 0.006}, {rod(12, 0.1, 0.5), 0.02},
           {makeLPrism(), 0.08}, {makeBoxWithSquareHole(), 0.07}}) {
    SamplingOptions o;
    o.spacing = spacing;
    const SampleSet samples = samplePlanarSolid(solid, o);
    const DelaunayVoronoi dv(samples.points);
    MedialParams noFill = MedialParams::cad();
    noFill.fillSingleFacetHoles = false;
    MedialResult r = computeCadMedial(dv, samples, noFill);
    const SelectedFacets selected = selectFacetsByAngleAndRatio(dv, computeUmbrellaData(samples), noFill);

    const auto expected = holesByRingWalk(dv, selected, r);
    const std::size_t before = r.polygonCount();
    const std::size_t added = fillSingleFacetHoles(dv, selected, r);
    ASSERT_EQ(added, expected.size()) << solid.name << " h=" << spacing;
    std::set<std::array<Index, 2>> got;
    for (std::size_t p = before; p < r.polygonCount(); ++p) {
      got.insert(r.provenanceSamples[p]);
      EXPECT_EQ(r.provenance[p], PolygonProvenance::DelaunayEdgeFacet);
      // The polygon is the facet's ring, in cyclic order: consecutive cells
      // share a triangle (which holds both samples of the edge).
      const Index b = r.polygonOffsets[p], e = r.polygonOffsets[p + 1];
      for (Index k = b; k < e; ++k) {
        const auto c = dv.cell(r.vertexCell[r.polygonVertices[k]]);
        const auto d = dv.cell(r.vertexCell[r.polygonVertices[k + 1 < e ? k + 1 : b]]);
        EXPECT_TRUE(c->has_neighbor(d)) << solid.name;
        EXPECT_TRUE(dv.cellHasSample(DelaunayVoronoi::cellId(c), r.provenanceSamples[p][0]));
        EXPECT_TRUE(dv.cellHasSample(DelaunayVoronoi::cellId(c), r.provenanceSamples[p][1]));
      }
    }
    EXPECT_EQ(got, expected) << solid.name;
    // The pipeline with the fill on adds the same number.
    EXPECT_EQ(computeCadMedial(dv, samples).counts.singleFacetHolesFilled, expected.size()) << solid.name;
    holesSeen += expected.size();
    std::cout << solid.name << " h=" << spacing << ": " << expected.size() << " one-facet holes\n";
  }
  EXPECT_GT(holesSeen, 0u) << "no model had a one-facet hole: the comparison tested nothing";
}
