// SolidRayCaster against OCCT's IntCurvesFace_ShapeIntersector, which it
// replaces for the thickness rays: the same hits (face and parameter along
// the ray) on random rays through shapes with planar, cylindrical, toroidal
// B-spline, revolved and extruded faces, a hole and fillets (random rays pass no closer than
// the tolerances to an edge, where the two may differ). A box test that
// dropped a face the ray meets, or a face order that changed, would show here.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <IntCurvesFace_ShapeIntersector.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include "ray_test_shapes.hpp"
#include "solid_ray_caster.hpp"

using namespace cadmedial;
using cadmedial::test::filletedBox;
using cadmedial::test::revolvedAndExtruded;

namespace {

TopoDS_Shape boxWithHole() {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(40.0, 30.0, 10.0).Shape();
  const TopoDS_Shape hole = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(20, 15, -1), gp_Dir(0, 0, 1)), 6.0, 12.0).Shape();
  return BRepAlgoAPI_Cut(box, hole).Shape();
}



// nearEdgesToo: the caster's intersectors are set up as OCCT's (edges'
// tolerances widen the face), so the hits' states and transitions must
// match too; without it only the hits themselves.
void expectSameHitsAsOcct(const TopoDS_Shape& shape, const char* name, bool nearEdgesToo = false) {
  constexpr double kTolerance = 1e-7;
  IntCurvesFace_ShapeIntersector occt;
  occt.Load(shape, kTolerance);
  SolidRayCaster caster(shape, kTolerance, nearEdgesToo);
  std::mt19937 random(7);
  // Rays from points in the shape's box grown by 20 %.
  const std::vector<gp_Pnt> origins = cadmedial::test::pointsAround(shape, 1500, random);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::vector<SolidRayCaster::Hit> hits;
  std::size_t rays = 0, totalHits = 0;
  for (int k = 0; k < 1500; ++k) {
    const gp_Vec d(unit(random), unit(random), unit(random));
    if (d.Magnitude() < 0.1) continue;
    const gp_Lin line(origins[static_cast<std::size_t>(k)], gp_Dir(d));
    occt.Perform(line, 1e-6, 1e300);
    ASSERT_TRUE(occt.IsDone());
    ASSERT_TRUE(caster.cast(line, 1e-6, 1e300, hits));
    ++rays;
    ASSERT_EQ(hits.size(), static_cast<std::size_t>(occt.NbPnt())) << name << " ray " << k;
    for (int i = 1; i <= occt.NbPnt(); ++i) {
      const SolidRayCaster::Hit& hit = hits[static_cast<std::size_t>(i - 1)];
      EXPECT_NEAR(hit.w, occt.WParameter(i), 1e-9) << name << " ray " << k << " hit " << i;
      EXPECT_TRUE(caster.face(hit.face).IsSame(occt.Face(i))) << name << " ray " << k << " hit " << i;
      if (!nearEdgesToo) continue;
      EXPECT_EQ(hit.transition, occt.Transition(i)) << name << " ray " << k << " hit " << i;
      EXPECT_EQ(hit.onEdge, occt.State(i) == TopAbs_ON) << name << " ray " << k << " hit " << i;
    }
    totalHits += hits.size();
  }
  EXPECT_GT(totalHits, rays / 4) << name;  // many rays pass through the part
}

}  // namespace

TEST(SolidRayCaster, SameHitsAsOcctsShapeIntersector) {
  expectSameHitsAsOcct(boxWithHole(), "box with a hole");
  expectSameHitsAsOcct(filletedBox(), "filleted box");
  expectSameHitsAsOcct(BRepBuilderAPI_NurbsConvert(boxWithHole()).Shape(), "B-spline box with a hole");
  expectSameHitsAsOcct(BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(20, 12, 5), gp_Dir(0, 0, 1)), 15.0, 4.0).Shape(), "torus");
  expectSameHitsAsOcct(revolvedAndExtruded(), "revolved and extruded faces");
  expectSameHitsAsOcct(boxWithHole(), "box with a hole, near edges too", true);
  expectSameHitsAsOcct(BRepBuilderAPI_NurbsConvert(filletedBox()).Shape(), "B-spline filleted box, near edges too", true);
  expectSameHitsAsOcct(revolvedAndExtruded(), "revolved and extruded faces, near edges too", true);
}

// Copies share the faces and boxes and answer alike (one per thread).
TEST(SolidRayCaster, CopiesAnswerAlike) {
  const TopoDS_Shape shape = filletedBox();
  SolidRayCaster first(shape, 1e-7);
  SolidRayCaster copy(first);
  EXPECT_EQ(copy.faceCount(), first.faceCount());
  std::vector<SolidRayCaster::Hit> a, b;
  const gp_Lin line(gp_Pnt(-5, 10, 5), gp_Dir(1, 0, 0));
  ASSERT_TRUE(first.cast(line, 0, 1e300, a));
  ASSERT_TRUE(copy.cast(line, 0, 1e300, b));
  ASSERT_EQ(a.size(), 2u);  // in at x = 0, out at x = 30
  ASSERT_EQ(b.size(), 2u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].face, b[i].face);
    EXPECT_DOUBLE_EQ(a[i].w, b[i].w);
  }
  EXPECT_NEAR(a[0].w, 5.0, 1e-9);
  EXPECT_NEAR(a[1].w, 35.0, 1e-9);
}
