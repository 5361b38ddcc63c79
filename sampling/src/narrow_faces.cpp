#include "narrow_faces.hpp"

#include <algorithm>
#include <cmath>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBndLib.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <Bnd_Box.hxx>
#include <Extrema_ExtPC.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GCPnts_UniformAbscissa.hxx>
#include <Standard_Failure.hxx>

namespace cadmedial {

namespace {

constexpr int kMaxPointsPerEdge = 4096;

// Distance from p to the edge behind `curve` (its ends included).
double distanceToCurve(const gp_Pnt& p, const BRepAdaptor_Curve& curve) {
  double best = std::min(p.SquareDistance(curve.Value(curve.FirstParameter())),
                         p.SquareDistance(curve.Value(curve.LastParameter())));
  Extrema_ExtPC extrema(p, curve);
  if (extrema.IsDone())
    for (int i = 1; i <= extrema.NbExt(); ++i) best = std::min(best, extrema.SquareDistance(i));
  return std::sqrt(best);
}

// Points along `curve` about `step` apart (both ends included).
std::vector<gp_Pnt> pointsAlong(const BRepAdaptor_Curve& curve, double step) {
  const double length = GCPnts_AbscissaPoint::Length(curve);
  const double wanted = std::ceil(length / step);
  const int n = std::isfinite(wanted) ? static_cast<int>(std::clamp(wanted, 1.0, double(kMaxPointsPerEdge))) : 1;
  std::vector<gp_Pnt> points;
  GCPnts_UniformAbscissa even(curve, n + 1);
  if (even.IsDone() && even.NbPoints() == n + 1) {
    for (int i = 1; i <= even.NbPoints(); ++i) points.push_back(curve.Value(even.Parameter(i)));
  } else {  // even in the parameter: the points are a guide, not samples
    for (int i = 0; i <= n; ++i)
      points.push_back(curve.Value(curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * i / n));
  }
  return points;
}

bool shareVertex(const SolidTopology& topo, int a, int b) {
  const auto& va = topo.edgeVertices[a];
  const auto& vb = topo.edgeVertices[b];
  for (int x : va)
    for (int y : vb)
      if (x >= 0 && x == y) return true;
  return false;
}

}  // namespace

std::vector<std::vector<FaceSpacingField::Source>> narrowFaceSources(const SolidTopology& topo, double floor,
                                                                      double cap, double fraction) {
  std::vector<std::vector<FaceSpacingField::Source>> sources(topo.faceCount());
  if (!(fraction > 0) || !(cap > 0)) return sources;
  std::vector<std::vector<int>> faceEdges(topo.faceCount());
  for (int e = 0; e < topo.edgeCount(); ++e) {
    if (topo.edgeDegenerate[e]) continue;
    const auto [f0, f1] = topo.edgeFaces[e];
    if (f0 >= 0) faceEdges[f0].push_back(e);
    if (f1 >= 0 && f1 != f0) faceEdges[f1].push_back(e);
  }
  std::vector<Bnd_Box> boxes(topo.edgeCount());
  for (int e = 0; e < topo.edgeCount(); ++e)
    if (!topo.edgeDegenerate[e]) BRepBndLib::Add(topo.edge(e), boxes[e], false);
  // Only edges nearer than this ask for less than the cap.
  const double reach = cap / fraction;

  for (int f = 0; f < topo.faceCount(); ++f) {
    const std::vector<int>& edges = faceEdges[f];
    for (std::size_t i = 0; i < edges.size(); ++i)
      for (std::size_t j = i + 1; j < edges.size(); ++j) {
        const int a = edges[i], b = edges[j];
        // Edges meeting at a vertex are near each other there: that is a
        // corner (its ball and the edges' spacing), not a narrow face.
        if (shareVertex(topo, a, b) || boxes[a].IsVoid() || boxes[b].IsVoid() ||
            boxes[a].Distance(boxes[b]) >= reach)
          continue;
        // A pair OCCT cannot measure (a broken curve in a hostile file)
        // asks for nothing: the rest of the sampling copes with it or
        // reports it.
        std::vector<FaceSpacingField::Source> found;
        try {
          BRepExtrema_DistShapeShape nearest(topo.edge(a), topo.edge(b));
          if (!nearest.IsDone() || !(nearest.Value() < reach)) continue;
          const double step = std::clamp(fraction * nearest.Value(), floor, cap);
          // Each edge's points ask for fraction × their own distance to the
          // other edge: where the two part, the face is wide again.
          for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
            const BRepAdaptor_Curve source(topo.edge(from)), other(topo.edge(to));
            for (const gp_Pnt& p : pointsAlong(source, step)) {
              const double spacing = std::clamp(fraction * distanceToCurve(p, other), floor, cap);
              if (spacing < cap) found.push_back({p, spacing});
            }
          }
        } catch (const Standard_Failure&) {
          continue;
        }
        sources[f].insert(sources[f].end(), found.begin(), found.end());
      }
  }
  return sources;
}

}  // namespace cadmedial
