#include "solid_topology.hpp"

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
  pcurve->D1(t, uv, duv);
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
