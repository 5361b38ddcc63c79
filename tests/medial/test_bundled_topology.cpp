// Every bundled model: the inner axis has the solid's topology (one
// component, β1 = genus) and the walk agrees with OCCT's exact classifier.
// The cylinder's axis segment and the torus's core circle are covered.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <mutex>

#include "cadmedial/medial.hpp"
// OCCT after CGAL (OCCT's Handle macro).
#include <BRepClass3d_SolidClassifier.hxx>

#include "cadmedial/brep_io.hpp"
#include "cadmedial/sampling.hpp"
#include "model_fixtures.hpp"

namespace cadmedial {
namespace {

struct Computed {
  SolidSampling sampling;
  MedialResult medial;
};

Computed compute(const std::string& name, bool withOracle) {
  const LoadedModel model = loadModel(test::bundledPath(test::bundledModel(name)));
  Computed c{sampleSolid(model.solids[0]), {}};
  BRepClass3d_SolidClassifier classifier(model.solids[0]);
  std::mutex lock;  // the walk's check calls the oracle from several threads
  InsideOracle oracle;
  if (withOracle)
    oracle = [&classifier, &lock](const Vec3& p) {
      const std::lock_guard<std::mutex> hold(lock);
      classifier.Perform(gp_Pnt(p[0], p[1], p[2]), 1e-9);
      return classifier.State() == TopAbs_IN;
    };
  c.medial = computeCadMedial(c.sampling.samples, MedialParams::cad(), oracle);
  return c;
}

// Largest distance from points of a curve to the nearest medial vertex.
template <typename Curve>
double worstGap(const MedialResult& m, Curve curve, int steps) {
  double worst = 0;
  for (int k = 0; k <= steps; ++k) {
    const Vec3 p = curve(static_cast<double>(k) / steps);
    double best = 1e300;
    for (const Vec3& v : m.vertices) {
      const double d = std::hypot(v[0] - p[0], v[1] - p[1], v[2] - p[2]);
      best = std::min(best, d);
    }
    worst = std::max(worst, best);
  }
  return worst;
}

class BundledTopology : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledTopology, AxisHasTheSolidsTopologyAndTheWalkAgreesWithTheExactClassifier) {
  const Computed c = compute(GetParam(), true);
  const int genus = test::bundledModel(GetParam()).at("genus").get<int>();
  const MedialCounts& n = c.medial.counts;
  std::printf("%-22s samples %6zu polygons %6zu sheets %5zu b0 %lld b1 %lld; walk vs classifier: %zu/%zu disagree\n",
              GetParam().c_str(), n.samples, c.medial.polygonCount(), c.medial.sheetCount, c.medial.topology.beta0,
              c.medial.topology.beta1, n.oracleDisagreements, n.oracleChecked);
  EXPECT_EQ(c.medial.topology.beta0, 1);
  EXPECT_EQ(c.medial.topology.beta1, genus);
  ASSERT_GT(n.oracleChecked, 0u);
  EXPECT_LE(static_cast<double>(n.oracleDisagreements), 0.001 * static_cast<double>(n.oracleChecked));
}

INSTANTIATE_TEST_SUITE_P(Models, BundledTopology, ::testing::ValuesIn(test::bundledModelNames()),
                         [](const auto& info) { return info.param; });

TEST(CylinderAxis, TheAxisSegmentIsCovered) {
  // R 10, H 30 along z: the inner axis holds the segment z in [10, 20] of the z axis.
  const Computed c = compute("cylinder", false);
  const double gap = worstGap(c.medial, [](double t) { return Vec3{0, 0, 10 + 10 * t}; }, 50);
  std::printf("cylinder: worst distance from the axis segment to the medial vertices %.3g (h %.3g)\n", gap,
              c.sampling.samples.spacing);
  EXPECT_LE(gap, c.sampling.samples.spacing);
}

TEST(TorusAxis, TheCoreCircleIsCovered) {
  // Major R 30, minor r 10: the inner axis is the circle of radius 30 in z = 0.
  const Computed c = compute("torus", false);
  const double gap = worstGap(
      c.medial, [](double t) { return Vec3{30 * std::cos(2 * M_PI * t), 30 * std::sin(2 * M_PI * t), 0}; }, 200);
  std::printf("torus: worst distance from the core circle to the medial vertices %.3g (h %.3g)\n", gap,
              c.sampling.samples.spacing);
  EXPECT_LE(gap, c.sampling.samples.spacing);
}

}  // namespace
}  // namespace cadmedial
