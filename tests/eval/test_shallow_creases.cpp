// Shallow creases in the attachment metric: convex length (and corners)
// where the two faces' normals differ by less than 2θ is measured apart from
// edgeShare / cornerShare, since the Angle condition at θ cannot see it
// (seed 002 §4). Checked on solids whose crease angles are known exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include "cadmedial/medial_evaluation.hpp"

namespace cadmedial {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A house-shaped prism: a 40 x 20 wall profile with a roof whose two halves
// meet at a ridge turning by `ridgeDeg`, extruded 30 along y.
constexpr double kWidth = 40, kWall = 20, kDepth = 30;
TopoDS_Shape roofPrism(double ridgeDeg) {
  const double rise = kWidth / 2 * std::tan(ridgeDeg / 2 * kPi / 180);
  BRepBuilderAPI_MakePolygon profile;
  for (const gp_Pnt& p : {gp_Pnt(0, 0, 0), gp_Pnt(kWidth, 0, 0), gp_Pnt(kWidth, 0, kWall),
                          gp_Pnt(kWidth / 2, 0, kWall + rise), gp_Pnt(0, 0, kWall)})
    profile.Add(p);
  profile.Close();
  return BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(profile.Wire()).Face(), gp_Vec(0, kDepth, 0)).Shape();
}

// A square pyramid, base 40 x 40, apex `height` above the centre: low, its
// four slanted edges turn by a few degrees and its apex is a corner only
// they reach.
constexpr double kBase = 40;
TopoDS_Shape pyramid(double height) {
  const gp_Pnt base[4] = {gp_Pnt(0, 0, 0), gp_Pnt(kBase, 0, 0), gp_Pnt(kBase, kBase, 0), gp_Pnt(0, kBase, 0)};
  const gp_Pnt apex(kBase / 2, kBase / 2, height);
  BRepBuilderAPI_Sewing sewing(1e-7);
  sewing.Add(BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakePolygon(base[0], base[3], base[2], base[1], true).Wire()));
  for (int i = 0; i < 4; ++i)
    sewing.Add(BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakePolygon(base[i], base[(i + 1) % 4], apex, true).Wire()));
  sewing.Perform();
  TopExp_Explorer shell(sewing.SewedShape(), TopAbs_SHELL);
  return BRepBuilderAPI_MakeSolid(TopoDS::Shell(shell.Current())).Solid();
}

AttachmentMetric attachmentOf(const TopoDS_Shape& solid, double thetaDeg, const MedialMesh& mesh = {}) {
  EvaluationParams params;
  params.thetaDeg = thetaDeg;
  params.boundaryPoints = 100;
  return MedialEvaluator(solid, params).evaluate(mesh).attachment;
}

// The angle between the outward normals of two adjacent slanted faces of the
// pyramid (normals (0, -h, a) and (h, 0, a) up to scale, a = half the base).
double pyramidCreaseDeg(double height) {
  const double a = kBase / 2;
  const double cosAngle = (a * a) / (a * a + height * height);
  return std::acos(cosAngle) * 180 / kPi;
}

TEST(ShallowCreases, ARidgeBelowTwoThetaIsMeasuredApart) {
  const TopoDS_Shape house = roofPrism(6.0);
  const double tol = 1e-6;
  // At θ = 5 the 6° ridge is shallow: its length (the depth) is apart, all else is steep.
  const AttachmentMetric at5 = attachmentOf(house, 5.0);
  EXPECT_EQ(at5.convexEdges, 15);
  EXPECT_NEAR(at5.shallowLength, kDepth, tol);
  EXPECT_NEAR(at5.steepLength + at5.shallowLength, at5.convexLength, tol);
  EXPECT_EQ(at5.shallowCorners, 0);  // the ridge's ends also meet the steep gable edges
  EXPECT_EQ(at5.corners, 10);
  // At θ = 2 (4° < 6°) the ridge is steep and counts like any other edge.
  const AttachmentMetric at2 = attachmentOf(house, 2.0);
  EXPECT_EQ(at2.shallowLength, 0);
  EXPECT_NEAR(at2.steepLength, at2.convexLength, tol);
}

TEST(ShallowCreases, AnAxisOnTheRidgeOnlyAttachesShallowLength) {
  const TopoDS_Shape house = roofPrism(6.0);
  const double rise = kWidth / 2 * std::tan(3.0 * kPi / 180);
  // One thin triangle hanging below the ridge, from end to end.
  MedialMesh mesh;
  const auto a = mesh.addVertex({kWidth / 2, 0, kWall + rise}, 0);
  const auto b = mesh.addVertex({kWidth / 2, kDepth, kWall + rise}, 0);
  const auto c = mesh.addVertex({kWidth / 2, kDepth / 2, kWall}, rise);
  mesh.addPolygon({a, b, c}, 0);
  const AttachmentMetric m = attachmentOf(house, 5.0, mesh);
  EXPECT_NEAR(m.shallowAttachedLength, kDepth, 1e-9);
  // Only the ridge's two ends (within tol of the triangle's corners) reach
  // into the gable edges: a sliver of the steep length.
  EXPECT_LT(m.attachedLength, 0.02 * m.steepLength);
  EXPECT_LT(m.edgeShare, 0.02);
}

TEST(ShallowCreases, ACornerOnlyShallowEdgesReachIsMeasuredApart) {
  const double height = 1.0;
  const double crease = pyramidCreaseDeg(height);
  ASSERT_GT(crease, 2.0);
  ASSERT_LT(crease, 10.0);
  const TopoDS_Shape low = pyramid(height);
  const double slant = std::sqrt(2 * (kBase / 2) * (kBase / 2) + height * height);

  const AttachmentMetric at5 = attachmentOf(low, 5.0);
  EXPECT_EQ(at5.convexEdges, 8);
  EXPECT_NEAR(at5.shallowLength, 4 * slant, 1e-6);
  EXPECT_NEAR(at5.steepLength, 4 * kBase, 1e-6);
  EXPECT_EQ(at5.shallowCorners, 1);  // the apex
  EXPECT_EQ(at5.corners, 4);         // the base corners, where the base's edges are steep

  const AttachmentMetric at1 = attachmentOf(low, 1.0);
  EXPECT_EQ(at1.shallowLength, 0);
  EXPECT_EQ(at1.shallowCorners, 0);
  EXPECT_EQ(at1.corners, 5);
}

}  // namespace
}  // namespace cadmedial
