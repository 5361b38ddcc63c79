// Edge and corner classification from exact geometry against the hand-derived
// table in models/EXPECTED.md.
#include <gtest/gtest.h>

#include "cadmedial/brep_io.hpp"
#include "cadmedial/sampling.hpp"
#include "model_fixtures.hpp"

namespace cadmedial {
namespace {

class BundledClassification : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledClassification, MatchesHandDerivedTable) {
  const nlohmann::json& expected = test::bundledModel(GetParam());
  const LoadedModel model = loadModel(test::bundledPath(expected));
  ASSERT_EQ(model.solids.size(), 1u);
  const FeatureCounts c = classifyFeatures(model.solids[0]);
  EXPECT_EQ(c.convexEdges, expected.at("convex_edges").get<int>());
  EXPECT_EQ(c.concaveEdges, expected.at("concave_edges").get<int>());
  EXPECT_EQ(c.smoothEdges, expected.at("smooth_edges").get<int>());
  EXPECT_EQ(c.seamEdges, expected.at("seam_edges").get<int>());
  EXPECT_EQ(c.mixedSignEdges, 0);
  EXPECT_EQ(c.corners, expected.at("corners").get<int>());
  EXPECT_EQ(c.nonConcaveCorners, expected.at("nonconcave_corners").get<int>());
  const double convexLength = expected.at("convex_length").at("value").get<double>();
  const double concaveLength = expected.at("concave_length").at("value").get<double>();
  EXPECT_NEAR(c.convexLength, convexLength, 1e-6 * (1 + convexLength));
  EXPECT_NEAR(c.concaveLength, concaveLength, 1e-6 * (1 + concaveLength));
}

// Splitting closed faces must not change what is sharp: the same lengths and
// corners on the split solid that sampling works on.
TEST_P(BundledClassification, SplitSolidKeepsFeatureLengthsAndCorners) {
  const nlohmann::json& expected = test::bundledModel(GetParam());
  const LoadedModel model = loadModel(test::bundledPath(expected));
  SamplingParams params;
  const SolidSampling result = sampleSolid(model.solids[0], params);
  const FeatureCounts& c = result.report.features;
  const double convexLength = expected.at("convex_length").at("value").get<double>();
  EXPECT_NEAR(c.convexLength, convexLength, 1e-6 * (1 + convexLength));
  EXPECT_EQ(c.corners, expected.at("corners").get<int>());
  EXPECT_EQ(c.nonConcaveCorners, expected.at("nonconcave_corners").get<int>());
  EXPECT_EQ(c.seamEdges, 0) << "closed faces must be split before sampling";
}

INSTANTIATE_TEST_SUITE_P(Models, BundledClassification, ::testing::ValuesIn(test::bundledModelNames()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace cadmedial
