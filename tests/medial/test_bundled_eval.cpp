// Every bundled model, default parameters: the DESIGN.md §6 metrics against
// OCCT's exact geometry meet the thresholds of the CAD_MEDIAL issue.
#include <gtest/gtest.h>

#include <cstdio>

#include "cadmedial/medial.hpp"
// OCCT after CGAL (OCCT's Handle macro).
#include "cadmedial/brep_io.hpp"
#include "cadmedial/medial_evaluation.hpp"
#include "cadmedial/sampling.hpp"
#include "medial_mesh_conversion.hpp"
#include "model_fixtures.hpp"

namespace cadmedial {
namespace {

class BundledEvaluation : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledEvaluation, MeetsTheExactGeometryThresholds) {
  const LoadedModel model = loadModel(test::bundledPath(test::bundledModel(GetParam())));
  const SolidSampling s = sampleSolid(model.solids[0]);
  const MedialResult m = computeCadMedial(s.samples);
  const EvaluationReport r = evaluateMedial(model.solids[0], toMedialMesh(m));
  std::printf("%-22s inside %.4f  medialness median %.4f%% diag  two contacts %.4f  coverage %.4f  edges %.4f  "
              "corners %d/%d  b0,b1 %lld,%lld (solid %lld,%lld)\n",
              GetParam().c_str(), r.inside.share, 100 * r.medialness.median, r.medialness.twoContactShare, r.coverage.share,
              r.attachment.edgeShare, r.attachment.attachedCorners, r.attachment.corners, r.topology.beta0,
              r.topology.beta1, r.topology.solidBeta0, r.topology.solidBeta1);
  EXPECT_GE(r.inside.share, 0.999);
  EXPECT_GE(r.coverage.share, 0.99);
  EXPECT_GE(r.attachment.edgeShare, 0.99);
  EXPECT_EQ(r.attachment.attachedCorners, r.attachment.corners);
  EXPECT_LE(r.medialness.median, 0.005);
  // Two contacts (DESIGN.md §6, eval threshold 90 %): the torus and the
  // cylinder reach it only with the fringe around their 1-D axes collapsed
  // (85 % and 92.5 % without), the flange only with its disc's faces graded
  // from the bolt holes' rims (85 % without: the sheets of the rims poked
  // through the disc's faces between samples spaced h;
  // FaceSpacingField::kConvexEdgeGrading).
  EXPECT_GE(r.medialness.twoContactShare, 0.9);
  EXPECT_EQ(r.topology.beta0, r.topology.solidBeta0);
  EXPECT_EQ(r.topology.beta1, r.topology.solidBeta1);
}

INSTANTIATE_TEST_SUITE_P(Models, BundledEvaluation, ::testing::ValuesIn(test::bundledModelNames()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace cadmedial
