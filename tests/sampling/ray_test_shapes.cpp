#include "ray_test_shapes.hpp"

#include <cmath>

#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <Geom_BezierCurve.hxx>
#include <Bnd_Box.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax1.hxx>
#include <gp_Ax2.hxx>
#include <gp_Elips.hxx>

namespace cadmedial::test {

TopoDS_Shape filletedBox() {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(30.0, 20.0, 10.0).Shape();
  BRepFilletAPI_MakeFillet fillet(box);
  for (TopExp_Explorer e(box, TopAbs_EDGE); e.More(); e.Next()) fillet.Add(2.0, TopoDS::Edge(e.Current()));
  return fillet.Shape();
}

TopoDS_Shape revolvedAndExtruded() {
  const gp_Elips ellipse(gp_Ax2(gp_Pnt(12, 0, 10), gp_Dir(0, 1, 0)), 6.0, 3.0);
  const TopoDS_Face disc =
      BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(ellipse).Edge()).Wire()).Face();
  const TopoDS_Shape ring = BRepPrimAPI_MakeRevol(disc, gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 1.5 * M_PI).Shape();
  TColgp_Array1OfPnt poles(1, 5);
  poles.SetValue(1, gp_Pnt(-8, -5, 0));
  poles.SetValue(2, gp_Pnt(-2, -9, 0));
  poles.SetValue(3, gp_Pnt(6, -4, 0));
  poles.SetValue(4, gp_Pnt(3, 6, 0));
  poles.SetValue(5, gp_Pnt(-8, -5, 0));
  const Handle(Geom_BezierCurve) curve = new Geom_BezierCurve(poles);
  const TopoDS_Face loop =
      BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(curve).Edge()).Wire()).Face();
  return BRepAlgoAPI_Fuse(ring, BRepPrimAPI_MakePrism(loop, gp_Vec(0, 0, 8)).Shape()).Shape();
}

std::vector<gp_Pnt> pointsAround(const TopoDS_Shape& shape, int count, std::mt19937& random) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  std::uniform_real_distribution<double> share(-0.2, 1.2);
  std::vector<gp_Pnt> points;
  for (int k = 0; k < count; ++k)
    points.emplace_back(x0 + (x1 - x0) * share(random), y0 + (y1 - y0) * share(random), z0 + (z1 - z0) * share(random));
  return points;
}

}  // namespace cadmedial::test
