#include <gtest/gtest.h>

#include <cmath>

#include "cadmedial/facet_selection.hpp"
#include "cadmedial/forced_triangles.hpp"

using namespace cadmedial;

namespace {

// Sample 0 at the origin with a flat umbrella in the plane z = 0 (two
// triangles with circumradius 1/sqrt(2)·0.1).
SampleSet flatUmbrella() {
  SampleSet s;
  s.points = {{0, 0, 0}, {0.1, 0, 0}, {0, 0.1, 0}, {-0.1, 0, 0}};
  s.kind.assign(4, SampleKind::Face);
  s.owner.assign(4, 0);
  s.onConvexEdge.assign(4, 0);
  s.isNonConcaveCorner.assign(4, 0);
  s.triangles = {{0, 1, 2}, {0, 2, 3}};
  s.triangleFace = {0, 0};
  s.buildUmbrellas();
  return s;
}

// Sample 0 at the origin inside a concave edge along y: face A is the plane
// z = 0 over x >= 0, face B the plane x = 0 over z >= 0, and the solid is
// everything but the quadrant x > 0, z > 0 (a wall standing on a floor).
// Samples 1, 2 are the edge's neighbours; 3-5 on A, 6-8 on B.
SampleSet concaveEdgeUmbrella() {
  SampleSet s;
  s.points = {{0, 0, 0},      {0, -0.1, 0},     {0, 0.1, 0},      {0.07, -0.07, 0}, {0.1, 0, 0},
              {0.07, 0.07, 0}, {0, -0.07, 0.07}, {0, 0, 0.1},      {0, 0.07, 0.07}};
  s.kind = {SampleKind::Edge, SampleKind::Edge, SampleKind::Edge, SampleKind::Face, SampleKind::Face,
            SampleKind::Face, SampleKind::Face, SampleKind::Face, SampleKind::Face};
  s.owner = {0, 0, 0, 0, 0, 0, 1, 1, 1};
  s.onConvexEdge.assign(9, 0);
  s.isNonConcaveCorner.assign(9, 0);
  EdgeInfo edge;
  edge.kind = EdgeKind::Concave;
  edge.faceLeft = 0;
  edge.faceRight = 1;
  edge.samples = {1, 0, 2};
  s.edges = {edge};
  s.triangles = {{0, 1, 3}, {0, 3, 4}, {0, 4, 5}, {0, 5, 2}, {0, 6, 1}, {0, 7, 6}, {0, 8, 7}, {0, 2, 8}};
  s.triangleFace = {0, 0, 0, 0, 1, 1, 1, 1};
  s.buildUmbrellas();
  return s;
}

}  // namespace

TEST(Selection, ConcaveEdgeSamplesJudgeOnlyTheFacesAnEdgeHeadsOver) {
  UmbrellaData oneSided = computeUmbrellaData(concaveEdgeUmbrella());
  ASSERT_EQ(oneSided.sideStart.size(), 9u);
  EXPECT_NE(oneSided.sideStart[0], kNoIndex);
  EXPECT_EQ(oneSided.sideStart[3], kNoIndex);
  UmbrellaData seed = oneSided;
  seed.sideStart.clear();  // seed 002: every normal judges every edge
  const double sin5 = std::sin(5 * M_PI / 180);
  const double len = 0.2;  // the Ratio condition fails: 0.2 < 8 · 0.05
  auto test = [&](const UmbrellaData& u, std::array<double, 3> d) {
    const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (double& c : d) c *= len / n;
    return satisfiesAngleOrRatio(u, 0, d.data(), len, sin5, 8);
  };
  // Chords into the solid that run flat against a face they leave behind
  // (across a boss's foot): selected only with one-sided umbrellas.
  for (const auto& d : std::vector<std::array<double, 3>>{{-1, 0, 0}, {0, 0, -1}, {-0.5, 0.87, 0}}) {
    EXPECT_TRUE(test(oneSided, d)) << d[0] << " " << d[1] << " " << d[2];
    EXPECT_FALSE(test(seed, d)) << d[0] << " " << d[1] << " " << d[2];
  }
  // Steep to both faces: selected either way.
  EXPECT_TRUE(test(oneSided, {-1, 0, -1}));
  EXPECT_TRUE(test(seed, {-1, 0, -1}));
  // Surface edges stay rejected: over face A, over face B, along the edge,
  // and along the edge tilted 3° out of A's half-plane (the widened wedge).
  for (const auto& d : std::vector<std::array<double, 3>>{
           {1, 0.3, 0}, {0, -0.3, 1}, {0, 1, 0}, {0, -1, 0}, {-0.05, 1, 0}, {0, 1, -0.05}, {-0.05, 1, -0.05}}) {
    EXPECT_FALSE(test(oneSided, d)) << d[0] << " " << d[1] << " " << d[2];
    EXPECT_FALSE(test(seed, d)) << d[0] << " " << d[1] << " " << d[2];
  }
}

TEST(Selection, AngleConditionThreshold) {
  const UmbrellaData u = computeUmbrellaData(flatUmbrella());
  const double sin5 = std::sin(5 * M_PI / 180);
  // Direction making angle a with the plane z = 0 (acute angle to the normal = 90° - a).
  auto dirAt = [](double deg, double len) {
    const double a = deg * M_PI / 180;
    return std::array<double, 3>{len * std::cos(a), 0, len * std::sin(a)};
  };
  for (double len : {0.05, 0.2}) {  // short: ratio fails (0.2 < 8 · 0.0707)
    auto d = dirAt(6, len);
    EXPECT_TRUE(satisfiesAngleOrRatio(u, 0, d.data(), len, sin5, 8)) << len;
    d = dirAt(4, len);
    EXPECT_FALSE(satisfiesAngleOrRatio(u, 0, d.data(), len, sin5, 8)) << len;
    d = dirAt(-30, len);  // orientation of the normal does not matter
    EXPECT_TRUE(satisfiesAngleOrRatio(u, 0, d.data(), len, sin5, 8)) << len;
  }
}

TEST(Selection, RatioConditionThreshold) {
  const UmbrellaData u = computeUmbrellaData(flatUmbrella());
  const double R = 0.1 / std::sqrt(2.0);
  EXPECT_NEAR(u.maxCircumradius[0], R, 1e-12);
  const double sin5 = std::sin(5 * M_PI / 180);
  double along[3] = {1, 0, 0};  // in the tangent plane: angle fails
  double len = 8 * R * 1.01;
  along[0] = len;
  EXPECT_TRUE(satisfiesAngleOrRatio(u, 0, along, len, sin5, 8));
  len = 8 * R * 0.99;
  along[0] = len;
  EXPECT_FALSE(satisfiesAngleOrRatio(u, 0, along, len, sin5, 8));
}

TEST(Selection, EmptyOrDegenerateUmbrellaSatisfiesNothing) {
  SampleSet s = flatUmbrella();
  s.points.push_back({0.2, 0, 0});  // sample 4: only a zero-area triangle
  s.kind.push_back(SampleKind::Face);
  s.owner.push_back(0);
  s.onConvexEdge.push_back(0);
  s.isNonConcaveCorner.push_back(0);
  s.triangles.push_back({4, 1, 3});  // collinear
  s.triangleFace.push_back(0);
  s.buildUmbrellas();
  const UmbrellaData u = computeUmbrellaData(s);
  EXPECT_EQ(u.degenerateTriangles, 1u);
  EXPECT_EQ(u.samplesWithoutUmbrella, 1u);
  double up[3] = {0, 0, 100};
  EXPECT_FALSE(satisfiesAngleOrRatio(u, 4, up, 100, 0.1, 8));
  EXPECT_TRUE(satisfiesAngleOrRatio(u, 0, up, 100, 0.1, 8));
}

TEST(Selection, TrianglesOffTheSurfaceLeaveTheUmbrella) {
  // A triangle standing on edge over the flat umbrella (normal along x, as
  // at a pole of a degenerate edge) vetoes an edge straight up at sample 0
  // only if the umbrella keeps it: |n·up| = 0 for it.
  SampleSet s = flatUmbrella();
  s.points.push_back({0, 0, 0.05});  // sample 4
  s.kind.push_back(SampleKind::Face);
  s.owner.push_back(0);
  s.onConvexEdge.push_back(0);
  s.isNonConcaveCorner.push_back(0);
  s.triangles.push_back({0, 2, 4});  // in the plane x = 0
  s.triangleFace.push_back(0);
  s.buildUmbrellas();
  const double up[3] = {0, 0, 0.5};
  EXPECT_FALSE(satisfiesAngleOrRatio(computeUmbrellaData(s), 0, up, 0.5, std::sin(5 * M_PI / 180), 8));

  s.triangleOffSurface = {0, 0, 1};
  s.validate();
  const UmbrellaData u = computeUmbrellaData(s);
  EXPECT_EQ(u.offsets[1] - u.offsets[0], 2u);  // the two flat triangles
  EXPECT_TRUE(satisfiesAngleOrRatio(u, 0, up, 0.5, std::sin(5 * M_PI / 180), 8));

  s.triangleOffSurface = {0, 1};  // one flag per triangle or none
  EXPECT_THROW(s.validate(), std::exception);
}

TEST(Selection, CornerRule) {
  // Build a tiny SelectedFacets by hand: only {1,2} selected.
  SelectedFacets f;
  f.lookup.reserve(4);
  f.lookup.insert(1, 2, 0);
  EXPECT_EQ(cornerRuleFacet(f, 0, 1, 2), 0u);
  EXPECT_EQ(cornerRuleFacet(f, 0, 2, 1), 0u);
  f.lookup.insert(0, 2, 1);
  EXPECT_EQ(cornerRuleFacet(f, 0, 1, 2), kNoIndex);  // a facet of V_0 on that edge is selected
  EXPECT_EQ(cornerRuleFacet(f, 3, 0, 1), kNoIndex);  // qr not selected
}
