// Degenerate inputs: regular grids, exact duplicates, cospherical and
// coplanar clusters, too few points. No crash, sane results.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "medial_checks.hpp"
#include "synthetic_samples.hpp"

using namespace cadmedial;
using namespace cadmedial::testing;

namespace {

void expectWellFormed(const MedialResult& r, std::size_t samples) {
  ASSERT_EQ(r.radius.size(), r.vertices.size());
  ASSERT_EQ(r.polygonOffsets.size(), r.polygonCount() + 1);
  ASSERT_EQ(r.provenanceSamples.size(), r.polygonCount());
  ASSERT_EQ(r.sheet.size(), r.polygonCount());
  for (Index v : r.polygonVertices) ASSERT_LT(v, r.vertices.size());
  for (std::size_t p = 0; p < r.polygonCount(); ++p) EXPECT_GE(r.polygonSize(p), 3u);
  for (std::size_t i = 0; i < r.vertices.size(); ++i) {
    for (double c : r.vertices[i]) EXPECT_TRUE(std::isfinite(c));
    EXPECT_TRUE(std::isfinite(r.radius[i]));
    EXPECT_GE(r.radius[i], 0.0);
    if (r.vertexSample[i] != kNoIndex) {
      EXPECT_LT(r.vertexSample[i], samples);
    }
  }
}

}  // namespace

TEST(Degenerate, RegularGridBox) {
  const SampleSet s = gridBoxSamples(20, 0.05);
  const MedialResult r = computeCadMedial(s, MedialParams::cad(), [](const Vec3& p) {
    return p[0] > 0 && p[1] > 0 && p[2] > 0 && p[0] < 1 && p[1] < 1 && p[2] < 1;
  });
  std::cout << summary(r) << "\n";
  expectWellFormed(r, s.size());
  const BoxMedialness m = boxMedialness(r, {1, 1, 1});
  EXPECT_EQ(m.outside, 0u);
  EXPECT_LE(m.tie.max, 1e-9);  // grid cells are exactly symmetric
  EXPECT_EQ(r.counts.tripletsNotDelaunay, 0u);
  EXPECT_EQ(r.topology.beta0, 1);
  EXPECT_EQ(r.topology.beta1, 0);
  EXPECT_EQ(r.counts.oracleDisagreements, 0u);
}

TEST(Degenerate, ExactDuplicatesChangeNothing) {
  SamplingOptions o;
  o.spacing = 0.05;
  SampleSet s = samplePlanarSolid(makeBox(1, 0.8, 0.6), o);
  const MedialResult clean = computeCadMedial(s);
  const std::size_t n = s.size();
  for (std::size_t i = 0; i < n; i += 7) {  // every 7th sample again, umbrella-less
    s.points.push_back(s.points[i]);
    s.kind.push_back(s.kind[i]);
    s.owner.push_back(s.owner[i]);
    s.onConvexEdge.push_back(s.onConvexEdge[i]);
    s.isNonConcaveCorner.push_back(s.isNonConcaveCorner[i]);
  }
  s.buildUmbrellas();
  const MedialResult r = computeCadMedial(s);
  expectWellFormed(r, s.size());
  EXPECT_EQ(r.counts.duplicateSamples, s.size() - n);
  EXPECT_EQ(r.counts.selectedFacets, clean.counts.selectedFacets);
  EXPECT_EQ(r.polygonCount(), clean.polygonCount());
  EXPECT_EQ(r.topology.beta0, clean.topology.beta0);
  EXPECT_EQ(r.topology.beta1, clean.topology.beta1);
}

TEST(Degenerate, CosphericalAndCoplanarClusters) {
  // Integer points on the sphere of radius 5 (exactly cospherical), a flat
  // 8x8 grid patch (coplanar, cocircular), and a few random points; hull
  // umbrellas only (interior points have none).
  SampleSet s;
  for (int x = -5; x <= 5; ++x)
    for (int y = -5; y <= 5; ++y)
      for (int z = -5; z <= 5; ++z)
        if (x * x + y * y + z * z == 25) s.points.push_back({double(x), double(y), double(z)});
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) s.points.push_back({-1.75 + 0.5 * i, -1.75 + 0.5 * j, 0.0});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int i = 0; i < 50; ++i) s.points.push_back({u(rng), u(rng), u(rng)});
  finishPointCloud(s);
  hullUmbrellas(s);
  const MedialResult r = computeCadMedial(s, MedialParams::pointCloud());
  std::cout << summary(r) << "\n";
  expectWellFormed(r, s.size());
  EXPECT_GT(r.counts.delaunayCells, 0u);
}

TEST(Degenerate, TooFewOrFlatPointsGiveAnEmptyResult) {
  for (std::size_t n : {0u, 1u, 3u}) {
    SampleSet s;
    for (std::size_t i = 0; i < n; ++i) s.points.push_back({double(i), 0.5 * i * i, 0});
    finishPointCloud(s);
    s.buildUmbrellas();
    const MedialResult r = computeCadMedial(s);
    EXPECT_EQ(r.polygonCount(), 0u);
    EXPECT_EQ(r.vertices.size(), 0u);
  }
  SampleSet flat;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) flat.points.push_back({double(i), double(j), 0});
  finishPointCloud(flat);
  flat.buildUmbrellas();
  const MedialResult r = computeCadMedial(flat);
  EXPECT_EQ(r.polygonCount(), 0u);
}

TEST(Degenerate, InvalidSampleSetThrows) {
  SampleSet s = ellipsoidCloud({1, 1, 1}, 100, 1);
  s.kind.pop_back();
  EXPECT_THROW(computeCadMedial(s), std::runtime_error);
  MedialParams p;
  p.thetaDeg = 95;
  EXPECT_THROW(computeCadMedial(ellipsoidCloud({1, 1, 1}, 100, 1), p), std::invalid_argument);
}
