// The bundled box (40 x 30 x 20 at the origin) has a known medial axis: the
// points whose two nearest face planes tie. Check the computed axis against it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "cadmedial/medial.hpp"
// OCCT after CGAL (OCCT's Handle macro).
#include "cadmedial/brep_io.hpp"
#include "cadmedial/sampling.hpp"
#include "model_fixtures.hpp"

namespace cadmedial {
namespace {

constexpr double kSize[3] = {40, 30, 20};

// The two smallest distances from p to the six face planes.
std::array<double, 2> twoNearestPlanes(const Vec3& p) {
  std::array<double, 6> d{};
  for (int k = 0; k < 3; ++k) {
    d[2 * k] = std::abs(p[k]);
    d[2 * k + 1] = std::abs(kSize[k] - p[k]);
  }
  std::sort(d.begin(), d.end());
  return {d[0], d[1]};
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

class BoxAxis : public ::testing::TestWithParam<double> {};  // spacing as a fraction of the default

TEST_P(BoxAxis, VerticesTieBetweenTwoFacePlanesAndTopologyIsADisc) {
  const LoadedModel model = loadModel(test::bundledPath(test::bundledModel("box")));
  SamplingParams sp;
  sp.spacing = defaultSpacing(model.solids[0]) * GetParam();
  const SolidSampling s = sampleSolid(model.solids[0], sp);
  const MedialResult m = computeCadMedial(s.samples);
  const double diag = s.samples.bboxDiagonal(), h = s.samples.spacing;

  std::vector<double> tie, radiusError;
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    const Vec3& v = m.vertices[i];
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(v[k] >= -1e-9 && v[k] <= kSize[k] + 1e-9) << "vertex outside the box";
    if (m.vertexSample[i] != kNoIndex) continue;  // samples on edges/corners tie at distance 0 trivially
    const auto d = twoNearestPlanes(v);
    tie.push_back(d[1] - d[0]);
    radiusError.push_back(std::abs(m.radius[i] - d[0]));
  }
  ASSERT_GT(tie.size(), 100u);
  const double tieMedian = median(tie), tieMax = *std::max_element(tie.begin(), tie.end());
  std::printf("box h=%.4g: %zu Voronoi vertices, |d1-d2| median %.3g (%.2g diag), max %.3g (%.2g h); |r-d1| median %.3g\n",
              h, tie.size(), tieMedian, tieMedian / diag, tieMax, tieMax / h, median(radiusError));
  EXPECT_LE(tieMedian, 1e-3 * diag);
  EXPECT_LE(tieMax, h);
  EXPECT_LE(median(radiusError), 5e-3 * diag);  // the medialness bound of DESIGN.md §6 tests
  EXPECT_EQ(m.topology.beta0, 1);
  EXPECT_EQ(m.topology.beta1, 0);
  EXPECT_EQ(m.counts.oracleDisagreements, 0u);
}

// Every convex-edge sample and every corner sample is a vertex of the axis:
// the completion attaches the axis to all 12 edges and all 8 corners.
TEST_P(BoxAxis, EveryEdgeAndCornerSampleIsOnTheAxis) {
  const LoadedModel model = loadModel(test::bundledPath(test::bundledModel("box")));
  SamplingParams sp;
  sp.spacing = defaultSpacing(model.solids[0]) * GetParam();
  const SolidSampling s = sampleSolid(model.solids[0], sp);
  const MedialResult m = computeCadMedial(s.samples);
  std::vector<std::uint8_t> onAxis(s.samples.size(), 0);
  for (Index v : m.vertexSample)
    if (v != kNoIndex) onAxis[v] = 1;
  int edgesFullyAttached = 0, corners = 0;
  for (const EdgeInfo& e : s.samples.edges) {
    if (e.kind != EdgeKind::Convex) continue;
    bool all = true;
    for (Index i : e.samples) all = all && onAxis[i];
    edgesFullyAttached += all ? 1 : 0;
  }
  for (const CornerInfo& c : s.samples.vertices)
    if (c.nonConcave && onAxis[c.sample]) ++corners;
  EXPECT_EQ(edgesFullyAttached, 12);
  EXPECT_EQ(corners, 8);
}

INSTANTIATE_TEST_SUITE_P(Spacings, BoxAxis, ::testing::Values(1.0, 0.5));

}  // namespace
}  // namespace cadmedial
