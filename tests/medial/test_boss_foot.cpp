// A boss on a plate: each vertical convex edge of the boss ends on the
// plate at a vertex where it meets two concave edges. The edge's medial
// sheet reaches that vertex (a ball on the bisector just above the plate
// touches the two boss faces first), so the axis must attach along the
// whole edge. Before the one-sided fill at such a vertex (convex_edges.cpp,
// 2026-12-06) the sheet stopped a corner ball short of it: 99.05 % of the
// convex length attached here, the bottom 0.9 mm of each of the 4 edges
// missing.
#include <gtest/gtest.h>

#include <cstdio>

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

TopoDS_Shape bossOnPlate() {
  BRepAlgoAPI_Fuse fuse(BRepPrimAPI_MakeBox(40, 40, 5).Shape(),
                        BRepPrimAPI_MakeBox(gp_Pnt(15, 15, 5), 10, 10, 10).Shape());
  ShapeUpgrade_UnifySameDomain unify(fuse.Shape());
  unify.Build();
  TopExp_Explorer solid(unify.Shape(), TopAbs_SOLID);
  return solid.More() ? solid.Current() : TopoDS_Shape();
}

TEST(BossFoot, ConvexEdgesEndingAmongConcaveOnesAreAttachedToTheirEnd) {
  const TopoDS_Shape solid = bossOnPlate();
  ASSERT_FALSE(solid.IsNull());
  const SolidSampling s = sampleSolid(solid);
  ASSERT_TRUE(s.report.surface.closedManifold());
  const MedialResult m = computeCadMedial(s.samples);
  const EvaluationReport r = evaluateMedial(solid, toMedialMesh(m));
  std::printf("boss: %zu samples; edges %.4f of %.1f, corners %d/%d, b0,b1,b2 %lld,%lld,%lld\n", s.samples.size(),
              r.attachment.edgeShare, r.attachment.convexLength, r.attachment.attachedCorners, r.attachment.corners,
              r.topology.beta0, r.topology.beta1, r.topology.beta2);
  EXPECT_GE(r.attachment.edgeShare, 0.999);
  EXPECT_EQ(r.attachment.attachedCorners, r.attachment.corners);
  EXPECT_TRUE(r.topology.matches);
  EXPECT_GE(r.inside.share, 0.999);
}

}  // namespace
}  // namespace cadmedial
