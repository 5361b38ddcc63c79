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

}  // namespace

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
