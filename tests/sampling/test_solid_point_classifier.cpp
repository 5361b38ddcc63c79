// SolidPointClassifier against BRepClass3d_SolidClassifier, which it stands
// in for (corner probes, the pair-mesh's exact cell labels): the same state
// (IN, OUT, ON) for random points in and around shapes with planar,
// cylindrical, toroidal, B-spline, revolved and extruded faces, holes, a
// void and fillets, and for points
// on their faces, edges and vertices and just off them. Most answers must
// come from its own rays, not from the OCCT classifier it falls back to.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include "ray_test_shapes.hpp"
#include "solid_point_classifier.hpp"

using namespace cadmedial;
using cadmedial::test::filletedBox;
using cadmedial::test::revolvedAndExtruded;

namespace {

TopoDS_Shape plateWithHoles() {  // 16 holes: faces with many wires
  TopoDS_Shape plate = BRepPrimAPI_MakeBox(40.0, 40.0, 6.0).Shape();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      plate = BRepAlgoAPI_Cut(plate, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(5 + 10 * i, 5 + 10 * j, -1), gp_Dir(0, 0, 1)),
                                                               2.0 + 0.3 * j, 8.0)
                                         .Shape())
                  .Shape();
  return plate;
}


// Random points in the box grown by 20 %, points on faces (at their UV
// box's interior points that the face holds), on edges and at vertices, and
// each of those moved off by 1e-3 and 1e-12 along a random direction.
std::vector<gp_Pnt> probePoints(const TopoDS_Shape& shape, std::mt19937& random) {
  std::uniform_real_distribution<double> unit(0, 1), signedUnit(-1, 1);
  std::vector<gp_Pnt> points = cadmedial::test::pointsAround(shape, 600, random), onBoundary;
  for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) {
    const TopoDS_Face& face = TopoDS::Face(f.Current());
    const BRepAdaptor_Surface surface(face);
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    for (int k = 0; k < 6; ++k) onBoundary.push_back(surface.Value(u0 + (u1 - u0) * unit(random), v0 + (v1 - v0) * unit(random)));
  }
  for (TopExp_Explorer e(shape, TopAbs_EDGE); e.More(); e.Next()) {
    const BRepAdaptor_Curve curve(TopoDS::Edge(e.Current()));
    onBoundary.push_back(curve.Value(curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * unit(random)));
  }
  for (TopExp_Explorer v(shape, TopAbs_VERTEX); v.More(); v.Next()) onBoundary.push_back(BRep_Tool::Pnt(TopoDS::Vertex(v.Current())));
  for (const gp_Pnt& p : onBoundary) {
    points.push_back(p);
    for (double step : {1e-3, 1e-12}) {
      gp_Vec d(signedUnit(random), signedUnit(random), signedUnit(random));
      if (d.Magnitude() < 1e-3) continue;
      points.push_back(p.Translated(d.Normalized() * step));
    }
  }
  return points;
}


TopoDS_Shape boxWithVoid() {  // two shells: the outer box and a spherical void
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(30.0, 30.0, 30.0).Shape();
  return BRepAlgoAPI_Cut(box, BRepPrimAPI_MakeSphere(gp_Pnt(15, 15, 15), 8.0).Shape()).Shape();
}

void expectSameStatesAsOcct(const TopoDS_Shape& shape, const char* name, bool inverted = false) {
  std::mt19937 random(3);
  SolidPointClassifier ours(shape);
  BRepClass3d_SolidClassifier occt(shape);
  std::size_t asked = 0, inside = 0, on = 0;
  for (const gp_Pnt& p : probePoints(shape, random)) {
    occt.Perform(p, 1e-9);
    const TopAbs_State expected = occt.State();
    EXPECT_EQ(ours.classify(p, 1e-9), expected) << name << " at " << p.X() << ", " << p.Y() << ", " << p.Z();
    ++asked;
    inside += expected == TopAbs_IN;
    on += expected == TopAbs_ON;
  }
  EXPECT_GT(on, 20u) << name;
  if (inverted) {
    EXPECT_GE(ours.fallbacks(), asked - on) << name;  // all but ON at an edge or vertex: OCCT's
  } else {
    EXPECT_GT(inside, asked / 10) << name;
    EXPECT_LT(ours.fallbacks(), asked / 20) << name;  // the rays answer nearly all
  }
}

}  // namespace

TEST(SolidPointClassifier, SameStatesAsOcctsClassifier) {
  expectSameStatesAsOcct(plateWithHoles(), "plate with 16 holes");
  expectSameStatesAsOcct(filletedBox(), "filleted box");
  expectSameStatesAsOcct(BRepBuilderAPI_NurbsConvert(filletedBox()).Shape(), "B-spline filleted box");
  expectSameStatesAsOcct(BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(1, 2, 3), gp_Dir(0, 0, 1)), 15.0, 4.0).Shape(), "torus");
  expectSameStatesAsOcct(revolvedAndExtruded(), "revolved and extruded faces");
  expectSameStatesAsOcct(boxWithVoid(), "box with a spherical void");
}

// A solid turned inside out (every face reversed): OCCT's classifier
// answers every query, so the states stay its own.
TEST(SolidPointClassifier, InvertedSolidIsLeftToOcct) {
  expectSameStatesAsOcct(filletedBox().Reversed(), "reversed filleted box", /*inverted=*/true);
}
