// thinFringe on hand-built complexes whose answer is known: fins of chords
// on one smooth surface with nested balls go, a true sheet (radius growing
// slower than distance), a facet across the solid and a loop stay.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "cadmedial/polygon_complex.hpp"

namespace cadmedial {
namespace {

// Samples 0-3 on face 0 (the plane z = 0, normal +z), 4-6 on face 1 (the
// plane z = 5, normal -z): a chord 0-1 lies on one smooth surface, 0-4
// crosses the solid. Samples 7-9 are on face 0 too but facing -z (one face
// wrapping round, like a tube's): 0-7 joins opposite contacts of one face.
SampleSet twoPlanes() {
  SampleSet s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 5}, {1, 0, 5}, {0, 1, 5},
              {0, 0, 4}, {1, 0, 4}, {0, 1, 4}};
  s.kind.assign(s.points.size(), SampleKind::Face);
  s.owner = {0, 0, 0, 0, 1, 1, 1, 0, 0, 0};
  s.triangles = {{0, 1, 2}, {1, 3, 2}, {4, 6, 5}, {7, 9, 8}};
  s.triangleFace = {0, 0, 1, 0};
  s.spacing = 1;
  return s;
}

struct ComplexBuilder {
  MedialComplex mc;
  Index vertex(const Vec3& p, double r) {
    mc.vertices.push_back(p);
    mc.radius.push_back(r);
    mc.vertexCell.push_back(static_cast<Index>(mc.vertexCell.size()));
    mc.vertexSample.push_back(kNoIndex);
    return static_cast<Index>(mc.vertices.size() - 1);
  }
  void quad(Index a, Index b, Index c, Index d, Index sampleP, Index sampleQ) {
    for (Index v : {a, b, c, d}) mc.polygonVertices.push_back(v);
    mc.polygonOffsets.push_back(static_cast<Index>(mc.polygonVertices.size()));
    mc.provenance.push_back(PolygonProvenance::DelaunayEdgeFacet);
    mc.provenanceSamples.push_back({sampleP, sampleQ});
  }
};

FringeThinningParams defaults() {
  FringeThinningParams p;
  p.cosBeta = std::cos(20 * M_PI / 180);
  p.slack = 0.03;
  p.minReach = 0.02;
  return p;
}

ComplexTopology topologyOf(const MedialComplex& mc) { return computeTopology(mc, buildComplexEdges(mc), 1000); }

// A core strip along x (facets across the solid, radius 10) with a fin two
// quads deep hanging off its edge y = 0, its radius falling by `slope` per
// unit of distance from the core.
MedialComplex coreWithFin(double slope) {
  ComplexBuilder b;
  Index core[5], top[5], fin1[5], fin2[5];
  for (int i = 0; i < 5; ++i) {
    core[i] = b.vertex({double(i), 0, 0}, 10);
    top[i] = b.vertex({double(i), 0, 1}, 10);
    fin1[i] = b.vertex({double(i), -1, 0}, 10 - slope);
    fin2[i] = b.vertex({double(i), -2, 0}, 10 - 2 * slope);
  }
  for (int i = 0; i < 4; ++i) b.quad(core[i], core[i + 1], top[i + 1], top[i], 0, 4);
  for (int i = 0; i < 4; ++i) {
    b.quad(core[i], fin1[i], fin1[i + 1], core[i + 1], 0, 1);
    b.quad(fin1[i], fin2[i], fin2[i + 1], fin1[i + 1], 0, 1);
  }
  b.mc.sheet.assign(b.mc.polygonCount(), kNoIndex);
  return b.mc;
}

TEST(FringeThinning, FinWithNestedBallsCollapsesOntoTheCore) {
  MedialComplex mc = coreWithFin(1.0);  // r_core - r_fin = distance: v's ball inside u's
  const ComplexTopology before = topologyOf(mc);
  EXPECT_EQ(thinFringe(mc, twoPlanes(), defaults()), 8u);
  ASSERT_EQ(mc.polygonCount(), 4u);
  for (std::size_t p = 0; p < 4; ++p) EXPECT_EQ(mc.provenanceSamples[p][1], 4u);  // the core's facets
  for (double r : mc.radius) EXPECT_EQ(r, 10);
  const ComplexTopology after = topologyOf(mc);
  EXPECT_EQ(after.beta0, before.beta0);
  EXPECT_EQ(after.beta1, before.beta1);
}

TEST(FringeThinning, SheetWhoseRadiusGrowsSlowerThanDistanceStays) {
  // A sheet between two faces at 90° grows r by sin 45° = 0.71 per unit.
  MedialComplex mc = coreWithFin(0.71);
  EXPECT_EQ(thinFringe(mc, twoPlanes(), defaults()), 0u);
  EXPECT_EQ(mc.polygonCount(), 12u);
}

TEST(FringeThinning, BallsNearerThanMinReachDoNotDominate) {
  // With minReach 1.5 the inner fin vertices' only dominating balls (the
  // core vertices beside them, 1 away) are too near to count, and the next
  // ones (√3 away) do not contain theirs: the outer fin row goes (its
  // vertices are 2 from the core), the inner one stays.
  MedialComplex mc = coreWithFin(1.0);
  FringeThinningParams p = defaults();
  p.minReach = 1.5;
  EXPECT_EQ(thinFringe(mc, twoPlanes(), p), 4u);
  EXPECT_EQ(mc.polygonCount(), 8u);
  for (double r : mc.radius) EXPECT_GE(r, 9);
}

TEST(FringeThinning, ChordsAcrossTheSolidAndSharpFeaturesAreNotFringe) {
  MedialComplex acrossSolid = coreWithFin(1.0);
  for (std::size_t p = 4; p < acrossSolid.polygonCount(); ++p) acrossSolid.provenanceSamples[p] = {0, 5};
  EXPECT_EQ(thinFringe(acrossSolid, twoPlanes(), defaults()), 0u);
  // Opposite sides of one face (across a tube): normals more than 90° apart.
  MedialComplex acrossTube = coreWithFin(1.0);
  for (std::size_t p = 4; p < acrossTube.polygonCount(); ++p) acrossTube.provenanceSamples[p] = {0, 7};
  EXPECT_EQ(thinFringe(acrossTube, twoPlanes(), defaults()), 0u);

  // The same fin on samples of a sharp edge between the two faces.
  SampleSet s = twoPlanes();
  s.kind[0] = s.kind[1] = SampleKind::Edge;
  s.owner[0] = s.owner[1] = 0;
  EdgeInfo edge;
  edge.kind = EdgeKind::Convex;
  edge.faceLeft = 0;
  edge.faceRight = 1;
  s.edges = {edge};
  MedialComplex onEdge = coreWithFin(1.0);
  EXPECT_EQ(thinFringe(onEdge, s, defaults()), 0u);
  // On a tangent-continuous edge the fin is fringe again.
  s.edges[0].kind = EdgeKind::Smooth;
  MedialComplex onSmoothEdge = coreWithFin(1.0);
  EXPECT_EQ(thinFringe(onSmoothEdge, s, defaults()), 8u);
}

TEST(FringeThinning, NeverOpensALoopOrCutsTheComplexApart) {
  // A ring of fringe quads two wide (radius 10 inside, 9 and 8 outwards),
  // every facet a chord of one surface: the outer ring goes, the inner one,
  // whose inner vertices no ball contains, stays and keeps the loop.
  ComplexBuilder b;
  constexpr int n = 12;
  Index ring[3][n];
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * i / n, rho = 10 + k;
      ring[k][i] = b.vertex({rho * std::cos(a), rho * std::sin(a), 0}, 10.0 - k);
    }
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < n; ++i)
      b.quad(ring[k][i], ring[k + 1][i], ring[k + 1][(i + 1) % n], ring[k][(i + 1) % n], 0, 1);
  b.mc.sheet.assign(b.mc.polygonCount(), kNoIndex);
  MedialComplex mc = b.mc;
  const ComplexTopology before = topologyOf(mc);
  ASSERT_EQ(before.beta1, 1);
  EXPECT_EQ(thinFringe(mc, twoPlanes(), defaults()), std::size_t(n));
  const ComplexTopology after = topologyOf(mc);
  EXPECT_EQ(after.beta0, 1);
  EXPECT_EQ(after.beta1, 1);
  for (double r : mc.radius) EXPECT_GE(r, 9);

  // All three rings at one radius: nothing nests, nothing goes.
  MedialComplex flat = b.mc;
  for (double& r : flat.radius) r = 10;
  EXPECT_EQ(thinFringe(flat, twoPlanes(), defaults()), 0u);

  // A huge ball at the centre (a vertex of no polygon) dominates every ring
  // vertex: now only the collapse rule keeps the loop, one ring of quads
  // whose contact with the rest is two arcs.
  MedialComplex dominatedRing = b.mc;
  dominatedRing.vertices.push_back({0, 0, 0});
  dominatedRing.radius.push_back(1000);
  dominatedRing.vertexCell.push_back(kNoIndex);
  dominatedRing.vertexSample.push_back(kNoIndex);
  const std::size_t removed = thinFringe(dominatedRing, twoPlanes(), defaults());
  EXPECT_GE(removed, std::size_t(n));
  EXPECT_LT(removed, std::size_t(2 * n));
  const ComplexTopology kept = topologyOf(dominatedRing);
  EXPECT_EQ(kept.beta0, 1);
  EXPECT_EQ(kept.beta1, 1);
}

TEST(FringeThinning, RefusesParametersOutOfRange) {
  MedialComplex mc = coreWithFin(1.0);
  FringeThinningParams p = defaults();
  p.minReach = 0;
  EXPECT_THROW(thinFringe(mc, twoPlanes(), p), std::invalid_argument);
  p = defaults();
  p.cosBeta = 0;
  EXPECT_THROW(thinFringe(mc, twoPlanes(), p), std::invalid_argument);
}

}  // namespace
}  // namespace cadmedial
