// Narrow faces: a 100 × 100 × 50 block with a step of height t on half its
// top (scripts/robustness_parts.py, small_step). The step's riser is a face
// t wide and 100 long; at the part's spacing (h 3.75) the triplet legs of
// its top edge found no room on it and were dropped, and the edge's sheet
// was missing: at t = 0.2, 91 % of the convex edges attached and β1 1; at
// t = 0.5, β1 2. The sampler now asks for a spacing of half a face's width
// along edges of the face that come close to each other
// (narrow_faces.hpp), and passes that on to the faces across the convex ones.
// Checked against the exact B-rep by the §6 evaluation.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "cadmedial/medial.hpp"
// OCCT after CGAL (OCCT's Handle macro).
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopExp_Explorer.hxx>

#include "cadmedial/medial_evaluation.hpp"
#include "cadmedial/sampling.hpp"
#include "medial_mesh_conversion.hpp"

namespace cadmedial {
namespace {

// The block and the step fused, coplanar faces merged (one face for the
// front, back and left side each, as a CAD modeller gives it).
TopoDS_Shape steppedBlock(double step) {
  const TopoDS_Shape block = BRepPrimAPI_MakeBox(100, 100, 50).Shape();
  const TopoDS_Shape tread = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 50), 50, 100, step).Shape();
  BRepAlgoAPI_Fuse fuse(block, tread);
  ShapeUpgrade_UnifySameDomain unify(fuse.Shape());
  unify.Build();
  TopExp_Explorer solid(unify.Shape(), TopAbs_SOLID);
  return solid.More() ? solid.Current() : TopoDS_Shape();
}

class NarrowFace : public ::testing::TestWithParam<double> {};

TEST_P(NarrowFace, StepRiserKeepsItsSheetAndTheAxisItsTopology) {
  const double step = GetParam();
  const TopoDS_Shape solid = steppedBlock(step);
  ASSERT_FALSE(solid.IsNull());
  const SolidSampling s = sampleSolid(solid);
  ASSERT_TRUE(s.report.surface.closedManifold());
  ASSERT_EQ(s.report.features.faces, 8);  // the merge worked: a riser, not slivers
  const MedialResult m = computeCadMedial(s.samples);
  const EvaluationReport r = evaluateMedial(solid, toMedialMesh(m));
  std::printf("step %.1f (h %.2f): %zu samples, %zu triplets dropped; inside %.4f  two contacts %.4f  edges %.4f  "
              "corners %d/%d  b0,b1 %lld,%lld (solid %lld,%lld)\n",
              step, s.samples.spacing, s.samples.size(), s.report.tripletsDropped, r.inside.share,
              r.medialness.twoContactShare, r.attachment.edgeShare, r.attachment.attachedCorners,
              r.attachment.corners, r.topology.beta0, r.topology.beta1, r.topology.solidBeta0,
              r.topology.solidBeta1);
  // The riser is 1/19 and 1/7.5 of the spacing wide.
  EXPECT_LT(step, s.samples.spacing / 7);
  EXPECT_GE(r.inside.share, 0.999);
  EXPECT_GE(r.attachment.edgeShare, 0.99);
  EXPECT_EQ(r.attachment.attachedCorners, r.attachment.corners);
  EXPECT_GE(r.medialness.twoContactShare, 0.9);
  EXPECT_EQ(r.topology.beta0, 1);
  EXPECT_EQ(r.topology.beta1, 0);
  // Not the whole part at the riser's spacing: the refinement stays near it
  // (the block alone takes 3.2 k samples at this spacing; the whole part at
  // a spacing of 0.5 would take 170 k).
  EXPECT_LT(s.samples.size(), 20000u);
}

INSTANTIATE_TEST_SUITE_P(Risers, NarrowFace, ::testing::Values(0.2, 0.5),
                         [](const ::testing::TestParamInfo<double>& info) {
                           return "height_" + std::to_string(static_cast<int>(info.param * 10)) + "_tenths";
                         });

}  // namespace
}  // namespace cadmedial
