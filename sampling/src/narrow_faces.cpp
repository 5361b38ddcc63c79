#include "narrow_faces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBndLib.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <Bnd_Box.hxx>
#include <Extrema_ExtPC.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GCPnts_UniformAbscissa.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "ordered_parallel.hpp"

namespace cadmedial {

namespace {

constexpr int kMaxCoarsePoints = 4096;
constexpr std::size_t kMaxPointsPerEdge = 100000;
// Two points of a face's boundary make it narrow when the way between them
// along the boundary is at least this × their distance: across a step's
// riser (100 mm round, 0.2 across), not where one edge of a line split in
// three meets the next through a short piece (the way is the distance).
constexpr double kPathRatio = 2.0;

// Where an edge sits in its face's boundary: its wire, the arc length of
// the wire before it (in the wire's order) and the edge's direction in it.
struct WireSpot {
  int wire = -1;
  double start = 0, length = 0;
  bool forward = true;
};

// Per edge of the face, its spot; per wire, its length.
struct FaceBoundary {
  std::unordered_map<int, WireSpot> spots;  // by edge id
  std::vector<double> perimeter;

  // Arc position along its wire of the point `arc` from the start of edge e's curve.
  double position(const WireSpot& s, double arc) const { return s.start + (s.forward ? arc : s.length - arc); }
  // The way along the boundary between two points (+inf on different wires,
  // or for an edge no wire lists).
  double way(int a, double arcA, int b, double arcB) const {
    const auto sa = spots.find(a), sb = spots.find(b);
    if (sa == spots.end() || sb == spots.end() || sa->second.wire != sb->second.wire)
      return std::numeric_limits<double>::infinity();
    const double apart = std::abs(position(sa->second, arcA) - position(sb->second, arcB));
    return std::min(apart, perimeter[sa->second.wire] - apart);
  }
};

FaceBoundary boundaryOf(const SolidTopology& topo, int f) {
  FaceBoundary fb;
  const TopoDS_Face& face = topo.face(f);
  for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) {
    const int wire = static_cast<int>(fb.perimeter.size());
    double along = 0;
    for (BRepTools_WireExplorer ex(TopoDS::Wire(w.Current()), face); ex.More(); ex.Next()) {
      const int e = topo.edges.FindIndex(ex.Current()) - 1;
      if (e < 0 || topo.edgeDegenerate[e]) continue;
      const double length = GCPnts_AbscissaPoint::Length(BRepAdaptor_Curve(topo.edge(e)));
      // A seam is met twice: its first passage stands.
      fb.spots.emplace(e, WireSpot{wire, along, length, ex.Current().Orientation() != TopAbs_REVERSED});
      along += length;
    }
    fb.perimeter.push_back(along);
  }
  return fb;
}

// Arc length from the start of `curve` to parameter u.
double arcTo(const BRepAdaptor_Curve& curve, double u) {
  return u > curve.FirstParameter() ? GCPnts_AbscissaPoint::Length(curve, curve.FirstParameter(), u) : 0.0;
}

struct Partner {
  int edge;
  BRepAdaptor_Curve curve;
  Bnd_Box near;  // its box grown by the reach: points outside are too far to ask
};

// Points of `curve` (parameters and arc lengths from its start) about `step`
// apart where `curve` comes within the reach of a partner: the edge is first
// cut into pieces at most reach / 4 long, and only pieces with an end in a
// partner's grown box are sampled at `step`.
std::vector<std::pair<double, double>> pointsNearPartners(const BRepAdaptor_Curve& curve, double length, double step,
                                                          double reach, const std::vector<Partner>& partners) {
  const double piece = std::max(step, reach / 4);
  const int n = static_cast<int>(std::clamp(std::ceil(length / piece), 1.0, double(kMaxCoarsePoints)));
  std::vector<double> params;
  GCPnts_UniformAbscissa coarse(curve, n + 1);
  if (coarse.IsDone() && coarse.NbPoints() == n + 1) {
    for (int i = 1; i <= coarse.NbPoints(); ++i) params.push_back(coarse.Parameter(i));
  } else {
    for (int i = 0; i <= n; ++i)
      params.push_back(curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * i / n);
  }
  auto nearSome = [&](double u) {
    const gp_Pnt p = curve.Value(u);
    return std::any_of(partners.begin(), partners.end(), [&](const Partner& q) { return !q.near.IsOut(p); });
  };
  std::vector<std::pair<double, double>> points;  // (parameter, arc)
  std::vector<char> near(params.size());
  for (std::size_t i = 0; i < params.size(); ++i) near[i] = nearSome(params[i]);
  for (int i = 0; i < n && points.size() < kMaxPointsPerEdge; ++i) {
    if (!near[i] && !near[i + 1]) continue;
    const double arc0 = length * i / n, arc1 = length * (i + 1) / n;
    const int k = static_cast<int>(std::clamp(std::ceil((arc1 - arc0) / step), 1.0, double(kMaxPointsPerEdge)));
    GCPnts_UniformAbscissa fine(curve, k + 1, params[i], params[i + 1]);
    const bool even = fine.IsDone() && fine.NbPoints() == k + 1;
    for (int j = (points.empty() || points.back().first != params[i]) ? 0 : 1; j <= k; ++j) {
      const double u = even ? fine.Parameter(j + 1) : params[i] + (params[i + 1] - params[i]) * j / k;
      points.push_back({u, arc0 + (arc1 - arc0) * j / k});
    }
  }
  return points;
}

bool shareVertex(const SolidTopology& topo, int a, int b) {
  for (int x : topo.edgeVertices[a])
    for (int y : topo.edgeVertices[b])
      if (x >= 0 && x == y) return true;
  return false;
}

// The sources of one face (see narrowFaceSources).
std::vector<FaceSpacingField::Source> sourcesOfFace(const SolidTopology& topo, int f,
                                                    const std::vector<Bnd_Box>& boxes, double floor, double cap,
                                                    double fraction) {
  std::vector<FaceSpacingField::Source> sources;
  const double reach = cap / fraction;  // only edges nearer than this ask for less than the cap
  std::vector<int> edges;
  for (TopExp_Explorer x(topo.face(f), TopAbs_EDGE); x.More(); x.Next()) {
    const int e = topo.edges.FindIndex(x.Current()) - 1;
    if (e >= 0 && !topo.edgeDegenerate[e] && !boxes[e].IsVoid()) edges.push_back(e);
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  // Per edge (its index in `edges`): its partners, the face's edges sharing
  // no vertex with it (edges meeting at a vertex are near each other there:
  // a corner, for its ball and the edges' spacing) within the reach, with
  // their distance; each pair measured once.
  std::vector<std::vector<std::pair<std::size_t, double>>> close(edges.size());
  bool any = false;
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const int a = edges[i], b = edges[j];
      if (shareVertex(topo, a, b) || boxes[a].Distance(boxes[b]) >= reach) continue;
      BRepExtrema_DistShapeShape distance(topo.edge(a), topo.edge(b));
      if (!distance.IsDone() || !(distance.Value() < reach)) continue;
      close[i].push_back({j, distance.Value()});
      close[j].push_back({i, distance.Value()});
      any = true;
    }
  if (!any) return sources;  // most faces: no wire walk, no edge lengths
  const FaceBoundary boundary = boundaryOf(topo, f);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto spot = boundary.spots.find(edges[i]);
    if (close[i].empty() || spot == boundary.spots.end()) continue;
    const int a = edges[i];
    std::vector<Partner> partners;
    double nearest = reach;
    for (const auto& [j, distance] : close[i]) {
      nearest = std::min(nearest, distance);
      Bnd_Box grown = boxes[edges[j]];
      grown.Enlarge(reach);
      partners.push_back({edges[j], BRepAdaptor_Curve(topo.edge(edges[j])), grown});
    }
    const BRepAdaptor_Curve curve(topo.edge(a));
    const double length = spot->second.length;
    const double step = std::clamp(fraction * nearest, floor, cap);
    for (const auto& [u, arc] : pointsNearPartners(curve, length, step, reach, partners)) {
      const gp_Pnt p = curve.Value(u);
      double spacing = cap;
      for (const Partner& q : partners) {
        if (q.near.IsOut(p)) continue;
        // The nearest point of the partner (its ends included), and whether
        // the boundary runs far between the two.
        double best = p.SquareDistance(q.curve.Value(q.curve.FirstParameter()));
        double at = q.curve.FirstParameter();
        if (const double last = p.SquareDistance(q.curve.Value(q.curve.LastParameter())); last < best) {
          best = last;
          at = q.curve.LastParameter();
        }
        Extrema_ExtPC extrema(p, q.curve);
        if (extrema.IsDone())
          for (int i = 1; i <= extrema.NbExt(); ++i)
            if (extrema.SquareDistance(i) < best) {
              best = extrema.SquareDistance(i);
              at = extrema.Point(i).Parameter();
            }
        const double d = std::sqrt(best);
        // The way round (an arc length on the partner) only where it could lower the spacing.
        if (fraction * d < spacing && boundary.way(a, arc, q.edge, arcTo(q.curve, at)) >= kPathRatio * d)
          spacing = fraction * d;
      }
      if (spacing < cap) sources.push_back({p, std::clamp(spacing, floor, cap)});
    }
  }
  return sources;
}

}  // namespace

std::vector<std::vector<FaceSpacingField::Source>> narrowFaceSources(const SolidTopology& topo, double floor,
                                                                      double cap, double fraction) {
  std::vector<std::vector<FaceSpacingField::Source>> sources(topo.faceCount());
  if (!(fraction > 0) || !(cap > 0)) return sources;
  // A box OCCT cannot make stays void: its edge asks for nothing.
  std::vector<Bnd_Box> boxes(topo.edgeCount());
  for (int e = 0; e < topo.edgeCount(); ++e) {
    if (topo.edgeDegenerate[e]) continue;
    try {
      BRepBndLib::Add(topo.edge(e), boxes[e], false);
    } catch (const Standard_Failure&) {
      boxes[e] = Bnd_Box();
    }
  }
  // Faces in parallel: each reads the shared edges and writes its own sources.
  parallelForInOrder(topo.faceCount(), [&](int f) {
    // A face OCCT cannot measure (a broken curve in a hostile file) asks
    // for nothing: the rest of the sampling copes with it or reports it.
    try {
      sources[f] = sourcesOfFace(topo, f, boxes, floor, cap, fraction);
    } catch (const Standard_Failure&) {
      sources[f].clear();
    }
  });
  return sources;
}

}  // namespace cadmedial
