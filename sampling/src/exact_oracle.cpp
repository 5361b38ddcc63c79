#include "cadmedial/exact_oracle.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <random>
#include <stdexcept>
#include <unordered_map>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Extrema_ExtPC.hxx>
#include <Extrema_ExtPS.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomAbs_SurfaceType.hxx>
#include <Extrema_GenLocateExtPS.hxx>
#include <Poly_Triangulation.hxx>
#include <Precision.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "face_uv_classifier.hpp"
#include "feature_classification.hpp"
#include "solid_topology.hpp"
#include "surface_newton.hpp"

namespace cadmedial {

namespace {


// Closest point of triangle abc to p (Ericson, Real-Time Collision
// Detection 5.1.5), as barycentric weights of a, b, c.
std::array<double, 3> closestBarycentric(const gp_XYZ& p, const gp_XYZ& a, const gp_XYZ& b, const gp_XYZ& c) {
  const gp_XYZ ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab * ap, d2 = ac * ap;
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const gp_XYZ bp = p - b;
  const double d3 = ab * bp, d4 = ac * bp;
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const gp_XYZ cp = p - c;
  const double d5 = ab * cp, d6 = ac * cp;
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {1 - v - w, v, w};
}

double boxDistance(const Bnd_Box& box, const gp_Pnt& p) {
  if (box.IsVoid()) return std::numeric_limits<double>::infinity();
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  const double dx = std::max({x0 - p.X(), 0.0, p.X() - x1});
  const double dy = std::max({y0 - p.Y(), 0.0, p.Y() - y1});
  const double dz = std::max({z0 - p.Z(), 0.0, p.Z() - z1});
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

using Triangle = std::array<gp_XYZ, 3>;

// Bounding-volume hierarchy over the mesh triangles. One traversal per query
// visits every triangle within (nearest mesh distance + extra), nearest boxes
// first, so the radius shrinks as soon as a close triangle is seen.
class TriangleTree {
 public:
  void build(const std::vector<Triangle>& triangles) {
    order_.resize(triangles.size());
    for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
    nodes_.clear();
    if (triangles.empty()) return;
    nodes_.emplace_back();
    buildNode(triangles, 0, 0, static_cast<std::uint32_t>(triangles.size()));
  }

  // visit(t) returns the distance from the query point to triangle t; the
  // traversal skips boxes farther than (smallest distance seen + extra).
  template <class Visit>
  void query(const gp_XYZ& p, double extra, std::vector<std::pair<double, std::uint32_t>>& stack,
             Visit&& visit) const {
    if (nodes_.empty()) return;
    double best = std::numeric_limits<double>::infinity();
    stack.clear();
    stack.emplace_back(boxDistance(nodes_[0], p), 0);
    while (!stack.empty()) {
      const auto [d, i] = stack.back();
      stack.pop_back();
      if (d > best + extra) continue;
      const Node& node = nodes_[i];
      if (node.left == 0) {
        for (std::uint32_t k = node.begin; k < node.end; ++k) best = std::min(best, visit(order_[k]));
        continue;
      }
      const double l = boxDistance(nodes_[node.left], p), r = boxDistance(nodes_[node.left + 1], p);
      if (l < r) {
        stack.emplace_back(r, node.left + 1);
        stack.emplace_back(l, node.left);
      } else {
        stack.emplace_back(l, node.left);
        stack.emplace_back(r, node.left + 1);
      }
    }
  }

 private:
  struct Node {
    gp_XYZ lo, hi;
    std::uint32_t begin = 0, end = 0;
    std::uint32_t left = 0;  // children at left and left + 1; 0 for a leaf
  };
  static double boxDistance(const Node& n, const gp_XYZ& p) {
    double s = 0;
    for (int k = 1; k <= 3; ++k) {
      const double d = std::max({n.lo.Coord(k) - p.Coord(k), 0.0, p.Coord(k) - n.hi.Coord(k)});
      s += d * d;
    }
    return std::sqrt(s);
  }
  // Fills nodes_[id] (already allocated) and, above 4 triangles, splits at
  // the median centroid along the longest axis of the centroids' box.
  void buildNode(const std::vector<Triangle>& tris, std::uint32_t id, std::uint32_t begin, std::uint32_t end) {
    Node node;
    node.begin = begin;
    node.end = end;
    node.lo = node.hi = tris[order_[begin]][0];
    gp_XYZ clo = (tris[order_[begin]][0] + tris[order_[begin]][1] + tris[order_[begin]][2]) / 3, chi = clo;
    for (std::uint32_t k = begin; k < end; ++k) {
      const Triangle& t = tris[order_[k]];
      for (const gp_XYZ& v : t) {
        node.lo.SetCoord(std::min(node.lo.X(), v.X()), std::min(node.lo.Y(), v.Y()), std::min(node.lo.Z(), v.Z()));
        node.hi.SetCoord(std::max(node.hi.X(), v.X()), std::max(node.hi.Y(), v.Y()), std::max(node.hi.Z(), v.Z()));
      }
      const gp_XYZ c = (t[0] + t[1] + t[2]) / 3;
      clo.SetCoord(std::min(clo.X(), c.X()), std::min(clo.Y(), c.Y()), std::min(clo.Z(), c.Z()));
      chi.SetCoord(std::max(chi.X(), c.X()), std::max(chi.Y(), c.Y()), std::max(chi.Z(), c.Z()));
    }
    nodes_[id] = node;
    if (end - begin <= 4) return;
    const gp_XYZ extent = chi - clo;
    const int axis = extent.X() >= extent.Y() && extent.X() >= extent.Z() ? 1 : (extent.Y() >= extent.Z() ? 2 : 3);
    const std::uint32_t mid = begin + (end - begin) / 2;
    auto key = [&](std::uint32_t t) { return tris[t][0].Coord(axis) + tris[t][1].Coord(axis) + tris[t][2].Coord(axis); };
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
    const std::uint32_t left = static_cast<std::uint32_t>(nodes_.size());
    nodes_[id].left = left;
    nodes_.emplace_back();
    nodes_.emplace_back();
    buildNode(tris, left, begin, mid);
    buildNode(tris, left + 1, mid, end);
  }
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
};

}  // namespace

// Everything built once per solid and never changed afterwards; shared by
// all copies of an oracle (read-only, so safe across threads).
struct ExactOracle::Shared {
  TopoDS_Shape solid;  // copy of the input (so meshing never touches the caller's shape)
  // Not split: ShapeUpgrade_ShapeDivideClosed approximates some new edges
  // (B-splines within 1e-5 on a torus), which would no longer be exact.
  SolidTopology topo;
  std::vector<std::vector<int>> faceEdges, faceVertices;
  std::vector<gp_Pnt> vertexPoint;
  std::vector<std::vector<gp_Vec>> vertexTangents;  // unit tangents of the edges leaving each vertex
  std::vector<Bnd_Box> edgeBox, faceBox;
  // Per edge: +1 convex, -1 concave, 0 smooth / seam / mixed. A closest point
  // inside a convex edge means the empty ball around p touches a wedge of
  // material narrower than a half-space there, so p is outside (concave:
  // inside), without looking at any normal.
  std::vector<int> edgeSide;
  // Per edge: the surface is smooth across it (a seam, or the tangent edge
  // of a fillet): a closest point inside it has the normal of either face.
  std::vector<bool> edgeSmooth;
  std::vector<bool> faceMeshed;
  std::vector<Triangle> triangles;                   // mesh
  std::vector<int> triangleFace;                     // per triangle
  std::vector<std::array<gp_Pnt2d, 3>> triangleUV;   // per triangle, UV of its corners on its face
  std::vector<bool> faceHasUV;
  std::vector<double> cumulativeArea;                // for area-uniform boundary samples
  TriangleTree tree;
  double deflection = 0;  // largest mesh deflection (requested or reported by BRepMesh)
  double margin = 0;      // assumed bound on |exact − mesh| distance to one face
  // Per face, its mesh's area, and whether meshSide may trust the mesh
  // there: -1 not yet known, 0 no, 1 yes (faceMeshMatches; set once, by
  // whichever thread asks first: every thread computes the same answer).
  std::vector<double> faceMeshArea;
  std::unique_ptr<std::atomic<signed char>[]> faceMeshTrusted;
  // meshSide's preconditions on the whole mesh, found on its first call
  // (eval never asks): closed and consistently oriented outward (so every
  // face is meshed), and the largest B-rep tolerance (the mesh's edge nodes
  // lie on 3D curves).
  mutable std::once_flag meshCheckedOnce;
  mutable bool meshClosedOutward = false;
  mutable double largestTolerance = 0;
  double diagonal = 0;
  gp_Pnt boxMin, boxMax;
  bool inwardFaces = false;  // faces oriented inside-out (negative volume)
};

struct FaceSolver {
  BRepAdaptor_Surface surface;
  Extrema_ExtPS extrema;
  Extrema_GenLocateExtPS locate;  // holds a reference to `surface`
  FaceUVClassifier uvClassifier;
  bool hasSeam = false;
  // Plane, cylinder, cone, sphere, torus: Extrema_ExtPS solves these in
  // closed form. On the others (B-spline, Bézier, offset, swept) it searches
  // a grid at every call, milliseconds each: eval never finished on a box
  // with variable fillets (21 k samples, > 900 s) or a swept helix.
  bool analytic = false;
  explicit FaceSolver(const TopoDS_Face& face)
      : surface(face, true), locate(surface), uvClassifier(face, Precision::PConfusion()) {
    const GeomAbs_SurfaceType type = surface.GetType();
    analytic = type == GeomAbs_Plane || type == GeomAbs_Cylinder || type == GeomAbs_Cone ||
               type == GeomAbs_Sphere || type == GeomAbs_Torus;
    for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More() && !hasSeam; ex.Next())
      hasSeam = BRep_Tool::IsClosed(TopoDS::Edge(ex.Current()), face);
    extrema.Initialize(surface, surface.FirstUParameter(), surface.LastUParameter(), surface.FirstVParameter(),
                       surface.LastVParameter(), Precision::PConfusion(), Precision::PConfusion());
  }
  TopAbs_State state(double u, double v) const { return uvClassifier.Perform(gp_Pnt2d(u, v)); }
  // The extremum a local solver reaches from (u0, v0): with `byDistance`
  // the distance minimised within the UV bounds (OCCT's
  // Extrema_GenLocateExtPS); otherwise a root of the normal-projection
  // equations, by plain Newton when it settles on a critical point (tens of
  // times cheaper, see surface_newton.hpp), else by OCCT. With
  // `stopPastBounds`, Newton leaving the UV bounds ends the search (false):
  // for callers that take the face's boundary from its edges.
  bool locateFrom(const gp_Pnt& p, double u0, double v0, bool byDistance, SurfaceFoot& foot,
                  bool stopPastBounds = false) {
    if (!byDistance) {
      const NewtonResult r = newtonFoot(surface, p, u0, v0, foot);
      if (r == NewtonResult::Converged && critical(p, foot.u, foot.v)) return true;
      if (r == NewtonResult::LeftBounds && stopPastBounds) return false;
    }
    locate.Perform(p, u0, v0, byDistance);
    if (!locate.IsDone()) return false;
    locate.Point().Parameter(foot.u, foot.v);
    foot.point = locate.Point().Value();
    return true;
  }
  // p − S(u, v) is normal to the surface: a true extremum, not a point where
  // a Newton run stopped at the UV bounds.
  bool critical(const gp_Pnt& p, double u, double v) const {
    gp_Pnt q;
    gp_Vec su, sv;
    surface.D1(u, v, q, su, sv);
    const gp_Vec r(q, p);
    const double tol = 1e-7 * r.Magnitude();
    return std::abs(r.Dot(su)) <= tol * su.Magnitude() && std::abs(r.Dot(sv)) <= tol * sv.Magnitude();
  }
  // No point a small UV step away in the 8 directions is nearer to p than
  // S(u, v), up to a relative 1e-9: a local minimum of the distance, or a
  // degenerate one (from the centre of a swept tube, every point of the
  // cross-section circle is as near: OCCT's IsMinDist said no there, and
  // such a query then ran the global grid search: on a helical spring 65 %
  // of the B-spline face queries did, 6 % with this test). A saddle or
  // maximum has a direction in which the distance drops by about the
  // curvature times the step squared. For
  // the nearest point only: where all near contacts are wanted (two
  // contacts), OCCT's stricter test keeps sending such points to the global
  // search, which finds the other walls of a U-shaped face (with this test
  // there, the variable-fillet box's two-contact share fell 92.4 -> 89.5 %).
  bool localMinimum(const gp_Pnt& p, double u, double v) const {
    const double d2 = p.SquareDistance(surface.Value(u, v));
    const double du = 1e-3 * (surface.LastUParameter() - surface.FirstUParameter());
    const double dv = 1e-3 * (surface.LastVParameter() - surface.FirstVParameter());
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j) {
        if (i == 0 && j == 0) continue;
        const double a = std::clamp(u + i * du, surface.FirstUParameter(), surface.LastUParameter());
        const double b = std::clamp(v + j * dv, surface.FirstVParameter(), surface.LastVParameter());
        if (p.SquareDistance(surface.Value(a, b)) < d2 * (1 - 1e-9)) return false;
      }
    return true;
  }
  // A point where the surface is smooth: inside the face, or on one of its
  // seams (ON, but IN a small step away in all four UV directions).
  bool smoothPoint(TopAbs_State s, double u, double v) const {
    if (s == TopAbs_IN) return true;
    if (s != TopAbs_ON || !hasSeam) return false;
    const double du = 1e-7 * (surface.LastUParameter() - surface.FirstUParameter());
    const double dv = 1e-7 * (surface.LastVParameter() - surface.FirstVParameter());
    return state(u + du, v) == TopAbs_IN && state(u - du, v) == TopAbs_IN && state(u, v + dv) == TopAbs_IN &&
           state(u, v - dv) == TopAbs_IN;
  }
};

struct EdgeSolver {
  BRepAdaptor_Curve curve;
  Extrema_ExtPC extrema;
  explicit EdgeSolver(const TopoDS_Edge& edge) : curve(edge) {
    extrema.Initialize(curve, curve.FirstParameter(), curve.LastParameter());
  }
};

// Solver objects and scratch buffers of one oracle copy.
struct ExactOracle::Workspace {
  std::vector<std::unique_ptr<FaceSolver>> faces;
  std::vector<std::unique_ptr<EdgeSolver>> edges;
  std::unique_ptr<BRepClass3d_SolidClassifier> classifier;
  std::size_t classifierQueries = 0;
  // Per-query marks (a stamp instead of clearing arrays every query).
  std::uint32_t stamp = 0;
  std::vector<std::uint32_t> faceStamp, edgeStamp, vertexStamp;
  std::vector<double> faceMeshDistance;
  std::vector<gp_Pnt2d> faceMeshUV;
  std::vector<std::pair<double, std::uint32_t>> stack;  // tree traversal
  // (mesh distance, triangle) near the best: Newton starts.
  std::vector<std::pair<double, std::uint32_t>> band;
  std::vector<std::uint32_t> faceBand;  // the band's triangles on one face
  std::vector<std::pair<double, int>> candidates;  // (lower bound of exact distance, face)
  // The last query's closest point when the surface is smooth there (inside
  // a face or on a seam): its outward normal then decides inside/outside
  // without the classifier.
  int bestFace = -1;
  double bestU = 0, bestV = 0;
  // ... or when it is inside a sharp edge: +1 convex (p is outside), -1 concave (inside), 0 unknown.
  int bestEdgeSide = 0;
  // ... or when it is inside a smooth edge (edgeSmooth): the edge, and the
  // point's parameter on it.
  int bestSmoothEdge = -1;
  double bestT = 0;
};

ExactOracle::ExactOracle(const TopoDS_Shape& solid, const ExactOracleParams& params) {
  auto shared = std::make_shared<Shared>();
  Shared& s = *shared;
  s.solid = BRepBuilderAPI_Copy(solid, false, false).Shape();
  s.topo = buildSolidTopology(s.solid, false);
  const SolidTopology& topo = s.topo;

  Bnd_Box box;
  BRepBndLib::AddOptimal(s.solid, box, false, false);
  if (box.IsVoid()) throw std::runtime_error("exact oracle: the solid has no geometry");
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  s.boxMin = gp_Pnt(x0, y0, z0);
  s.boxMax = gp_Pnt(x1, y1, z1);
  s.diagonal = s.boxMin.Distance(s.boxMax);

  GProp_GProps volume;
  BRepGProp::VolumeProperties(s.solid, volume);
  s.inwardFaces = volume.Mass() < 0;

  const int nf = topo.faceCount(), ne = topo.edgeCount(), nv = topo.vertexCount();
  s.faceEdges.resize(nf);
  s.faceVertices.resize(nf);
  for (int e = 0; e < ne; ++e) {
    if (topo.edgeDegenerate[e]) continue;
    for (int f : topo.edgeFaces[e])
      if (f >= 0) s.faceEdges[f].push_back(e);
  }
  for (int f = 0; f < nf; ++f) {
    for (TopExp_Explorer ex(topo.face(f), TopAbs_VERTEX); ex.More(); ex.Next()) {
      const int v = topo.vertices.FindIndex(ex.Current()) - 1;
      if (v >= 0 && std::find(s.faceVertices[f].begin(), s.faceVertices[f].end(), v) == s.faceVertices[f].end())
        s.faceVertices[f].push_back(v);
    }
  }
  for (int v = 0; v < nv; ++v) s.vertexPoint.push_back(BRep_Tool::Pnt(TopoDS::Vertex(topo.vertices(v + 1))));
  s.vertexTangents.resize(nv);
  for (int e = 0; e < ne; ++e) {
    if (topo.edgeDegenerate[e]) continue;
    BRepAdaptor_Curve curve(topo.edge(e));
    for (int end = 0; end < 2; ++end) {
      const int v = topo.edgeVertices[e][end];
      if (v < 0) continue;
      gp_Pnt q;
      gp_Vec d;
      curve.D1(end == 0 ? curve.FirstParameter() : curve.LastParameter(), q, d);
      if (d.Magnitude() < 1e-300) continue;
      s.vertexTangents[v].push_back(end == 0 ? d.Normalized() : -d.Normalized());
    }
  }
  // Exact (conservative) boxes from the curves, slightly enlarged: used to
  // skip edges and unmeshed faces that cannot beat the current best.
  const double pad = 1e-7 * s.diagonal;
  s.edgeBox.resize(ne);
  for (int e = 0; e < ne; ++e) {
    if (topo.edgeDegenerate[e]) continue;
    BRepBndLib::Add(topo.edge(e), s.edgeBox[e], false);
    s.edgeBox[e].Enlarge(pad);
  }
  s.faceBox.resize(nf);
  for (int f = 0; f < nf; ++f) {
    BRepBndLib::Add(topo.face(f), s.faceBox[f], false);
    s.faceBox[f].Enlarge(pad);
  }

  const std::vector<EdgeFeature> features = classifyEdges(topo, 1.0);
  s.edgeSide.assign(ne, 0);
  s.edgeSmooth.assign(ne, false);
  for (int e = 0; e < ne; ++e) {
    const EdgeFeature& f = features[e];
    if (f.free || f.mixedSign || topo.edgeDegenerate[e]) continue;
    s.edgeSmooth[e] = f.seam || (f.kind == EdgeKind::Smooth && f.validProbes > 0);
    if (f.seam) continue;
    s.edgeSide[e] = f.kind == EdgeKind::Convex ? 1 : f.kind == EdgeKind::Concave ? -1 : 0;
  }

  const double deflection = params.meshDeflectionFraction * s.diagonal;
  BRepMesh_IncrementalMesh mesher(topo.solid, deflection, false, params.meshAngle, true);
  s.deflection = deflection;
  s.faceMeshed.assign(nf, false);
  s.faceHasUV.assign(nf, false);
  s.faceMeshArea.assign(nf, 0.0);
  s.faceMeshTrusted = std::make_unique<std::atomic<signed char>[]>(nf);
  for (int f = 0; f < nf; ++f) s.faceMeshTrusted[f] = -1;
  double area = 0;
  for (int f = 0; f < nf; ++f) {
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(topo.face(f), loc);
    if (tri.IsNull() || tri->NbTriangles() == 0) continue;
    s.faceMeshed[f] = true;
    s.faceHasUV[f] = tri->HasUVNodes();
    s.deflection = std::max(s.deflection, tri->Deflection());
    const gp_Trsf trsf = loc.Transformation();
    for (int t = 1; t <= tri->NbTriangles(); ++t) {
      int n[3];
      tri->Triangle(t).Get(n[0], n[1], n[2]);
      gp_Pnt p[3];
      std::array<gp_Pnt2d, 3> uv;
      for (int k = 0; k < 3; ++k) {
        p[k] = tri->Node(n[k]).Transformed(trsf);
        if (s.faceHasUV[f]) uv[k] = tri->UVNode(n[k]);
      }
      const double a = 0.5 * gp_Vec(p[0], p[1]).Crossed(gp_Vec(p[0], p[2])).Magnitude();
      if (!(a > 0)) continue;  // degenerate: its edges belong to neighbours anyway
      s.triangles.push_back({p[0].XYZ(), p[1].XYZ(), p[2].XYZ()});
      s.triangleFace.push_back(f);
      s.triangleUV.push_back(uv);
      area += a;
      s.cumulativeArea.push_back(area);
      s.faceMeshArea[f] += a;
    }
  }
  s.tree.build(s.triangles);
  s.margin = params.candidateDeflections / 2.0 * s.deflection;

  shared_ = shared;
  work_ = std::make_unique<Workspace>();
}

ExactOracle::ExactOracle(const ExactOracle& other) : shared_(other.shared_), work_(std::make_unique<Workspace>()) {}

ExactOracle::~ExactOracle() = default;

double ExactOracle::diagonal() const { return shared_->diagonal; }
gp_Pnt ExactOracle::boxMin() const { return shared_->boxMin; }
gp_Pnt ExactOracle::boxMax() const { return shared_->boxMax; }
double ExactOracle::meshDeflection() const { return shared_->deflection; }
std::size_t ExactOracle::meshTriangles() const { return shared_->triangles.size(); }
int ExactOracle::faceCount() const { return shared_->topo.faceCount(); }
int ExactOracle::unmeshedFaces() const {
  return static_cast<int>(std::count(shared_->faceMeshed.begin(), shared_->faceMeshed.end(), false));
}
const TopoDS_Shape& ExactOracle::solid() const { return shared_->solid; }

bool ExactOracle::inside(const gp_Pnt& p, double onTolerance, double* distance) {
  // Fast path: when the closest point is a smooth point of the surface
  // (inside a face, or inside a seam or a tangent edge), p − foot is along
  // the surface normal there, and its sign is the answer (the classifier
  // costs 10-100 times a distance query on parts with many faces).
  const BoundaryPoint foot = closestPoint(p);
  if (distance) *distance = foot.distance;
  if (foot.distance <= onTolerance) return true;
  Workspace& w = *work_;
  const Shared& s = *shared_;
  if (w.bestEdgeSide != 0) return w.bestEdgeSide < 0;
  // -1 inside, +1 outside, 0 when p − foot is not clearly along face f's
  // normal at S(u, v) (the foot itself, or within the edge's tolerance of
  // it when the foot is on an edge).
  auto sideByNormal = [&](int f, double u, double v) {
    if (!w.faces[f]) w.faces[f] = std::make_unique<FaceSolver>(s.topo.face(f));
    gp_Pnt q;
    gp_Vec su, sv;
    w.faces[f]->surface.D1(u, v, q, su, sv);
    const gp_Vec n = su.Crossed(sv);
    if (n.Magnitude() <= 1e-300) return 0;
    const bool reversed = (s.topo.face(f).Orientation() == TopAbs_REVERSED) != s.inwardFaces;
    const double side = gp_Vec(foot.point, p).Dot(n.Normalized()) * (reversed ? -1 : 1);
    if (std::abs(side) < 0.99 * foot.distance) return 0;
    return side < 0 ? -1 : 1;
  };
  // Across a smooth edge: both faces' normals, which must agree (a seam's
  // two pcurves give the same point and normal); 0 when either cannot tell.
  auto sideAcrossSmoothEdge = [&](int e) {
    const TopoDS_Edge& edge = s.topo.edge(e);
    int agreed = 0;
    for (int f : s.topo.edgeFaces[e]) {
      if (f < 0) continue;
      double first, last;
      const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, s.topo.face(f), first, last);
      if (pcurve.IsNull()) return 0;
      const gp_Pnt2d uv = pcurve->Value(w.bestT);
      const int side = sideByNormal(f, uv.X(), uv.Y());
      if (side == 0 || (agreed != 0 && side != agreed)) return 0;
      agreed = side;
    }
    return agreed;
  };
  if (w.bestFace >= 0) {
    if (const int side = sideByNormal(w.bestFace, w.bestU, w.bestV)) return side < 0;
  } else if (w.bestSmoothEdge >= 0 && BRep_Tool::SameParameter(s.topo.edge(w.bestSmoothEdge)) &&
             foot.distance > 4 * BRep_Tool::Tolerance(s.topo.edge(w.bestSmoothEdge))) {
    // Not within a few edge tolerances of the edge, where the pcurves'
    // points may be as far from the foot as p is.
    if (const int side = sideAcrossSmoothEdge(w.bestSmoothEdge)) return side < 0;
  }
  ++w.classifierQueries;
  if (!work_->classifier) work_->classifier = std::make_unique<BRepClass3d_SolidClassifier>(shared_->solid);
  work_->classifier->Perform(p, onTolerance);
  const TopAbs_State state = work_->classifier->State();
  return state == TopAbs_IN || state == TopAbs_ON;
}

namespace {

// The mesh's triangles wound outward (BRepMesh winds them along the face's
// parameters: reversed on a REVERSED face, and all of them on a solid whose
// faces point inward).
bool faceWoundInward(const TopoDS_Face& face, bool inwardFaces) {
  return (face.Orientation() == TopAbs_REVERSED) != inwardFaces;
}

// Closed and consistently oriented: with corners identified by their exact
// coordinates (BRepMesh puts the nodes of an edge shared by two faces at the
// same points), every directed edge of an outward-wound triangle appears
// once and its reverse once. A face mesh that ignores a hole of its face,
// or leaves one, fails this. (Triangles without area were left out of the
// mesh: those with two corners at one point, at poles, leave no edge
// unmatched; a sliver with three distinct collinear corners does, and
// then meshSide never decides.)
bool closedAndOutward(const std::vector<Triangle>& triangles, const std::vector<int>& triangleFace,
                      const SolidTopology& topo, bool inwardFaces) {
  struct Hash {
    std::size_t operator()(const std::array<double, 3>& v) const {
      std::size_t h = 0;
      for (double x : v) h = h * 1000003u ^ std::hash<double>()(x);
      return h;
    }
  };
  std::unordered_map<std::array<double, 3>, std::uint32_t, Hash> ids;
  ids.reserve(triangles.size());
  auto id = [&](const gp_XYZ& p) {
    return ids.emplace(std::array<double, 3>{p.X(), p.Y(), p.Z()}, static_cast<std::uint32_t>(ids.size()))
        .first->second;
  };
  std::unordered_map<std::uint64_t, int> directed;  // (from, to) -> uses
  directed.reserve(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    std::array<std::uint32_t, 3> v{id(triangles[t][0]), id(triangles[t][1]), id(triangles[t][2])};
    if (faceWoundInward(topo.face(triangleFace[t]), inwardFaces)) std::swap(v[1], v[2]);
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = v[k], b = v[(k + 1) % 3];
      if (a == b) return false;
      if (++directed[std::uint64_t(a) << 32 | b] > 1) return false;
    }
  }
  for (const auto& [key, uses] : directed)
    if (directed.find(key << 32 | key >> 32) == directed.end()) return false;
  return true;
}

double largestTolerance(const TopoDS_Shape& solid) {
  double tolerance = 0;
  for (TopExp_Explorer x(solid, TopAbs_FACE); x.More(); x.Next())
    tolerance = std::max(tolerance, BRep_Tool::Tolerance(TopoDS::Face(x.Current())));
  for (TopExp_Explorer x(solid, TopAbs_EDGE); x.More(); x.Next())
    tolerance = std::max(tolerance, BRep_Tool::Tolerance(TopoDS::Edge(x.Current())));
  for (TopExp_Explorer x(solid, TopAbs_VERTEX); x.More(); x.Next())
    tolerance = std::max(tolerance, BRep_Tool::Tolerance(TopoDS::Vertex(x.Current())));
  return tolerance;
}

// A face's mesh covers the face and nothing else when its area is the
// face's to 5 %: one that misread a wire (covering a hole, or leaving
// part of the face out) would put triangles where the solid has no
// boundary, and a side read from them would be wrong. (Chords of a face
// curved on the scale of the deflection miss a few per cent.)
bool faceMeshMatches(const TopoDS_Face& face, double meshArea) {
  GProp_GProps props;
  BRepGProp::SurfaceProperties(face, props);
  const double exact = props.Mass();
  return exact > 0 && std::abs(meshArea / exact - 1) <= 0.05;
}

}  // namespace

int ExactOracle::meshSide(const gp_Pnt& p, double margins) {
  const Shared& s = *shared_;
  Workspace& w = *work_;
  // The mesh closed and wound outward, or sides read from it mean nothing
  // (a face left unmeshed leaves its neighbours' edges unmatched).
  if (s.triangles.empty()) return 0;
  std::call_once(s.meshCheckedOnce, [&s] {
    s.meshClosedOutward = closedAndOutward(s.triangles, s.triangleFace, s.topo, s.inwardFaces);
    s.largestTolerance = largestTolerance(s.solid);
  });
  if (!s.meshClosedOutward) return 0;
  if (w.faces.size() != static_cast<std::size_t>(s.topo.faceCount())) w.faces.resize(s.topo.faceCount());
  const gp_XYZ px = p.XYZ();
  // The nearest triangles: all within rounding of the nearest distance, so
  // that a foot on a mesh edge or vertex comes with every triangle at it
  // (a box is skipped only when farther than the running best + rounding).
  const double rounding = 1e-9 * s.diagonal;
  double best = std::numeric_limits<double>::infinity();
  w.band.clear();
  s.tree.query(px, rounding, w.stack, [&](std::uint32_t t) {
    const Triangle& tri = s.triangles[t];
    const std::array<double, 3> b = closestBarycentric(px, tri[0], tri[1], tri[2]);
    const double d = (px - (b[0] * tri[0] + b[1] * tri[1] + b[2] * tri[2])).Modulus();
    best = std::min(best, d);
    if (d <= best + rounding) w.band.emplace_back(d, t);
    return d;
  });
  // Farther from the mesh than the mesh can be from the exact surface: its
  // deflection, and the tolerance by which its edge nodes (on the 3D
  // curves) may miss the faces.
  if (!(best > std::max(margins * s.margin, 4 * s.largestTolerance))) return 0;
  // The side of the closed mesh at its nearest point q: the sign of
  // (p − q) · N with N the angle-weighted pseudo-normal at q (Bærentzen &
  // Aanæs 2005): the sum over the triangles at q of their outward normals,
  // each weighted by its angle at q (π when q is inside an edge, the
  // triangle alone when q is inside it). Triangles equally near with
  // another foot (p equidistant from two places) must give the same side.
  struct Foot {
    gp_XYZ point;
    gp_Vec normal;  // the weighted sum
  };
  std::vector<Foot> feet;
  for (const auto& [d, t] : w.band) {
    if (d > best + rounding) continue;
    const Triangle& tri = s.triangles[t];
    const int f = s.triangleFace[t];
    gp_Vec normal = gp_Vec(tri[1] - tri[0]).Crossed(gp_Vec(tri[2] - tri[0]));
    if (normal.Magnitude() <= 1e-300 || !s.faceHasUV[f]) return 0;
    normal.Normalize();
    // The face's mesh covers it (area), and this triangle faces as the exact
    // surface does at its UV centre (BRepMesh winds along the face's
    // parameters; a fold in UV would not).
    if (s.faceMeshTrusted[f] < 0) s.faceMeshTrusted[f] = faceMeshMatches(s.topo.face(f), s.faceMeshArea[f]) ? 1 : 0;
    if (s.faceMeshTrusted[f] == 0) return 0;
    if (!w.faces[f]) w.faces[f] = std::make_unique<FaceSolver>(s.topo.face(f));
    const auto& uv = s.triangleUV[t];
    gp_Pnt q;
    gp_Vec su, sv;
    w.faces[f]->surface.D1((uv[0].X() + uv[1].X() + uv[2].X()) / 3, (uv[0].Y() + uv[1].Y() + uv[2].Y()) / 3, q, su,
                           sv);
    const gp_Vec surfaceNormal = su.Crossed(sv);
    if (surfaceNormal.Magnitude() <= 1e-300 || normal.Dot(surfaceNormal) < 0.5 * surfaceNormal.Magnitude()) return 0;
    if (faceWoundInward(s.topo.face(f), s.inwardFaces)) normal.Reverse();  // now outward
    const std::array<double, 3> b = closestBarycentric(px, tri[0], tri[1], tri[2]);
    const gp_XYZ foot = b[0] * tri[0] + b[1] * tri[1] + b[2] * tri[2];
    auto same = std::find_if(feet.begin(), feet.end(),
                             [&](const Foot& x) { return (x.point - foot).Modulus() <= rounding; });
    if (same == feet.end()) same = feet.insert(feet.end(), {foot, gp_Vec(0, 0, 0)});
    // The weight from where the (merged) foot is on this triangle: at a
    // corner its angle there, on an edge π, inside 2π.
    double weight = 2 * M_PI;
    for (int k = 0; k < 3; ++k) {
      const gp_XYZ& a = tri[k];
      const gp_XYZ& c = tri[(k + 1) % 3];
      if ((same->point - a).Modulus() <= rounding) {
        weight = gp_Vec(c - a).Angle(gp_Vec(tri[(k + 2) % 3] - a));
        break;
      }
      const gp_XYZ edge = c - a;
      const double t = std::clamp((same->point - a).Dot(edge) / edge.SquareModulus(), 0.0, 1.0);
      if ((same->point - (a + t * edge)).Modulus() <= rounding) weight = M_PI;
    }
    same->normal += weight * normal;
  }
  int side = 0;
  for (const Foot& foot : feet) {
    const gp_Vec along(foot.point, px);
    if (foot.normal.Magnitude() <= 1e-300) return 0;
    const double cosine = along.Dot(foot.normal) / (along.Magnitude() * foot.normal.Magnitude());
    if (!(std::abs(cosine) > 1e-6)) return 0;  // p (nearly) in the tangent plane: no verdict
    const int here = cosine > 0 ? 1 : -1;
    if (side != 0 && here != side) return 0;
    side = here;
  }
  return side;
}

std::size_t ExactOracle::classifierQueries() const { return work_->classifierQueries; }

double ExactOracle::distance(const gp_Pnt& p) { return closestPoint(p).distance; }

BoundaryPoint ExactOracle::closestPoint(const gp_Pnt& p) {
  const std::vector<BoundaryPoint> r = query(p, 0, false);
  if (r.empty()) throw std::runtime_error("exact oracle: no boundary point found");
  return r.front();
}

std::vector<BoundaryPoint> ExactOracle::nearPoints(const gp_Pnt& p, double slack) {
  return query(p, std::max(0.0, slack), true);
}

std::vector<BoundaryPoint> ExactOracle::query(const gp_Pnt& p, double slack, bool nearOnly) {
  const Shared& s = *shared_;
  Workspace& w = *work_;
  const int nf = s.topo.faceCount();
  if (w.faceStamp.empty()) {
    w.faces.resize(nf);
    w.edges.resize(s.topo.edgeCount());
    w.faceStamp.assign(nf, 0);
    w.edgeStamp.assign(s.topo.edgeCount(), 0);
    w.vertexStamp.assign(s.topo.vertexCount(), 0);
    w.faceMeshDistance.assign(nf, 0);
    w.faceMeshUV.assign(nf, gp_Pnt2d());
  }
  const std::uint32_t stamp = ++w.stamp;
  const double margin = s.margin;
  const gp_XYZ px = p.XYZ();

  // 1. Candidate faces: every meshed face with a triangle within
  //    (best mesh distance + slack + 2 margins), with its mesh foot's UV.
  w.candidates.clear();
  w.band.clear();
  const double extra = slack + 2 * margin;
  double meshBest = std::numeric_limits<double>::infinity();
  if (!s.triangles.empty()) {
    s.tree.query(px, extra, w.stack, [&](std::uint32_t t) {
      const Triangle& tri = s.triangles[t];
      const auto bc = closestBarycentric(px, tri[0], tri[1], tri[2]);
      const double d = (px - (tri[0] * bc[0] + tri[1] * bc[1] + tri[2] * bc[2])).Modulus();
      meshBest = std::min(meshBest, d);
      if (d <= meshBest + (nearOnly ? slack + margin : extra)) w.band.emplace_back(d, t);
      const int f = s.triangleFace[t];
      if (w.faceStamp[f] != stamp || d < w.faceMeshDistance[f]) {
        if (w.faceStamp[f] != stamp) w.candidates.emplace_back(0, f);
        w.faceStamp[f] = stamp;
        w.faceMeshDistance[f] = d;
        const auto& uv = s.triangleUV[t];
        w.faceMeshUV[f] = gp_Pnt2d(uv[0].XY() * bc[0] + uv[1].XY() * bc[1] + uv[2].XY() * bc[2]);
      }
      return d;
    });
    // Faces seen early in the traversal may be farther than the final radius.
    w.candidates.erase(std::remove_if(w.candidates.begin(), w.candidates.end(),
                                      [&](const auto& c) { return w.faceMeshDistance[c.second] > meshBest + extra; }),
                       w.candidates.end());
    for (auto& c : w.candidates) c.first = w.faceMeshDistance[c.second] - margin;
  }
  for (int f = 0; f < nf; ++f)
    if (!s.faceMeshed[f]) w.candidates.emplace_back(boxDistance(s.faceBox[f], p), f);
  std::sort(w.candidates.begin(), w.candidates.end());

  // 2. Exact minima on the candidates, nearest first, until no face can
  //    come within best + slack.
  std::vector<BoundaryPoint> found;
  double best = std::numeric_limits<double>::infinity();
  w.bestFace = -1;
  w.bestEdgeSide = 0;
  w.bestSmoothEdge = -1;
  // `interior`: a face point where the surface is smooth (see FaceSolver::smoothPoint).
  // For nearPoints, edge and vertex points count only where the distance to
  // the boundary has a local minimum, i.e. does not decrease into any
  // incident face (edge) or along any incident edge (vertex; to first order,
  // the faces between those edges are covered when their angles are below
  // 180°). Otherwise a seam or an edge crossing the region around one
  // contact would look like a second contact.
  auto edgePointIsLocalMinimum = [&](int e, double t, const gp_Pnt& b) {
    const gp_Vec toP(b, p);
    const double eps = 1e-9 * toP.Magnitude();
    for (int f : s.topo.edgeFaces[e]) {
      if (f < 0) continue;
      const EdgeFaceFrame frame = edgeFaceFrame(s.topo.edge(e), s.topo.face(f), t);
      if (!frame.valid) continue;
      const double into = toP.Dot(frame.intoFace);
      if (into > eps) return false;
      if (BRep_Tool::IsClosed(s.topo.edge(e), s.topo.face(f)) && -into > eps) return false;  // seam: both sides
    }
    return true;
  };
  auto vertexIsLocalMinimum = [&](int vtx) {
    const gp_Vec toP(s.vertexPoint[vtx], p);
    for (const gp_Vec& tangent : s.vertexTangents[vtx])
      if (toP.Dot(tangent) > 1e-9 * toP.Magnitude()) return false;
    return true;
  };
  // edgeSide: of an edge point strictly inside the edge's parameter range.
  gp_Pnt bestPoint;
  bool bestOnFace = false;  // bestPoint came from a face's solvers (not an edge's or a vertex's)
  // smoothEdgeT: the parameter of an edge point strictly inside a smooth edge (else NaN).
  auto add = [&](const gp_Pnt& q, int face, int edge, int vertex, bool interior = false, double u = 0, double v = 0,
                 int edgeSide = 0, double smoothEdgeT = std::numeric_limits<double>::quiet_NaN()) {
    const double d = p.Distance(q);
    if (d <= best + slack) found.push_back({q, d, face, edge, vertex});
    if (d < best) {
      best = d;
      bestPoint = q;
      bestOnFace = face >= 0;
      w.bestFace = interior ? face : -1;
      w.bestU = u;
      w.bestV = v;
      w.bestEdgeSide = edgeSide;
      w.bestSmoothEdge = std::isnan(smoothEdgeT) ? -1 : edge;
      w.bestT = smoothEdgeT;
    } else if (!std::isnan(smoothEdgeT) && bestOnFace && w.bestFace < 0 &&
               q.Distance(bestPoint) <= 1e-9 * std::max(d, s.diagonal)) {
      // The same foot, found before as a face point on the face's boundary
      // (ON, so not known to be smooth there): the smooth edge tells. (Not
      // another foot as near: from a point on an axis a whole circle is.)
      w.bestSmoothEdge = edge;
      w.bestT = smoothEdgeT;
    }
  };
  // The UV of p's closest point on mesh triangle t (a start for Newton).
  auto meshFootUV = [&](std::uint32_t t) {
    const Triangle& tri = s.triangles[t];
    const auto bc = closestBarycentric(px, tri[0], tri[1], tri[2]);
    const auto& uv = s.triangleUV[t];
    return uv[0].XY() * bc[0] + uv[1].XY() * bc[1] + uv[2].XY() * bc[2];
  };
  for (const auto& [lowerBound, f] : w.candidates) {
    if (lowerBound > best + slack) break;
    if (!w.faces[f]) w.faces[f] = std::make_unique<FaceSolver>(s.topo.face(f));
    FaceSolver& fs = *w.faces[f];
    double u, v;
    // The Newton projection from the face's mesh foot (within the mesh
    // deflection of the exact foot) first; the global search on analytic
    // faces (cheap), unmeshed ones, and wherever Newton found no local
    // minimum inside the face as near as the mesh says the face is (Newton
    // can land on a farther extremum) - except for the closest point, where
    // the searches from the face's other triangles below come first. For
    // near points, other extrema of a
    // non-analytic face (both walls of a U-shaped B-spline face) come from
    // the Newton runs under the band's triangles below, not from the global
    // search: with it, eval on a box with variable fillets ran past 15 min
    // again (its medial vertices sit between two points of one fillet).
    // Missing one there under-counts two contacts, never over-counts.
    bool newtonFound = false;
    if (s.faceMeshed[f] && s.faceHasUV[f]) {
      // Analytic faces: the distance minimised within the UV bounds (the
      // global search has the rest); others: the normal-projection
      // equations, whose root is an exact extremum when there is one.
      SurfaceFoot foot;
      if (fs.locateFrom(p, w.faceMeshUV[f].X(), w.faceMeshUV[f].Y(), fs.analytic, foot, !nearOnly)) {
        u = foot.u;
        v = foot.v;
        const TopAbs_State state = fs.state(u, v);
        const bool critical = fs.critical(p, u, v);
        if (state != TopAbs_OUT && (!nearOnly || critical))
          add(foot.point, f, -1, -1, fs.smoothPoint(state, u, v), u, v);
        newtonFound = state == TopAbs_IN && critical && p.Distance(foot.point) <= w.faceMeshDistance[f] + 2 * margin &&
                      (nearOnly ? Extrema_GenLocateExtPS::IsMinDist(p, fs.surface, u, v) : fs.localMinimum(p, u, v));
      }
    }
    // Closest point only: a non-analytic face where that found no minimum
    // is searched by Newton from up to kFaceStarts of its mesh triangles
    // within the candidates' radius, spread over them, instead of OCCT's
    // global search (a grid over the whole face, then a bounded solver from
    // each grid minimum: 3 ms a query on a variable fillet, 90 % of the
    // run's walk check there). An interior minimum of the face as near as
    // the best point has triangles within the mesh deflection of it, and
    // Newton from there reaches it; a minimum on the face's boundary comes
    // from its edges below.
    bool searchedFromStarts = false;
    if (!nearOnly && !newtonFound && !fs.analytic && s.faceMeshed[f] && s.faceHasUV[f]) {
      constexpr std::size_t kFaceStarts = 8;
      w.faceBand.clear();
      for (const auto& [d, t] : w.band)
        if (s.triangleFace[t] == f && d <= meshBest + extra) w.faceBand.push_back(t);
      const std::size_t step = std::max<std::size_t>(1, w.faceBand.size() / kFaceStarts);
      for (std::size_t i = 0; i < w.faceBand.size(); i += step) {
        SurfaceFoot foot;
        const gp_XY start = meshFootUV(w.faceBand[i]);
        if (!fs.locateFrom(p, start.X(), start.Y(), false, foot, true)) continue;
        const TopAbs_State state = fs.state(foot.u, foot.v);
        if (state != TopAbs_OUT) add(foot.point, f, -1, -1, fs.smoothPoint(state, foot.u, foot.v), foot.u, foot.v);
      }
      searchedFromStarts = !w.faceBand.empty();
    }
    auto globalSearch = [&] {
      fs.extrema.Perform(p);
      if (!fs.extrema.IsDone()) return;
      for (int n = 1; n <= fs.extrema.NbExt(); ++n) {
        fs.extrema.Point(n).Parameter(u, v);
        const TopAbs_State state = fs.state(u, v);
        if (state != TopAbs_OUT) add(fs.extrema.Point(n).Value(), f, -1, -1, fs.smoothPoint(state, u, v), u, v);
      }
    };
    if (fs.analytic || !(newtonFound || searchedFromStarts)) globalSearch();
    for (int e : s.faceEdges[f]) {
      if (w.edgeStamp[e] == stamp) continue;
      w.edgeStamp[e] = stamp;
      if (boxDistance(s.edgeBox[e], p) > best + slack) continue;
      if (!w.edges[e]) w.edges[e] = std::make_unique<EdgeSolver>(s.topo.edge(e));
      Extrema_ExtPC& ext = w.edges[e]->extrema;
      const BRepAdaptor_Curve& curve = w.edges[e]->curve;
      ext.Perform(p);
      if (!ext.IsDone()) continue;  // e.g. p on a circle's axis: its vertices give the distance
      const double t0 = curve.FirstParameter(), t1 = curve.LastParameter();
      for (int n = 1; n <= ext.NbExt(); ++n) {
        if (!ext.IsMin(n)) continue;
        const double t = ext.Point(n).Parameter();
        const bool inner = t > t0 + 1e-9 * (t1 - t0) && t < t1 - 1e-9 * (t1 - t0);
        if (nearOnly && !edgePointIsLocalMinimum(e, t, ext.Point(n).Value())) continue;
        add(ext.Point(n).Value(), -1, e, -1, false, 0, 0, inner ? s.edgeSide[e] : 0,
            inner && s.edgeSmooth[e] ? t : std::numeric_limits<double>::quiet_NaN());
      }
    }
    for (int vtx : s.faceVertices[f]) {
      if (w.vertexStamp[vtx] == stamp) continue;
      w.vertexStamp[vtx] = stamp;
      if (nearOnly && !vertexIsLocalMinimum(vtx)) continue;
      add(s.vertexPoint[vtx], -1, -1, vtx);
    }
    // The safety net of the search from starts: nothing found (on this
    // face, its boundary or elsewhere) as near as the mesh says this face
    // comes, so the starts missed a minimum of it.
    if (searchedFromStarts && best > w.faceMeshDistance[f] + 2 * margin) globalSearch();
  }

  const double limit = best + slack;
  if (nearOnly) {
    // A minimum can be degenerate: from a point on a torus' core circle the
    // distance is minimal along a whole tube circle, and the solvers above
    // return one point of it. Newton runs on the normal-projection equations
    // (still solvable where the distance Hessian is singular), started under
    // up to kBandStarts mesh triangles spread over those within the limit,
    // find other points of it; on a plane they all return the same foot.
    constexpr std::size_t kBandStarts = 16;
    w.band.erase(std::remove_if(w.band.begin(), w.band.end(),
                                [&](const auto& b) { return b.first > limit + margin; }),
                 w.band.end());
    const std::size_t step = std::max<std::size_t>(1, w.band.size() / kBandStarts);
    for (std::size_t i = 0; i < w.band.size(); i += step) {
      const std::uint32_t t = w.band[i].second;
      const int f = s.triangleFace[t];
      if (!s.faceHasUV[f]) continue;
      const gp_XY start = meshFootUV(t);
      if (!w.faces[f]) w.faces[f] = std::make_unique<FaceSolver>(s.topo.face(f));
      FaceSolver& fs = *w.faces[f];
      SurfaceFoot foot;
      if (!fs.locateFrom(p, start.X(), start.Y(), false, foot)) continue;
      const double d = p.Distance(foot.point);
      if (d <= limit && fs.state(foot.u, foot.v) != TopAbs_OUT && fs.critical(p, foot.u, foot.v))
        found.push_back({foot.point, d, f, -1, -1});
    }
  }
  found.erase(std::remove_if(found.begin(), found.end(), [&](const BoundaryPoint& b) { return b.distance > limit; }),
              found.end());
  std::sort(found.begin(), found.end(),
            [](const BoundaryPoint& a, const BoundaryPoint& b) { return a.distance < b.distance; });
  if (!nearOnly && found.size() > 1) found.resize(1);
  return found;
}

std::vector<gp_Pnt> ExactOracle::sampleBoundary(std::size_t count, unsigned seed) const {
  const Shared& s = *shared_;
  std::vector<gp_Pnt> out;
  if (s.cumulativeArea.empty() || count == 0) return out;
  // Own uniform mapping (not std::uniform_real_distribution) so the points
  // are the same with every standard library.
  std::mt19937_64 rng(seed);
  auto uniform = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  std::vector<std::unique_ptr<BRepAdaptor_Surface>> surfaces(s.topo.faceCount());
  const double total = s.cumulativeArea.back();
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double pick = uniform() * total;
    std::size_t t = std::upper_bound(s.cumulativeArea.begin(), s.cumulativeArea.end(), pick) - s.cumulativeArea.begin();
    t = std::min(t, s.triangles.size() - 1);
    double a = uniform(), b = uniform();
    if (a + b > 1) a = 1 - a, b = 1 - b;
    const double c = 1 - a - b;
    const int f = s.triangleFace[t];
    if (s.faceHasUV[f]) {
      if (!surfaces[f]) surfaces[f] = std::make_unique<BRepAdaptor_Surface>(s.topo.face(f), true);
      const auto& uv = s.triangleUV[t];
      const gp_XY q = uv[0].XY() * c + uv[1].XY() * a + uv[2].XY() * b;
      out.push_back(surfaces[f]->Value(q.X(), q.Y()));
    } else {
      const Triangle& tri = s.triangles[t];
      out.emplace_back(tri[0] * c + tri[1] * a + tri[2] * b);
    }
  }
  return out;
}

}  // namespace cadmedial
