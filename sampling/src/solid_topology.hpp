// Indexed topology of one (closed-face-split) solid and the local geometry
// along its edges that classification and triplet placement share.
#pragma once

#include <array>
#include <vector>

#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>

namespace cadmedial {

struct SolidTopology {
  TopoDS_Shape solid;  // after splitting closed faces
  TopTools_IndexedMapOfShape faces, edges, vertices;  // 1-based OCCT maps; our ids are index-1
  std::vector<std::array<int, 2>> edgeFaces;          // per edge: up to two face ids (-1 if missing)
  std::vector<bool> edgeDegenerate;
  std::vector<std::array<int, 2>> edgeVertices;       // per edge: first/last vertex id
  std::vector<std::vector<int>> vertexEdges;          // per vertex: incident non-degenerate edge ids (an edge closing on itself appears twice)

  const TopoDS_Face& face(int id) const;
  const TopoDS_Edge& edge(int id) const;
  int faceCount() const { return faces.Extent(); }
  int edgeCount() const { return edges.Extent(); }
  int vertexCount() const { return vertices.Extent(); }
};

// Splits periodic/closed faces (cylinder, sphere, torus seams) so every face
// has a simple UV domain, then indexes faces, edges and vertices.
SolidTopology buildSolidTopology(const TopoDS_Shape& solid, bool splitClosedFaces = true);

// Local frame of face `face` at parameter t of `edge`: the point, the edge
// tangent (in the edge's parameter direction), the outward normal of the face
// as it sits in the solid, the unit direction into the face perpendicular to
// the edge, and the UV point.
struct EdgeFaceFrame {
  gp_Pnt point;
  gp_Vec tangent;
  gp_Vec outwardNormal;
  gp_Vec intoFace;
  gp_Pnt2d uv;
  bool valid = false;
};
EdgeFaceFrame edgeFaceFrame(const TopoDS_Edge& edge, const TopoDS_Face& face, double t);

// UV on `face` of the point at 3D-curve parameter t of `edge`. Uses the
// pcurve directly when the edge is SameParameter, otherwise maps t linearly
// onto the pcurve range and refines it so the point matches the 3D curve.
gp_Pnt2d uvOnFace(const TopoDS_Edge& edge, const TopoDS_Face& face, double t);

// Outward normal of `face` (as oriented in the solid) at uv.
gp_Vec outwardNormalAt(const TopoDS_Face& face, const gp_Pnt2d& uv);

}  // namespace cadmedial
