// CAD_MEDIAL on a sampled box against the exact medial axis: the points where
// the two nearest face planes tie, radius = distance to the nearest plane.
#include <gtest/gtest.h>

#include <cmath>

#include "medial_checks.hpp"
#include "synthetic_samples.hpp"

using namespace cadmedial;
using namespace cadmedial::testing;

namespace {

const Vec3 kSize{1.0, 0.8, 0.6};

class BoxAtSpacing : public ::testing::TestWithParam<double> {};

}  // namespace

TEST_P(BoxAtSpacing, MatchesExactMedialAxis) {
  const double h = GetParam();
  SamplingOptions o;
  o.spacing = h;
  const PlanarSolid box = makeBox(kSize[0], kSize[1], kSize[2]);
  const SampleSet s = samplePlanarSolid(box, o);
  const MedialResult r = computeCadMedial(s, MedialParams::cad(), box.inside);
  std::cout << "box h=" << h << ": " << summary(r) << "\n";
  const double diagonal = s.bboxDiagonal();

  // Medialness of every Voronoi vertex of the inner complex.
  const BoxMedialness m = boxMedialness(r, kSize);
  std::cout << "  |d1-d2|: median " << m.tie.median << " (" << m.tie.median / diagonal << " diag) p99 " << m.tie.p99
            << " max " << m.tie.max << " (" << m.tie.max / h << " h); |r-d1|: median " << m.radius.median << " max "
            << m.radius.max << "\n";
  ASSERT_GT(m.tie.count, 1000u);
  EXPECT_EQ(m.outside, 0u) << "inner vertices outside the box";
  EXPECT_LE(m.tie.median, 1e-3 * diagonal);
  EXPECT_LE(m.tie.max, h);
  EXPECT_LE(m.radius.median, 0.1 * h);
  EXPECT_LE(m.radius.max, 0.5 * h);

  // Completion: every convex-edge sample and every corner is on the axis.
  EXPECT_EQ(r.counts.tripletsNotDelaunay, 0u);
  EXPECT_EQ(r.counts.tripletsOnHull, 0u);
  EXPECT_EQ(r.forced.gapsWithoutFill, 0u);
  ASSERT_EQ(s.edges.size(), 12u);
  for (const EdgeInfo& e : s.edges) {
    std::vector<Index> edgeSamples(e.samples.begin() + 1, e.samples.end() - 1);
    EXPECT_EQ(attachedShare(r, edgeSamples), 1.0);
  }
  std::vector<Index> corners;
  for (const CornerInfo& c : s.vertices) corners.push_back(c.sample);
  ASSERT_EQ(corners.size(), 8u);
  EXPECT_EQ(attachedShare(r, corners), 1.0);

  // Topology of a box's medial axis: one contractible piece.
  EXPECT_EQ(r.topology.beta0, 1);
  EXPECT_EQ(r.topology.beta1, 0);
  EXPECT_EQ(r.topology.beta2, 0);

  // A box is convex: nothing reaches infinity, everything is inner, and the
  // oracle agrees on every facet.
  EXPECT_EQ(r.counts.outerFacets, 0u);
  EXPECT_EQ(r.counts.oracleChecked, r.counts.selectedFacets);
  EXPECT_EQ(r.counts.oracleDisagreements, 0u);

  // Provenance and radii are consistent.
  for (std::size_t i = 0; i < r.vertices.size(); ++i) {
    if (r.vertexSample[i] != kNoIndex) {
      EXPECT_EQ(r.radius[i], 0.0);
      EXPECT_NE(s.kind[r.vertexSample[i]], SampleKind::Face);
    } else {
      EXPECT_GT(r.radius[i], 0.0);
    }
  }
  std::size_t facets = 0;
  for (PolygonProvenance p : r.provenance) facets += p == PolygonProvenance::DelaunayEdgeFacet;
  // Inner facets all stay but the degenerate ones the weld of coincident
  // Voronoi vertices drops (the diagonals of the triplets' cocircular quads).
  EXPECT_EQ(facets + r.counts.degenerateFacetsDropped, r.counts.innerFacets);
  EXPECT_EQ(r.sheet.size(), r.polygonCount());
  for (Index id : r.sheet) EXPECT_LT(id, r.sheetCount);
}

INSTANTIATE_TEST_SUITE_P(Spacings, BoxAtSpacing, ::testing::Values(0.05, 0.025));

TEST(Box, RefinementImprovesMedialness) {
  double previous = 1e300;
  for (double h : {0.05, 0.025}) {
    SamplingOptions o;
    o.spacing = h;
    const MedialResult r = computeCadMedial(samplePlanarSolid(makeBox(kSize[0], kSize[1], kSize[2]), o));
    const double median = boxMedialness(r, kSize).tie.median;
    EXPECT_LT(median, previous);
    previous = median;
  }
}

TEST(Box, PaperFillsAloneLeaveOneLoopPerGap) {
  // Documents why procConvexEdges adds the fan at s: with only the triplet
  // triangles (and fills), the complex would not close along the edges. Here
  // the fan triangles are removed from a result and β1 jumps.
  SamplingOptions o;
  o.spacing = 0.05;
  const SampleSet s = samplePlanarSolid(makeBox(kSize[0], kSize[1], kSize[2]), o);
  DelaunayVoronoi dv(s.points);
  const UmbrellaData u = computeUmbrellaData(s);
  const SelectedFacets f = selectFacetsByAngleAndRatio(dv, u, MedialParams::cad());
  ForcedTriangles forced;
  procConvexEdges(dv, s, f, forced);
  procNonconcaveCorners(dv, s, f, forced);
  EXPECT_GT(forced.convexFanTriangles, 0u);
  // procConvexEdges appends the triplet triangles first, then the fans, then fills.
  ForcedTriangles paperOnly = forced;
  paperOnly.triangles.erase(paperOnly.triangles.begin() + forced.convexEdgeTriangles,
                            paperOnly.triangles.begin() + forced.convexEdgeTriangles + forced.convexFanTriangles);
  for (std::size_t i = 0; i < forced.convexEdgeTriangles + forced.convexFanTriangles; ++i) {
    const bool isFan = i >= forced.convexEdgeTriangles;
    const ForcedTriangle& t = forced.triangles[i];
    ASSERT_EQ(t.kind, PolygonProvenance::ConvexEdgeTriangle);
    const Triplet& tr = s.triplets[t.source];
    const Index own = f.find(dv.canonicalSample(tr.sLeft), dv.canonicalSample(tr.sRight));
    EXPECT_EQ(t.attachedFacet == own, !isFan);
  }
  auto betti1 = [&](const ForcedTriangles& ft) {
    const InnerOuterLabels labels = separateInnerOuter(dv, s, f, ft, MedialParams::cad());
    MedialComplex mc = buildInnerComplex(dv, s, f, ft, labels);
    const ComplexEdges e = buildComplexEdges(mc);
    return computeTopology(mc, e, 1000000).beta1;
  };
  EXPECT_EQ(betti1(forced), 0);
  EXPECT_GT(betti1(paperOnly), 0);
}

// Same samples, same complex, polygon for polygon: CGAL's order of the facets
// around a vertex follows memory addresses, which made the fan triangles'
// order and orientation change between runs. The second run is made after
// other allocations so that its cells land at other addresses.
TEST(BoxDeterminism, SameSamplesGiveTheSameComplexPolygonForPolygon) {
  SamplingOptions o;
  o.spacing = 0.05;
  const PlanarSolid box = makeBox(kSize[0], kSize[1], kSize[2]);
  const SampleSet s = samplePlanarSolid(box, o);
  const MedialResult first = computeCadMedial(s, MedialParams::cad(), box.inside);
  std::vector<std::vector<double>> ballast;
  for (int i = 0; i < 1000; ++i) ballast.emplace_back(37 + i % 101, 1.0);
  const MedialResult second = computeCadMedial(s, MedialParams::cad(), box.inside);
  ASSERT_GT(first.forced.convexFanTriangles, 0u);
  EXPECT_EQ(first.polygonOffsets, second.polygonOffsets);
  EXPECT_TRUE(first.polygonVertices == second.polygonVertices) << "same polygons, other vertex order";
  EXPECT_TRUE(first.vertices == second.vertices);
  EXPECT_TRUE(first.sheet == second.sheet);
}
