// The stitched per-face reconstruction is a closed 2-manifold with the solid's
// topology, and its area and enclosed volume match OCCT's exact values.
#include <gtest/gtest.h>

#include <cmath>

#include "cadmedial/brep_io.hpp"
#include "cadmedial/sampling.hpp"
#include "cadmedial/surface_mesh_checks.hpp"
#include "model_fixtures.hpp"

namespace cadmedial {
namespace {

class BundledReconstruction : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledReconstruction, ClosedManifoldWithExactTopologyAreaAndVolume) {
  const nlohmann::json& expected = test::bundledModel(GetParam());
  const LoadedModel model = loadModel(test::bundledPath(expected));
  const SolidSampling result = sampleSolid(model.solids[0]);
  const SamplingReport& r = result.report;
  const SurfaceMeshStats& s = r.surface;
  EXPECT_EQ(r.facesFailed, 0);
  EXPECT_EQ(r.orphanSamples, 0);
  EXPECT_TRUE(s.closedManifold()) << s.boundaryEdges << " boundary, " << s.nonManifoldEdges << " non-manifold, "
                                  << s.misorientedEdges << " misoriented edges, " << s.nonManifoldVertices
                                  << " non-manifold vertices";
  EXPECT_EQ(s.components, 1u);
  const int genus = expected.at("genus").get<int>();
  EXPECT_EQ(s.eulerCharacteristic, 2 - 2 * genus);
  // Against the hand formulas and against BRepGProp.
  const double area = expected.at("area").at("value").get<double>();
  const double volume = expected.at("volume").at("value").get<double>();
  EXPECT_NEAR(r.exactArea, area, 1e-6 * area);
  EXPECT_NEAR(r.exactVolume, volume, 1e-6 * volume);
  EXPECT_LT(std::abs(s.area / area - 1.0), 0.01) << "area " << s.area << " vs " << area;
  EXPECT_LT(std::abs(s.enclosedVolume / volume - 1.0), 0.01) << "volume " << s.enclosedVolume << " vs " << volume;
  // Every sample has an umbrella.
  for (Index i = 0; i < result.samples.size(); ++i)
    ASSERT_LT(result.samples.umbrellaOffsets[i], result.samples.umbrellaOffsets[i + 1]) << "sample " << i;
}

INSTANTIATE_TEST_SUITE_P(Models, BundledReconstruction, ::testing::ValuesIn(test::bundledModelNames()),
                         [](const auto& info) { return info.param; });

// The checker itself must see holes, flips and non-manifold edges.
TEST(SurfaceMeshChecks, DetectsOpenFlippedAndNonManifoldSurfaces) {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  std::vector<std::array<Index, 3>> tet = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  const SurfaceMeshStats closed = checkSurfaceMesh(p, tet);
  EXPECT_TRUE(closed.closedManifold());
  EXPECT_EQ(closed.eulerCharacteristic, 2);
  EXPECT_NEAR(closed.enclosedVolume, 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(closed.area, 1.5 + std::sqrt(3.0) / 2, 1e-12);

  auto open = tet;
  open.pop_back();
  EXPECT_EQ(checkSurfaceMesh(p, open).boundaryEdges, 3u);
  auto flipped = tet;
  std::swap(flipped[0][1], flipped[0][2]);
  EXPECT_EQ(checkSurfaceMesh(p, flipped).misorientedEdges, 3u);
  auto fin = tet;
  fin.push_back({1, 2, 4});
  EXPECT_EQ(checkSurfaceMesh(p, fin).nonManifoldEdges, 1u);
}

}  // namespace
}  // namespace cadmedial
