// The CLI's and the Python module's path (the Delaunay on its own thread
// beside the reconstruction, the samples' part prepared meanwhile, the Betti
// numbers afterwards) gives the same axis as the one-call pipeline.
#include <gtest/gtest.h>

#include "cadmedial/medial.hpp"
// OCCT after CGAL (OCCT's Handle macro).
#include "cadmedial/brep_io.hpp"
#include "cadmedial/sample_and_triangulate.hpp"
#include "cadmedial/sampling.hpp"
#include "model_fixtures.hpp"

namespace cadmedial {
namespace {

TEST(OverlappedPipeline, SameAxisAsTheOneCallPipeline) {
  for (const char* name : {"flange", "thin_wall"}) {
    SCOPED_TRACE(name);
    const LoadedModel model = loadModel(test::bundledPath(test::bundledModel(name)));
    const SolidSampling alone = sampleSolid(model.solids[0]);
    const MedialResult expected = computeCadMedial(alone.samples);
    ASSERT_GT(expected.polygonCount(), 0u);

    MedialParams params;
    params.computeTopology = false;
    const TriangulatedSamples run = sampleAndTriangulate(model.solids[0], {}, params.mayReadCellSides());
    ASSERT_EQ(run.sampled.samples.points, alone.samples.points);
    MedialResult got = computeCadMedial(*run.triangulation, run.sampled.samples, *run.prepared, params);
    EXPECT_EQ(got.topology.beta0, 0);  // left to the caller
    got.topology = computeTopology(got, got.edges, params.bettiCoreLimit);
    EXPECT_GT(got.times.preparedAlongside, 0);

    EXPECT_EQ(got.vertices, expected.vertices);
    EXPECT_EQ(got.radius, expected.radius);
    EXPECT_EQ(got.polygonOffsets, expected.polygonOffsets);
    EXPECT_EQ(got.polygonVertices, expected.polygonVertices);
    EXPECT_EQ(got.sheet, expected.sheet);
    EXPECT_EQ(got.provenance, expected.provenance);
    EXPECT_EQ(got.topology.beta0, expected.topology.beta0);
    EXPECT_EQ(got.topology.beta1, expected.topology.beta1);
  }
}

}  // namespace
}  // namespace cadmedial
