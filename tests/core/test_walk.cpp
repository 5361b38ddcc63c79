// Inner/outer walk on non-convex solids, checked against the exact inside test.
#include <gtest/gtest.h>

#include "medial_checks.hpp"
#include "synthetic_samples.hpp"

using namespace cadmedial;
using namespace cadmedial::testing;

namespace {

MedialResult run(const PlanarSolid& solid, double h, WalkBlocking blocking = WalkBlocking::None,
                 bool relabelOutsideFacets = true) {
  SamplingOptions o;
  o.spacing = h;
  MedialParams p;
  p.walkBlocking = blocking;
  p.innerNeedsInsideVertices = relabelOutsideFacets;
  return computeCadMedial(samplePlanarSolid(solid, o), p, solid.inside);
}

double innerVerticesInside(const MedialResult& r, const PlanarSolid& solid) {
  std::size_t in = 0, total = 0;
  for (std::size_t i = 0; i < r.vertices.size(); ++i) {
    if (r.vertexCell[i] == kNoIndex) continue;
    ++total;
    in += solid.inside(r.vertices[i]);
  }
  return total ? double(in) / total : 0.0;
}

}  // namespace

TEST(Walk, LPrismSeparatesInnerFromOuter) {
  const PlanarSolid solid = makeLPrism();
  const MedialResult r = run(solid, 0.05);
  std::cout << summary(r) << "\n";
  EXPECT_GT(r.counts.unboundedFacets, 0u);
  EXPECT_GT(r.counts.outerFacets, 0u);
  EXPECT_GT(r.counts.oracleChecked, 10000u);
  EXPECT_LE(r.counts.oracleDisagreements, 0.001 * r.counts.oracleChecked);
  EXPECT_LE(r.counts.oracleForcedDisagreements, 0.01 * r.counts.oracleForcedChecked);
  EXPECT_GE(innerVerticesInside(r, solid), 0.999);
  EXPECT_EQ(r.topology.beta0, 1);
  EXPECT_EQ(r.topology.beta1, 0);
  EXPECT_GT(r.labels.outerCornerTriangles, 0u) << "the outer axis of the notch reaches its corners";
}

TEST(Walk, HoledBoxSeparatesInnerFromOuterAndHasGenusOne) {
  const PlanarSolid solid = makeBoxWithSquareHole();
  const MedialResult r = run(solid, 0.05);
  std::cout << summary(r) << "\n";
  EXPECT_GT(r.counts.outerFacets, 0u);
  EXPECT_LE(r.counts.oracleDisagreements, 0.001 * r.counts.oracleChecked);
  EXPECT_LE(r.counts.oracleForcedDisagreements, 0.01 * r.counts.oracleForcedChecked);
  EXPECT_GE(innerVerticesInside(r, solid), 0.999);
  EXPECT_EQ(r.topology.beta0, 1);
  EXPECT_EQ(r.topology.beta1, 1);
  EXPECT_EQ(r.topology.beta2, 0);
}

TEST(Walk, BlockingAtFeatureSamplesOnlyLosesOuterFacets) {
  // The measurement behind the default WalkBlocking::None (inner_outer.hpp),
  // on the bare walk (no relabelling of unreached facets).
  for (const PlanarSolid& solid : {makeLPrism(), makeBoxWithSquareHole()}) {
    const MedialResult none = run(solid, 0.05, WalkBlocking::None, false);
    const MedialResult corners = run(solid, 0.05, WalkBlocking::NonConcaveCorners, false);
    const MedialResult edges = run(solid, 0.05, WalkBlocking::CornersAndConvexEdges, false);
    std::cout << solid.name << " oracle disagreements: none " << none.counts.oracleDisagreements << ", corners "
              << corners.counts.oracleDisagreements << " (blocked " << corners.counts.walkBlockedCrossings
              << "), corners+convex edges " << edges.counts.oracleDisagreements << " (blocked "
              << edges.counts.walkBlockedCrossings << ") of " << none.counts.oracleChecked << "\n";
    EXPECT_LE(none.counts.oracleDisagreements, corners.counts.oracleDisagreements);
    EXPECT_LT(none.counts.oracleDisagreements, edges.counts.oracleDisagreements);
    EXPECT_GE(none.counts.outerFacets, corners.counts.outerFacets);
    EXPECT_GT(edges.counts.oracleDisagreements, 0.01 * edges.counts.oracleChecked);
  }
}

TEST(Walk, UnreachedFacetsOutsideTheSurfaceBecomeOuter) {
  // The outer islands that blocking at every feature sample cuts off from the
  // unbounded facets are found again by their Voronoi vertices outside the
  // sampled surface (innerNeedsInsideVertices, the default).
  for (const PlanarSolid& solid : {makeLPrism(), makeBoxWithSquareHole()}) {
    const MedialResult edges = run(solid, 0.05, WalkBlocking::CornersAndConvexEdges, true);
    std::cout << solid.name << ": " << edges.labels.innerFacetsOutsideSurface << " unreached facets relabelled outer, "
              << edges.counts.oracleDisagreements << " oracle disagreements of " << edges.counts.oracleChecked << "\n";
    EXPECT_GT(edges.labels.innerFacetsOutsideSurface, 0.01 * edges.counts.oracleChecked);
    EXPECT_LE(edges.counts.oracleDisagreements, 0.001 * edges.counts.oracleChecked);
    EXPECT_GE(innerVerticesInside(edges, solid), 0.999);
  }
}
