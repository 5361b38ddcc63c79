#include "solid_topology.hpp"

#include <algorithm>
#include <cmath>

#include <BRepAdaptor_Surface.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Curve.hxx>
#include <ShapeUpgrade_ShapeDivideClosed.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

namespace cadmedial {

const TopoDS_Face& SolidTopology::face(int id) const { return TopoDS::Face(faces(id + 1)); }
const TopoDS_Edge& SolidTopology::edge(int id) const { return TopoDS::Edge(edges(id + 1)); }

SolidTopology buildSolidTopology(const TopoDS_Shape& solid, bool splitClosedFaces) {
  SolidTopology topo;
  topo.solid = solid;
  if (splitClosedFaces) {
    ShapeUpgrade_ShapeDivideClosed divide(solid);
    divide.SetNbSplitPoints(1);
    divide.Perform();
    topo.solid = divide.Result();
  }

  TopExp::MapShapes(topo.solid, TopAbs_FACE, topo.faces);
  TopExp::MapShapes(topo.solid, TopAbs_EDGE, topo.edges);
  TopExp::MapShapes(topo.solid, TopAbs_VERTEX, topo.vertices);

  TopTools_IndexedDataMapOfShapeListOfShape edgeToFaces;
  TopExp::MapShapesAndUniqueAncestors(topo.solid, TopAbs_EDGE, TopAbs_FACE, edgeToFaces);

  const int ne = topo.edges.Extent();
  topo.edgeFaces.assign(ne, {-1, -1});
  topo.edgeDegenerate.assign(ne, false);
  topo.edgeVertices.assign(ne, {-1, -1});
  topo.vertexEdges.assign(topo.vertices.Extent(), {});
  for (int e = 0; e < ne; ++e) {
    const TopoDS_Edge& edge = topo.edge(e);
    topo.edgeDegenerate[e] = BRep_Tool::Degenerated(edge);
    int slot = 0;
    if (const TopTools_ListOfShape* fl = edgeToFaces.Seek(edge)) {
      for (const TopoDS_Shape& f : *fl)
        if (slot < 2) topo.edgeFaces[e][slot++] = topo.faces.FindIndex(f) - 1;
    }
    TopoDS_Vertex a, b;
    TopExp::Vertices(edge, a, b);
    topo.edgeVertices[e] = {a.IsNull() ? -1 : topo.vertices.FindIndex(a) - 1,
                            b.IsNull() ? -1 : topo.vertices.FindIndex(b) - 1};
    if (topo.edgeDegenerate[e]) continue;
    for (int v : topo.edgeVertices[e])
      if (v >= 0) topo.vertexEdges[v].push_back(e);
  }
  return topo;
}

namespace {

// Parameter on the pcurve matching 3D-curve parameter t (see uvOnFace).
double pcurveParameter(const TopoDS_Edge& edge, const TopoDS_Face& face, const Handle(Geom2d_Curve)& pcurve,
                       double f2, double l2, double t) {
  double f3, l3;
  Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, f3, l3);
  if (curve.IsNull() || (BRep_Tool::SameParameter(edge) && std::abs(f2 - f3) < 1e-12 && std::abs(l2 - l3) < 1e-12))
    return t;
  double s = (l3 > f3) ? f2 + (t - f3) / (l3 - f3) * (l2 - f2) : t;
  const gp_Pnt target = curve->Value(t);
  BRepAdaptor_Surface surf(face, false);
  // Newton on g(s) = |S(pc(s)) - target|^2 / 2 with a finite-difference second derivative.
  const double h = 1e-7 * std::max(1.0, std::abs(l2 - f2));
  auto gradient = [&](double x) {
    gp_Pnt2d uv;
    gp_Vec2d duv;
    pcurve->D1(x, uv, duv);
    gp_Pnt p;
    gp_Vec su, sv;
    surf.D1(uv.X(), uv.Y(), p, su, sv);
    return gp_Vec(target, p).Dot(su * duv.X() + sv * duv.Y());
  };
  for (int iter = 0; iter < 20; ++iter) {
    const double g = gradient(s);
    const double dg = (gradient(s + h) - gradient(s - h)) / (2 * h);
    if (!(std::abs(dg) > 1e-300)) break;
    const double next = std::clamp(s - g / dg, std::min(f2, l2), std::max(f2, l2));
    if (std::abs(next - s) < 1e-14 * std::max(1.0, std::abs(s))) {
      s = next;
      break;
    }
    s = next;
  }
  return s;
}

}  // namespace

gp_Pnt2d uvOnFace(const TopoDS_Edge& edge, const TopoDS_Face& face, double t) {
  double f2, l2;
  Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, f2, l2);
  if (pcurve.IsNull()) return gp_Pnt2d(0, 0);
  return pcurve->Value(pcurveParameter(edge, face, pcurve, f2, l2, t));
}

gp_Vec outwardNormalAt(const TopoDS_Face& face, const gp_Pnt2d& uv) {
  BRepAdaptor_Surface surf(face, false);
  gp_Pnt p;
  gp_Vec su, sv;
  surf.D1(uv.X(), uv.Y(), p, su, sv);
  gp_Vec n = su.Crossed(sv);
  if (n.Magnitude() < 1e-300) return gp_Vec(0, 0, 0);
  n.Normalize();
  if (face.Orientation() == TopAbs_REVERSED) n.Reverse();
  return n;
}

EdgeFaceFrame edgeFaceFrame(const TopoDS_Edge& edge, const TopoDS_Face& face, double t) {
  EdgeFaceFrame frame;
  // Orientation of the edge in the face's wires, read on the FORWARD face:
  // there the face material lies to the left of the edge in UV.
  TopAbs_Orientation inFace = TopAbs_FORWARD;
  bool found = false;
  for (TopExp_Explorer ex(face.Oriented(TopAbs_FORWARD), TopAbs_EDGE); ex.More(); ex.Next())
    if (ex.Current().IsSame(edge)) {
      inFace = ex.Current().Orientation();
      found = true;
      break;
    }
  if (!found) return frame;

  double f2, l2;
  Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, f2, l2);
  double f3, l3;
  Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, f3, l3);
  if (pcurve.IsNull() || curve.IsNull()) return frame;

  gp_Pnt2d uv;
  gp_Vec2d duv;
  pcurve->D1(pcurveParameter(edge, face, pcurve, f2, l2, t), uv, duv);
  if ((l2 - f2) * (l3 - f3) < 0) duv.Reverse();  // pcurve runs against the 3D curve
  gp_Pnt p3;
  gp_Vec tangent;
  curve->D1(t, p3, tangent);
  if (tangent.Magnitude() < 1e-300) return frame;
  tangent.Normalize();

  BRepAdaptor_Surface surf(face, false);
  gp_Pnt p;
  gp_Vec su, sv;
  surf.D1(uv.X(), uv.Y(), p, su, sv);
  if (inFace == TopAbs_REVERSED) duv.Reverse();
  const gp_Vec2d leftUv(-duv.Y(), duv.X());
  gp_Vec into = su * leftUv.X() + sv * leftUv.Y();
  into -= tangent * into.Dot(tangent);
  if (into.Magnitude() < 1e-300) return frame;
  into.Normalize();

  frame.point = p3;
  frame.tangent = tangent;
  frame.outwardNormal = outwardNormalAt(face, uv);
  frame.intoFace = into;
  frame.uv = uv;
  frame.valid = frame.outwardNormal.Magnitude() > 0.5;
  return frame;
}

}  // namespace cadmedial
