// MEDIAL (seed 000) on points alone: sphere, ellipsoid and torus at three
// densities, without and with 0.1 % noise, one θ = π/8 and ρ = 8 for all,
// measured against the exact shapes (analytic_shapes.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analytic_shapes.hpp"
#include "cadmedial/compute_medial.hpp"
#include "cadmedial/medial_poles.hpp"
#include "cadmedial/medial_umbrellas.hpp"

using namespace cadmedial;
using namespace cadmedial::testing;

namespace {

struct CloudRun {
  std::size_t points = 0;
  double noise = 0;
  PointMedialResult result;
  AnalyticMeasure m;
};

CloudRun runOn(const AnalyticShape& shape, std::size_t count, double noise, unsigned seed = 3) {
  CloudRun run;
  const std::vector<Vec3> pts = sampleSurface(shape, count, seed, noise);
  run.points = pts.size();
  run.noise = noise;
  run.result = computeMedial(pts, MedialParams::pointCloud());
  run.m = measureAgainstShape(run.result, shape, true);
  const AnalyticMeasure& m = run.m;
  std::printf("%-9s n=%6zu noise=%.3f%% poly=%7zu vert=%7zu | |d-r| med %.5f p90 %.5f | axis med %.5f p90 %.5f "
              "p99 %.4f max %.4f far %.4f | cover %.4f inside %.3f | b0 %lld t %.2fs\n",
              shape.name().c_str(), run.points, noise * 100, run.result.polygonCount(), m.vertices, m.medialMedian,
              m.medialP90, m.axisMedian, m.axisP90, m.axisP99, m.axisMax, m.farShare, m.coverage, m.insideShare,
              run.result.topology.beta0, run.result.times.total);
  return run;
}

}  // namespace

TEST(AnalyticShapes, EllipsoidDistanceMatchesADenseSearch) {
  const Vec3 e{3, 2, 1};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-4, 4);
  for (int k = 0; k < 200; ++k) {
    Vec3 p{u(rng), u(rng), u(rng) / 2};
    if (k % 5 == 0) p[2] = 0;  // the symmetry plane (medial axis inside)
    double best = 1e300;
    // Dense parameter search, then local refinement.
    double bu = 0, bv = 0;
    for (int i = 0; i <= 400; ++i)
      for (int j = 0; j <= 200; ++j) {
        const double s = 2 * M_PI * i / 400, t = M_PI * j / 200 - M_PI / 2;
        const Vec3 x{e[0] * std::cos(t) * std::cos(s), e[1] * std::cos(t) * std::sin(s), e[2] * std::sin(t)};
        const double d = std::hypot(std::hypot(x[0] - p[0], x[1] - p[1]), x[2] - p[2]);
        if (d < best) best = d, bu = s, bv = t;
      }
    for (double h = 0.02; h > 1e-9; h *= 0.5)
      for (int it = 0; it < 8; ++it)
        for (int di = -1; di <= 1; ++di)
          for (int dj = -1; dj <= 1; ++dj) {
            const double s = bu + di * h, t = std::clamp(bv + dj * h, -M_PI / 2, M_PI / 2);
            const Vec3 x{e[0] * std::cos(t) * std::cos(s), e[1] * std::cos(t) * std::sin(s), e[2] * std::sin(t)};
            const double d = std::hypot(std::hypot(x[0] - p[0], x[1] - p[1]), x[2] - p[2]);
            if (d < best) best = d, bu = s, bv = t;
          }
    EXPECT_NEAR(ellipsoidDistance(e, p), best, 1e-7) << p[0] << " " << p[1] << " " << p[2];
  }
}

namespace {

// Three shapes, one θ = π/8 and ρ = 8 (MedialParams::pointCloud()) for all.
std::vector<std::unique_ptr<AnalyticShape>> shapes() {
  std::vector<std::unique_ptr<AnalyticShape>> out;
  out.push_back(makeSphere(1.0));
  out.push_back(makeEllipsoid(3, 2, 1));
  out.push_back(makeTorus(2.0, 0.7));
  return out;
}
constexpr std::size_t kDensities[] = {2000, 8000, 32000};
constexpr double kTol = 0.005;  // × diagonal, as `cadmedial eval` (EvaluationParams::toleranceFraction)

// DESIGN §6 thresholds of the CAD path (EvaluationThresholds): medialness
// median <= 1 tol and 90th percentile <= 2 tol, coverage >= 99 %.
void expectCadThresholds(const CloudRun& run, const std::string& what) {
  EXPECT_GT(run.m.vertices, 0u) << what;
  EXPECT_LE(run.m.medialMedian, kTol) << what;
  EXPECT_LE(run.m.medialP90, 2 * kTol) << what;
  EXPECT_GE(run.m.coverage, 0.99) << what;
}

}  // namespace

TEST(MedialClouds, NoiseFreeSamplesMeetTheCadThresholdsAtEveryDensity) {
  for (const auto& shape : shapes()) {
    double previous = 1e300;
    for (std::size_t n : kDensities) {
      const CloudRun run = runOn(*shape, n, 0.0);
      const std::string what = shape->name() + " n=" + std::to_string(run.points);
      expectCadThresholds(run, what);
      // On the exact axis (inner ∪ outer): 90 % of the vertices within 2 tol,
      // and at most 2 % of them farther (measured: torus 1.3 %, 0.9 %, 0.7 %;
      // those are the outer facets around the torus' hole).
      EXPECT_LE(run.m.axisP90, 2 * kTol) << what;
      EXPECT_LE(run.m.farShare, 0.02) << what;
      if (shape->name() != "torus") {
        EXPECT_GE(run.m.insideShare, 0.999) << what;  // convex: no outer axis
      }
      if (shape->name() == "ellipsoid") {
        // Convergence (seed 000 §4): the error shrinks with density at fixed θ, ρ.
        EXPECT_LT(run.m.medialP90, previous) << what;
        previous = run.m.medialP90;
      }
    }
  }
}

// 0.1 % of the diagonal, uniform per coordinate. Medialness and coverage keep
// the CAD thresholds at every density. Where the axis itself holds up is a
// matter of noise against spacing: the ellipsoid's stays within 2 tol of the
// exact axis at every density; the torus' only at the coarsest (noise ≈ 0.1
// spacing; 90th percentile 0.008, 0.024, 0.062 diag at 2k, 8k, 32k points);
// the sphere's axis (a point) spreads at every density (0.015, 0.051, 0.13):
// the noisy surface has a large medial axis of its own, and the Angle/Ratio
// filters cannot tell it from the sphere's (the paper assumes noise-free
// ε-samples). bench/RESULTS_medial.md has the table.
TEST(MedialClouds, NoiseOfATenthOfAPercent) {
  for (const auto& shape : shapes()) {
    for (std::size_t n : kDensities) {
      const CloudRun run = runOn(*shape, n, 0.001);
      const std::string what = shape->name() + " noisy n=" + std::to_string(run.points);
      expectCadThresholds(run, what);
      if (shape->name() == "ellipsoid" || (shape->name() == "torus" && n == kDensities[0])) {
        EXPECT_LE(run.m.axisP90, 2 * kTol) << what;
      }
    }
  }
}

TEST(MedialClouds, SelectionIsScaleIndependent) {
  // The Angle and Ratio conditions compare angles and length ratios only.
  const auto shape = makeEllipsoid(3, 2, 1);
  std::vector<Vec3> pts = sampleSurface(*shape, 4000, 9);
  const PointMedialResult a = computeMedial(pts);
  for (Vec3& p : pts)
    for (double& x : p) x *= 1000;
  const PointMedialResult b = computeMedial(pts);
  EXPECT_EQ(a.counts.selectedFacets, b.counts.selectedFacets);
  EXPECT_EQ(a.polygonCount(), b.polygonCount());
  EXPECT_GT(a.polygonCount(), 1000u);
}

TEST(MedialClouds, PolesAndUmbrellasOnAnEllipsoid) {
  // Pole vectors approximate the normal (Amenta-Bern); tangent-polygon
  // umbrellas are the small flat triangle fans around each sample.
  const auto shape = makeEllipsoid(3, 2, 1);
  const std::vector<Vec3> pts = sampleSurface(*shape, 8000, 4);
  DelaunayVoronoi dv(pts);
  const PoleData poles = computePoles(dv);
  const TangentPolygonUmbrellas umb = computeTangentPolygonUmbrellas(dv, poles);
  std::vector<double> angle;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vec3& p = pts[i];
    Vec3 n{p[0] / 9, p[1] / 4, p[2] / 1};
    const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const Vec3& v = poles.direction[i];
    angle.push_back(std::acos(std::min(1.0, std::abs(n[0] * v[0] + n[1] * v[1] + n[2] * v[2]) / l)) * 180 / M_PI);
  }
  std::sort(angle.begin(), angle.end());
  const double p99 = angle[angle.size() * 99 / 100];
  const double mean = static_cast<double>(umb.triangles.size()) / static_cast<double>(pts.size());
  std::printf("pole-normal angle median %.3f° p99 %.3f° max %.3f°; umbrella triangles per sample %.2f, empty %zu, "
              "hull samples %zu\n",
              angle[angle.size() / 2], p99, angle.back(), mean, umb.emptyUmbrellas, poles.unboundedCells);
  EXPECT_LE(p99, 5.0);
  EXPECT_EQ(umb.emptyUmbrellas, 0u);
  EXPECT_GE(mean, 4.5);  // a fan around p: ~6 triangles on a well-spaced sample
  EXPECT_LE(mean, 8.0);
  // Every umbrella triangle contains its sample and lies flat to the surface.
  for (std::size_t p = 0; p < pts.size(); ++p)
    for (Index k = umb.offsets[p]; k < umb.offsets[p + 1]; ++k) ASSERT_EQ(umb.triangles[k][0], p);
}

TEST(MedialClouds, DegenerateInputs) {
  // Fewer than 4 points, coplanar points, duplicates: no crash, empty or sane output.
  EXPECT_EQ(computeMedial({}).polygonCount(), 0u);
  EXPECT_EQ(computeMedial({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}).polygonCount(), 0u);
  std::vector<Vec3> plane;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) plane.push_back({i + 0.1 * j * j, j + 0.01 * i * i, 0});
  const PointMedialResult flat = computeMedial(plane);
  EXPECT_EQ(flat.polygonCount(), 0u);
  EXPECT_NE(flat.cloud.axisNote.find("fewer than 3"), std::string::npos);
  const auto shape = makeSphere(1);
  std::vector<Vec3> pts = sampleSurface(*shape, 500, 2, 0.001);
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < 50; ++i) pts.push_back(pts[i]);
  const PointMedialResult dup = computeMedial(pts);
  EXPECT_EQ(dup.counts.duplicateSamples, 50u);
  EXPECT_GT(dup.polygonCount(), 0u);
  EXPECT_EQ(dup.counts.samples, n + 50);
  EXPECT_THROW(computeMedial({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, std::nan("")}}), std::exception);
  EXPECT_THROW(computeMedial(pts, MedialParams::pointCloud(), {{0, 1, static_cast<Index>(pts.size())}}),
               std::invalid_argument);
}

// Random samples on the planar faces of a box, lifted off their planes by
// rounding-sized noise, make nearly flat slivers whose exact circumcenters
// lie ~1e15 away. The whole axis drops the facets through them with the
// unbounded ones instead of drawing polygons 1e18 wide.
TEST(MedialClouds, WholeAxisStaysNearTheCloudDespiteSlivers) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0), noise(-1e-15, 1e-15);
  std::vector<Vec3> points;
  for (int face = 0; face < 6; ++face)
    for (int i = 0; i < 400; ++i) {
      Vec3 p{unit(random), unit(random), unit(random)};
      p[face / 2] = (face % 2) + noise(random);
      points.push_back(p);
    }
  const PointMedialResult whole = computeMedial(points);
  ASSERT_GT(whole.polygonCount(), 0u);
  double farthest = 0;
  for (const Vec3& v : whole.vertices) farthest = std::max({farthest, std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
  std::printf("whole axis of a jittered box cloud: %zu polygons, farthest vertex coordinate %.3g\n",
              whole.polygonCount(), farthest);
  EXPECT_LT(farthest, 1e3) << "a unit box's whole axis reaches ~1e2 at most; far sliver centres are ~1e15";
}
