#include "feature_classification.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <Geom_Curve.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>

#include <tbb/enumerable_thread_specific.h>

#include "face_uv_classifier.hpp"
#include "ordered_parallel.hpp"
#include "solid_point_classifier.hpp"

namespace cadmedial {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int kProbesPerEdge = 9;

double degrees(double radians) { return radians * 180.0 / kPi; }

// Outgoing unit tangent of edge e at its end `atLast`.
gp_Vec outgoingTangent(const TopoDS_Edge& edge, bool atLast) {
  double f, l;
  Handle(Geom_Curve) c = BRep_Tool::Curve(edge, f, l);
  if (c.IsNull()) return gp_Vec(0, 0, 0);
  gp_Pnt p;
  gp_Vec d;
  c->D1(atLast ? l : f, p, d);
  if (d.Magnitude() < 1e-300) {
    // Singular parametrisation at the end: use a chord instead.
    const double t = atLast ? l - 1e-6 * (l - f) : f + 1e-6 * (l - f);
    d = gp_Vec(c->Value(atLast ? l : f), c->Value(t));
    if (!atLast) d.Reverse();
  }
  if (d.Magnitude() < 1e-300) return gp_Vec(0, 0, 0);
  d.Normalize();
  return atLast ? -d : d;
}
}  // namespace

std::vector<EdgeFeature> classifyEdges(const SolidTopology& topo, double smoothAngleDeg) {
  const double smoothCos = std::cos(smoothAngleDeg * kPi / 180.0);
  std::vector<EdgeFeature> out(topo.edgeCount());
  for (int e = 0; e < topo.edgeCount(); ++e) {
    EdgeFeature& feat = out[e];
    const TopoDS_Edge& edge = topo.edge(e);
    if (topo.edgeDegenerate[e]) continue;
    BRepAdaptor_Curve curve(edge);
    feat.length = GCPnts_AbscissaPoint::Length(curve);
    const auto [fl, fr] = topo.edgeFaces[e];
    if (fl < 0) continue;
    if (fr < 0) {
      feat.seam = BRep_Tool::IsClosed(edge, topo.face(fl));
      feat.free = !feat.seam;
      continue;
    }
    int convexVotes = 0, concaveVotes = 0;
    double maxDev = 0;
    const double t0 = curve.FirstParameter(), t1 = curve.LastParameter();
    for (int k = 0; k < kProbesPerEdge; ++k) {
      const double t = t0 + (t1 - t0) * (k + 0.5) / kProbesPerEdge;
      const EdgeFaceFrame a = edgeFaceFrame(edge, topo.face(fl), t);
      const EdgeFaceFrame b = edgeFaceFrame(edge, topo.face(fr), t);
      if (!a.valid || !b.valid) continue;
      ++feat.validProbes;
      const double cosNormals = std::clamp(a.outwardNormal.Dot(b.outwardNormal), -1.0, 1.0);
      maxDev = std::max(maxDev, degrees(std::acos(cosNormals)));
      if (cosNormals >= smoothCos) continue;
      // Face b bends away below face a's tangent plane (and vice versa) at a convex edge.
      const double bend = b.intoFace.Dot(a.outwardNormal) + a.intoFace.Dot(b.outwardNormal);
      (bend < 0 ? convexVotes : concaveVotes)++;
    }
    feat.maxDeviationDeg = maxDev;
    if (convexVotes + concaveVotes == 0) continue;
    feat.kind = convexVotes >= concaveVotes ? EdgeKind::Convex : EdgeKind::Concave;
    feat.mixedSign = convexVotes > 0 && concaveVotes > 0;
  }
  return out;
}

namespace {

// Rays from vertex v into face f: points of the face on a small loop around v.
void addFaceRays(const TopoDS_Vertex& vertex, const TopoDS_Face& face, const FaceUVClassifier& classifier,
                 double radius3d, std::vector<gp_Vec>& rays) {
  gp_Pnt2d uv = BRep_Tool::Parameters(vertex, face);
  BRepAdaptor_Surface surf(face, false);
  gp_Pnt p;
  gp_Vec su, sv;
  surf.D1(uv.X(), uv.Y(), p, su, sv);
  const double lu = su.Magnitude(), lv = sv.Magnitude();
  if (lu < 1e-300 || lv < 1e-300) return;  // singular point (pole): no tangent-cone probe
  const gp_Pnt origin = BRep_Tool::Pnt(vertex);
  constexpr int kDirections = 24;
  for (int k = 0; k < kDirections; ++k) {
    const double phi = 2 * kPi * k / kDirections;
    const gp_Pnt2d q(uv.X() + radius3d / lu * std::cos(phi), uv.Y() + radius3d / lv * std::sin(phi));
    if (classifier.Perform(q) != TopAbs_IN) continue;
    gp_Vec ray(origin, surf.Value(q.X(), q.Y()));
    if (ray.Magnitude() < 1e-300) continue;
    rays.push_back(ray.Normalized());
  }
}

// max over unit n of min_i rays[i]·n, by enumerating the candidates where the
// optimum of this small LP can sit (one, two or three active rays): the
// candidates whose margin is at least -tolerance, best first (ties in the
// order they were made). Scoring a candidate stops at the first ray below
// -tolerance: a corner with 80 rays has ~170 k candidates, most of them far
// below, and scoring and sorting them all was a third of the lever's vertex
// classification.
std::vector<std::pair<double, gp_Vec>> bestHalfSpaceNormals(const std::vector<gp_Vec>& rays, double tolerance) {
  std::vector<std::pair<double, gp_Vec>> scored;
  auto score = [&](const gp_Vec& n) {
    double worst = 1;
    for (const gp_Vec& r : rays) {
      worst = std::min(worst, r.Dot(n));
      if (worst < -tolerance) return;
    }
    scored.emplace_back(worst, n);
  };
  const std::size_t m = rays.size();
  for (std::size_t i = 0; i < m; ++i) {
    score(rays[i]);
    for (std::size_t j = i + 1; j < m; ++j) {
      gp_Vec s = rays[i] + rays[j];
      if (s.Magnitude() > 1e-9) score(s.Normalized());
      for (std::size_t k = j + 1; k < m; ++k) {
        gp_Vec c = (rays[i] - rays[j]).Crossed(rays[i] - rays[k]);
        if (c.Magnitude() < 1e-12) continue;
        c.Normalize();
        score(c);
        score(-c);
      }
    }
  }
  std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  return scored;
}

}  // namespace

std::vector<VertexFeature> classifyVertices(const SolidTopology& topo, const std::vector<EdgeFeature>& edges) {
  constexpr double kPassThroughCos = -0.99985;  // outgoing tangents within 1° of opposite
  constexpr double kHalfSpaceTolerance = 0.035;  // ~2°: rays may dip this far below the plane
  std::vector<VertexFeature> out(topo.vertexCount());

  TopTools_IndexedDataMapOfShapeListOfShape vertexToFaces;
  TopExp::MapShapesAndUniqueAncestors(topo.solid, TopAbs_VERTEX, TopAbs_FACE, vertexToFaces);
  // Vertices in parallel (each answer is the vertex's own; the probes near a
  // vertex fall back to OCCT's exact face classifier, which recomputes the
  // face's UV bounds, most of this stage's time on NIST CTC-01). Each thread
  // has its own classifiers.
  struct Classifiers {
    std::map<int, std::unique_ptr<FaceUVClassifier>> faces;
    std::unique_ptr<SolidPointClassifier> solid;
  };
  tbb::enumerable_thread_specific<Classifiers> perThread;

  parallelForInOrder(topo.vertexCount(), [&](int v) {
    Classifiers& mine = perThread.local();
    auto faceClassifier = [&](int f) -> FaceUVClassifier& {
      auto& slot = mine.faces[f];
      if (!slot) slot = std::make_unique<FaceUVClassifier>(topo.face(f), 1e-9);
      return *slot;
    };
    VertexFeature& feat = out[v];
    const TopoDS_Vertex& vertex = TopoDS::Vertex(topo.vertices(v + 1));
    std::vector<gp_Vec> sharpTangents;
    std::vector<EdgeKind> sharpKinds;
    std::vector<gp_Vec> allTangents;
    double minEdgeLength = 1e300;
    // An edge closing on itself lists v twice: once per end.
    std::map<int, int> endsSeen;
    for (int e : topo.vertexEdges[v]) {
      const bool atLast = endsSeen[e]++ > 0 || topo.edgeVertices[e][0] != v;
      const gp_Vec t = outgoingTangent(topo.edge(e), atLast);
      allTangents.push_back(t);
      minEdgeLength = std::min(minEdgeLength, edges[e].length);
      if (edges[e].sharp()) {
        sharpTangents.push_back(t);
        sharpKinds.push_back(edges[e].kind);
      }
    }
    feat.sharpEdgeEnds = static_cast<int>(sharpTangents.size());
    if (feat.sharpEdgeEnds == 0) return;
    const bool passThrough = feat.sharpEdgeEnds == 2 && sharpKinds[0] == sharpKinds[1] &&
                             sharpTangents[0].Dot(sharpTangents[1]) < kPassThroughCos;
    feat.isCorner = !passThrough;
    if (!feat.isCorner) return;

    // Probe the interior tangent cone with rays along edges and into faces.
    std::vector<gp_Vec> rays = allTangents;
    const double probe = 1e-3 * minEdgeLength;
    if (const TopTools_ListOfShape* faces = vertexToFaces.Seek(vertex))
      for (const TopoDS_Shape& f : *faces) {
        const int fid = topo.faces.FindIndex(f) - 1;
        addFaceRays(vertex, topo.face(fid), faceClassifier(fid), probe, rays);
      }
    rays.erase(std::remove_if(rays.begin(), rays.end(), [](const gp_Vec& r) { return r.Magnitude() < 0.5; }),
               rays.end());
    feat.nonConcave = true;
    const auto scored = bestHalfSpaceNormals(rays, kHalfSpaceTolerance);
    if (!mine.solid) mine.solid = std::make_unique<SolidPointClassifier>(topo.solid);
    const gp_Pnt origin = BRep_Tool::Pnt(vertex);
    std::vector<gp_Vec> tried;
    for (const auto& [margin, n] : scored) {
      if (margin < -kHalfSpaceTolerance || tried.size() >= 4) break;
      bool near = false;
      for (const gp_Vec& t : tried) near = near || t.Dot(n) > 0.985;
      if (near) continue;
      tried.push_back(n);
      // The open half-space {x·n < 0} is free of boundary; is it inside?
      const gp_Pnt inside = origin.Translated(-n * probe);
      if (mine.solid->classify(inside, 1e-9) == TopAbs_IN) {
        feat.nonConcave = false;
        break;
      }
    }
  });
  return out;
}

}  // namespace cadmedial
