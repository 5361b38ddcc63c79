// Betti numbers of small polygon complexes with known topology, and the
// solid side of the §6 checks (genus, convex-edge length, non-concave
// corners) against the hand-derived values in models/expected.json.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cadmedial/brep_io.hpp"
#include "cadmedial/medial_evaluation.hpp"

namespace cadmedial {
namespace {

MedialMesh complexOf(std::size_t vertices, const std::vector<std::vector<std::uint32_t>>& polygons) {
  MedialMesh m;
  for (std::size_t v = 0; v < vertices; ++v) m.addVertex({double(v), 0, 0}, 1);
  for (const auto& p : polygons) m.addPolygon(p, 0);
  return m;
}

// n x m quads on a torus grid (vertex (i, j) = i * m + j, indices wrap).
MedialMesh torusGrid(std::uint32_t n, std::uint32_t m) {
  std::vector<std::vector<std::uint32_t>> quads;
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < m; ++j)
      quads.push_back({i * m + j, ((i + 1) % n) * m + j, ((i + 1) % n) * m + (j + 1) % m, i * m + (j + 1) % m});
  return complexOf(n * m, quads);
}

TEST(MedialTopology, TriangleIsContractible) {
  const TopologyMetric t = medialComplexTopology(complexOf(3, {{0, 1, 2}}), 1000);
  EXPECT_EQ(t.euler, 1);
  EXPECT_EQ(t.beta0, 1);
  EXPECT_EQ(t.beta1, 0);
  EXPECT_EQ(t.beta2, 0);
  EXPECT_EQ(t.corePolygons, 0u);
}

TEST(MedialTopology, TetrahedronSurfaceEnclosesAVoid) {
  const TopologyMetric t = medialComplexTopology(complexOf(4, {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {0, 2, 3}}), 1000);
  EXPECT_EQ(t.euler, 2);
  EXPECT_EQ(t.beta0, 1);
  EXPECT_EQ(t.beta1, 0);
  EXPECT_EQ(t.beta2, 1);
  EXPECT_EQ(t.corePolygons, 4u);
}

TEST(MedialTopology, AnnulusHasOneLoop) {
  // Outer square 0..3, inner square 4..7, four quads between them.
  const TopologyMetric t =
      medialComplexTopology(complexOf(8, {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}), 1000);
  EXPECT_EQ(t.beta0, 1);
  EXPECT_EQ(t.beta1, 1);
  EXPECT_EQ(t.beta2, 0);
}

TEST(MedialTopology, BookOfThreePagesAndDisjointPieces) {
  // Three triangles on edge 0-1 (a non-manifold junction), plus a separate triangle.
  const TopologyMetric t = medialComplexTopology(complexOf(8, {{0, 1, 2}, {0, 1, 3}, {1, 0, 4}, {5, 6, 7}}), 1000);
  EXPECT_EQ(t.beta0, 2);
  EXPECT_EQ(t.beta1, 0);
  EXPECT_EQ(t.beta2, 0);
  EXPECT_EQ(t.edges, 10u);
}

TEST(MedialTopology, TorusSurface) {
  const TopologyMetric t = medialComplexTopology(torusGrid(6, 5), 1000);
  EXPECT_EQ(t.euler, 0);
  EXPECT_EQ(t.beta0, 1);
  EXPECT_EQ(t.beta1, 2);
  EXPECT_EQ(t.beta2, 1);
  // Above the core limit β2 (and so β1) is reported as unknown.
  const TopologyMetric big = medialComplexTopology(torusGrid(6, 5), 10);
  EXPECT_EQ(big.beta2, -1);
  EXPECT_EQ(big.beta1, -1);
}

TEST(MedialTopology, UnusedVerticesDoNotCount) {
  const TopologyMetric t = medialComplexTopology(complexOf(5, {{0, 1, 2}}), 1000);
  EXPECT_EQ(t.vertices, 3u);
  EXPECT_EQ(t.beta0, 1);
}

// The solid side of the checks, on every bundled model.
TEST(SolidSide, BundledModelsMatchHandDerivedValues) {
  std::ifstream in(std::string(CADMEDIAL_MODELS_DIR) + "/expected.json");
  ASSERT_TRUE(in);
  const nlohmann::json doc = nlohmann::json::parse(in);
  for (const nlohmann::json& m : doc.at("models")) {
    const std::string name = m.at("name");
    const LoadedModel model = loadModel(std::string(CADMEDIAL_MODELS_DIR) + "/" + m.at("file").get<std::string>());
    ASSERT_EQ(model.solids.size(), 1u) << name;
    const SolidBetti betti = solidBettiNumbers(model.solids[0]);
    EXPECT_EQ(betti.shells, 1) << name;
    EXPECT_EQ(betti.beta1, m.at("genus").get<long long>()) << name;
    EXPECT_EQ(betti.beta2, 0) << name;

    EvaluationParams params;
    params.boundaryPoints = 100;
    const EvaluationReport r = MedialEvaluator(model.solids[0], params).evaluate(MedialMesh{});
    const double length = m.at("convex_length").at("value");
    EXPECT_NEAR(r.attachment.convexLength, length, 1e-6 * std::max(1.0, length)) << name;
    EXPECT_EQ(r.attachment.corners, m.at("nonconcave_corners").get<int>()) << name;
    // An empty axis attaches to nothing and fails.
    EXPECT_EQ(r.attachment.attachedCorners, 0) << name;
    EXPECT_FALSE(r.pass.all()) << name;
  }
}

}  // namespace
}  // namespace cadmedial
