// Vertices, sharp and smooth edges, and convex-edge triplets (seed 002 §4.2.1).
#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepLProp_CLProps.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <tbb/enumerable_thread_specific.h>

#include "face_spacing_field.hpp"
#include "face_uv_classifier.hpp"
#include "narrow_faces.hpp"
#include "ordered_parallel.hpp"
#include "sampling_context.hpp"

namespace cadmedial {

namespace {
constexpr double kCurvatureFraction = FaceSpacingField::kCurvatureFraction;
constexpr double kCornerBallFraction = 0.3;  // corner ball <= this × shortest incident edge
constexpr double kLegFraction = 0.6;         // triplet leg = this × min(edge spacing, corner balls)
constexpr double kRungWallFraction = 1.0;    // knife-edge rungs until the chord across the wedge is this × the edge spacing
constexpr double kRungGapFraction = 0.85;    // gap between rungs = this × the edge spacing (less up to 10 %)

// Smallest radius of curvature at 9 points of the edge (1e300 if straight),
// and where: `tightest` gets that point.
double edgeMinCurvatureRadius(const TopoDS_Edge& edge, gp_Pnt* tightest = nullptr) {
  BRepAdaptor_Curve curve(edge);
  double maxK = 0;
  constexpr int n = 9;
  for (int i = 0; i < n; ++i) {
    const double t = curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * (i + 0.5) / n;
    BRepLProp_CLProps props(curve, t, 2, 1e-9);
    if (!props.IsTangentDefined() || !(std::abs(props.Curvature()) > maxK)) continue;
    maxK = std::abs(props.Curvature());
    if (tightest) *tightest = props.Value();
  }
  return maxK > 0 ? 1.0 / maxK : 1e300;
}

double clampSpacing(double s, const SamplingContext& ctx) { return std::clamp(s, ctx.minSpacing, ctx.spacing); }

// The spacing of edge e at its end on vertex v (its one value when even).
double edgeSpacingAt(const SamplingContext& ctx, int e, int v) {
  const auto& profile = ctx.edgeSpacingAlong[e];
  if (profile.empty()) return ctx.edgeSpacing[e];
  const auto [v0, v1] = ctx.topo.edgeVertices[e];
  if (v0 == v1) return ctx.edgeSpacing[e];  // closed: both ends on v
  return v == v0 ? profile.front()[1] : profile.back()[1];
}

// Arc positions from `from` to from + inner (both included) whose steps
// follow the spacing along the edge: piecewise linear in arc length between
// the profile's points, steps equal in the integral of 1 / spacing. With an
// empty profile, even steps at `even` (as before profiles existed, to the
// bit). At least `minSegments` steps.
std::vector<double> sampleArcs(const std::vector<std::array<double, 2>>& profile, double even, double from,
                               double inner, int minSegments) {
  const double to = from + inner;
  const bool positive = std::all_of(profile.begin(), profile.end(), [](const auto& p) { return p[1] > 0; });
  if (profile.size() < 2 || !(inner > 0) || !positive) {
    const int segments = std::max(minSegments, static_cast<int>(std::ceil(inner / even - 1e-9)));
    const double step = inner / segments;
    std::vector<double> arcs;
    for (int k = 0; k <= segments; ++k) arcs.push_back(from + k * step);
    return arcs;
  }
  // The profile cut to [from, to]: pieces (start arc, length, spacing at start, slope).
  struct Piece {
    double arc, length, spacing, slope, density;  // density: integral of 1/s over the piece
  };
  auto spacingAt = [&](double a) {
    std::size_t j = 1;
    while (j + 1 < profile.size() && profile[j][0] < a) ++j;
    const auto &p = profile[j - 1], &q = profile[j];
    const double w = q[0] > p[0] ? std::clamp((a - p[0]) / (q[0] - p[0]), 0.0, 1.0) : 0.0;
    return p[1] + w * (q[1] - p[1]);
  };
  std::vector<double> cuts{from};
  for (const auto& p : profile)
    if (p[0] > from && p[0] < to) cuts.push_back(p[0]);
  cuts.push_back(to);
  std::vector<Piece> pieces;
  double total = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double a = cuts[i], length = cuts[i + 1] - a;
    if (!(length > 0)) continue;
    const double s0 = spacingAt(a), s1 = spacingAt(cuts[i + 1]);
    const double slope = (s1 - s0) / length;
    const double density = std::abs(slope) > 1e-12 ? std::log(s1 / s0) / slope : length / s0;
    pieces.push_back({a, length, s0, slope, density});
    total += density;
  }
  const int segments = std::max(minSegments, static_cast<int>(std::ceil(total - 1e-9)));
  std::vector<double> arcs{from};
  std::size_t piece = 0;
  double before = 0;  // integral up to the start of `piece`
  for (int k = 1; k < segments; ++k) {
    const double target = total * k / segments;
    while (piece + 1 < pieces.size() && before + pieces[piece].density < target) before += pieces[piece++].density;
    const Piece& p = pieces[piece];
    const double within = std::clamp(target - before, 0.0, p.density);
    // Inverse of F(x) = ln(s(x) / s0) / slope, or x / s0 when flat.
    const double x = std::abs(p.slope) > 1e-12 ? p.spacing * std::expm1(p.slope * within) / p.slope : within * p.spacing;
    arcs.push_back(std::clamp(p.arc + x, arcs.back(), to));
  }
  arcs.push_back(to);
  return arcs;
}

// The medial sheet of a convex edge starts on the edge with balls of radius
// 0 that touch both faces; a ball of radius r touches each face about r from
// the edge. Where one face is sampled much finer than the other (a bolt hole
// of radius 5, spacing 0.6, in a plate sampled at 2.9), the sheet's Voronoi
// vertices hug the fine face and their balls poke through the coarse one
// between its samples (by ~1 at r 2.4 on the flange: one contact instead of
// two for 15 % of its vertices). So each face near a convex edge is graded
// from the edge's spacing (the finer face's, computeSpacings), growing by
// kConvexEdgeGrading per unit of distance from it.
// A narrow face (narrowFaceSources, `sources` here) is finer near its close
// edges, and where such an edge is convex the face across takes that on too,
// near where the face is narrow only (the riser of a step makes the tread
// fine along it, and the step's sides only near its ends). A
// field holds one set of sources: the narrow faces' and the convex edges'.
void gradeFacesFromConvexEdges(SamplingContext& ctx, std::vector<std::vector<FaceSpacingField::Source>> sources) {
  const SolidTopology& topo = ctx.topo;
  std::vector<std::unique_ptr<SpacingSources>> narrow(topo.faceCount());
  for (int f = 0; f < topo.faceCount(); ++f)
    if (!sources[f].empty()) narrow[f] = std::make_unique<SpacingSources>(sources[f], FaceSpacingField::kConvexEdgeGrading);
  // Each edge's points in parallel, then handed to its faces in edge order
  // (the same sources on any number of threads).
  std::vector<std::vector<FaceSpacingField::Source>> alongEdge(topo.edgeCount());
  parallelForInOrder(topo.edgeCount(), [&](int e) {
    if (topo.edgeDegenerate[e] || ctx.edgeFeatures[e].kind != EdgeKind::Convex) return;
    const double s = ctx.edgeSpacing[e];
    double finest = s;
    for (int f : topo.edgeFaces[e])
      if (f >= 0 && narrow[f]) finest = std::min(finest, narrow[f]->finest());  // sources are >= the floor
    if (!(finest < ctx.spacing)) return;  // nothing finer to pass on
    BRepAdaptor_Curve curve(topo.edge(e));
    // Points the finest spacing apart, as many as the edge's own samples
    // there (the k-d tree of SpacingSources takes them all): a point's
    // distance to the edge is off by at most finest / 2, its spacing by
    // kConvexEdgeGrading × finest / 2. (At most 257 while the grading lived
    // on the field's nodes only: a 1000 mm edge at 1 then allowed 2 next to it.)
    const double length = ctx.edgeFeatures[e].length;
    const double points = std::ceil(length / finest);
    const int n = std::isfinite(points) ? static_cast<int>(std::clamp(points, 2.0, 1e7)) : 2;
    std::vector<FaceSpacingField::Source>& along = alongEdge[e];
    for (int i = 0; i <= n; ++i) {
      const gp_Pnt p = curve.Value(curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * i / n);
      double spacing = s;
      for (int f : topo.edgeFaces[e])
        if (f >= 0 && narrow[f]) spacing = narrow[f]->allowedNear(p, 0, spacing);
      if (spacing < ctx.spacing) along.push_back({p, spacing});
    }
  });
  for (int e = 0; e < topo.edgeCount(); ++e)
    for (int f : topo.edgeFaces[e])
      if (f >= 0) sources[f].insert(sources[f].end(), alongEdge[e].begin(), alongEdge[e].end());
  parallelForInOrder(topo.faceCount(), [&](int f) {
    ctx.faceSpacing[f].gradeFrom(std::move(sources[f]), FaceSpacingField::kConvexEdgeGrading);
  });
}

// Fewest steps each edge needs so that every boundary loop of a face has at
// least three distinct samples, which a face's triangulation needs: 3 on an
// edge closing on itself, 2 on an edge of a wire with two edges (a circle
// split in halves, a lens). The curvature spacing (0.15 × radius) asks for
// far more, except where the finest spacing clamps it: on a pin of radius
// 0.05 on a 200 mm part, a circle of one step left its face with no
// boundary loop, and the face triangulation crashed (2026-12-06).
// (Also asking for a step per quarter turn changed 6 arcs of NIST CTC-01,
// radius 0.6 at a finest spacing of 1.45, and none of the parts it was
// meant for: not kept.)
std::vector<int> minimumEdgeSegments(const SolidTopology& topo) {
  std::vector<int> fewest(topo.edgeCount(), 1);
  for (int e = 0; e < topo.edgeCount(); ++e)
    if (!topo.edgeDegenerate[e] && topo.edgeVertices[e][0] == topo.edgeVertices[e][1]) fewest[e] = 3;
  for (int f = 0; f < topo.faceCount(); ++f)
    for (TopExp_Explorer w(topo.face(f), TopAbs_WIRE); w.More(); w.Next()) {
      std::vector<int> edges;
      for (TopExp_Explorer x(w.Current(), TopAbs_EDGE); x.More(); x.Next()) {
        const int e = topo.edges.FindIndex(x.Current()) - 1;
        if (e >= 0 && !topo.edgeDegenerate[e] && std::find(edges.begin(), edges.end(), e) == edges.end())
          edges.push_back(e);
      }
      if (edges.size() == 2)
        for (int e : edges) fewest[e] = std::max(fewest[e], 2);
    }
  return fewest;
}

}  // namespace

void computeSpacings(SamplingContext& ctx) {
  const SolidTopology& topo = ctx.topo;
  ctx.faceSpacing.clear();
  ctx.faceSpacing.reserve(topo.faceCount());
  {
    // Faces in parallel, each thread casting its rays through its own copy
    // of the caster (OCCT's face intersectors keep their last hits); every
    // field is the same on any number of threads.
    std::vector<std::optional<FaceSpacingField>> fields(topo.faceCount());
    const SolidRayCaster solidRays(topo.solid, FaceSpacingField::rayTolerance(ctx.spacing));
    tbb::enumerable_thread_specific<SolidRayCaster> rays(solidRays);
    parallelForInOrder(topo.faceCount(), [&](int f) {
      fields[f].emplace(topo.face(f), rays.local(), ctx.minSpacing, ctx.spacing, ctx.gradedSpacing, ctx.boundsScale);
    });
    for (std::optional<FaceSpacingField>& field : fields) ctx.faceSpacing.push_back(std::move(*field));
  }

  // Each edge's curvature, once for both passes below; the tightest for
  // the warning (warnAboutUnresolvedCurves).
  std::vector<double> radius(topo.edgeCount(), 1e300);
  for (int e = 0; e < topo.edgeCount(); ++e) {
    if (topo.edgeDegenerate[e]) continue;
    gp_Pnt tightest;
    radius[e] = edgeMinCurvatureRadius(topo.edge(e), &tightest);
    if (radius[e] < ctx.tightestEdgeRadius) {
      ctx.tightestEdgeRadius = radius[e];
      ctx.tightestEdgeAt = tightest;
    }
  }

  // An edge is sampled at the spacing its own curvature and its faces'
  // fields ask for along it: evenly at the smallest of them on the first
  // pass (the faces' grading from convex edges reads it), then, once the
  // faces are graded, following them along its length (`along`).
  auto spaceEdges = [&](bool along) {
    ctx.edgeSpacing.assign(topo.edgeCount(), ctx.spacing);
    ctx.edgeSpacingAlong.assign(topo.edgeCount(), {});
    for (int e = 0; e < topo.edgeCount(); ++e) {
      if (topo.edgeDegenerate[e]) continue;
      const double curvature = kCurvatureFraction * ctx.boundsScale * radius[e];
      BRepAdaptor_Curve curve(topo.edge(e));
      const double length = ctx.edgeFeatures[e].length;
      // Points where the fields are read: 17 evenly in the parameter, or
      // when following them, evenly in arc length, about h/2 apart (so an
      // edge's smallest value can differ a little between the passes even
      // where it does not vary much).
      const int n = along ? static_cast<int>(std::clamp(std::ceil(2 * length / ctx.spacing), 16.0, 256.0)) : 16;
      std::vector<double> params(n + 1), spacing(n + 1, curvature);
      for (int i = 0; i <= n; ++i)
        params[i] = along ? GCPnts_AbscissaPoint(curve, length * i / n, curve.FirstParameter()).Parameter()
                          : curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * i / n;
      for (int f : topo.edgeFaces[e]) {
        if (f < 0) continue;
        const FaceSpacingField& field = ctx.faceSpacing[f];
        for (int i = 0; i <= n; ++i) {
          if (field.minimum() == field.maximum()) {  // uniform: no need to find the edge on the face
            spacing[i] = std::min(spacing[i], field.minimum());
            continue;
          }
          const gp_Pnt2d uv = uvOnFace(topo.edge(e), topo.face(f), params[i]);
          spacing[i] = std::min(spacing[i], field.at(uv.X(), uv.Y(), curve.Value(params[i])));
        }
      }
      for (double& s : spacing) s = clampSpacing(s, ctx);
      const auto [lowest, highest] = std::minmax_element(spacing.begin(), spacing.end());
      ctx.edgeSpacing[e] = *lowest;
      if (along && *highest > *lowest * (1 + 1e-9) && length > 0)
        for (int i = 0; i <= n; ++i) ctx.edgeSpacingAlong[e].push_back({length * i / n, spacing[i]});
    }
  };
  spaceEdges(false);
  // Faces graded from their convex edges; then the edges again, following
  // the faces along their length: a face may now be finer near one end of
  // another of its edges (a corner where a fine edge meets a coarse one), and
  // face samples finer than the edge's next to it cut between its samples
  // and their triplets. Once, not to a fixed point: an edge made finer here
  // does not grade its faces in turn (a face can still meet a finer edge one
  // corner further on). Until 2026-12-03 the second pass sampled such an
  // edge at its finest value over its whole length: on CTC-01 141 of 418
  // edges, 1.8 k edge samples (and their triplets) more.
  if (ctx.gradedSpacing) {
    gradeFacesFromConvexEdges(
        ctx, narrowFaceSources(topo, ctx.minSpacing, ctx.spacing, FaceSpacingField::kWidthFraction * ctx.boundsScale));
    spaceEdges(true);
  }

  ctx.cornerRadius.assign(topo.vertexCount(), 0.0);
  for (int v = 0; v < topo.vertexCount(); ++v) {
    if (!ctx.vertexFeatures[v].isCorner) continue;
    double r = 1e300;
    for (int e : topo.vertexEdges[v])
      r = std::min({r, kCornerBallFraction * ctx.edgeFeatures[e].length, edgeSpacingAt(ctx, e, v)});
    ctx.cornerRadius[v] = r < 1e300 ? r : 0.0;
  }
}

void sampleVerticesAndEdges(SamplingContext& ctx, SampleBuilder& builder) {
  const SolidTopology& topo = ctx.topo;
  SampleSet& set = builder.set();
  set.vertices.assign(topo.vertexCount(), {});
  set.edges.assign(topo.edgeCount(), {});
  ctx.edgeParams.assign(topo.edgeCount(), {});
  ctx.vertexSample.assign(topo.vertexCount(), kNoIndex);
  const std::vector<int> fewestSegments = minimumEdgeSegments(topo);

  for (int v = 0; v < topo.vertexCount(); ++v) {
    double nearby = ctx.spacing;
    for (int e : topo.vertexEdges[v]) nearby = std::min(nearby, edgeSpacingAt(ctx, e, v));
    const double ball = ctx.cornerRadius[v];
    const double exclusion = ball > 0 ? ball : 0.75 * nearby;
    const Index id =
        builder.add(BRep_Tool::Pnt(TopoDS::Vertex(topo.vertices(v + 1))), SampleKind::Corner, v, exclusion);
    ctx.vertexSample[v] = id;
    CornerInfo& info = set.vertices[v];
    info.sample = id;
    info.isCorner = ctx.vertexFeatures[v].isCorner;
    info.nonConcave = ctx.vertexFeatures[v].isCorner && ctx.vertexFeatures[v].nonConcave;
    info.ballRadius = ball;
    set.isNonConcaveCorner[id] = info.nonConcave ? 1 : 0;
  }

  for (int e = 0; e < topo.edgeCount(); ++e) {
    EdgeInfo& info = set.edges[e];
    const EdgeFeature& feat = ctx.edgeFeatures[e];
    info.kind = feat.kind;
    info.faceLeft = topo.edgeFaces[e][0];
    info.faceRight = topo.edgeFaces[e][1];
    info.length = feat.length;
    info.maxDihedralDeviationDeg = feat.maxDeviationDeg;
    if (topo.edgeDegenerate[e]) continue;

    BRepAdaptor_Curve curve(topo.edge(e));
    const auto [v0, v1] = topo.edgeVertices[e];
    const double t0 = curve.FirstParameter(), t1 = curve.LastParameter();
    const double a0 = v0 >= 0 ? ctx.cornerRadius[v0] : 0.0, a1 = v1 >= 0 ? ctx.cornerRadius[v1] : 0.0;
    // Arc positions of the ball points and interior samples, from a0 to
    // length - a1; each sample's exclusion and leg from its own step.
    const std::vector<std::array<double, 2>>& profile = ctx.edgeSpacingAlong[e];
    const double inner = feat.length - a0 - a1;
    const std::vector<double> arcs = sampleArcs(profile, ctx.edgeSpacing[e], a0, inner, fewestSegments[e]);
    const int segments = static_cast<int>(arcs.size()) - 1;
    const double evenStep = inner / segments;

    info.samples.push_back(ctx.vertexSample[v0]);
    ctx.edgeParams[e].push_back(t0);
    const int first = a0 > 0 ? 0 : 1, last = a1 > 0 ? segments : segments - 1;
    for (int k = first; k <= last; ++k) {
      const double step = profile.empty() ? evenStep
                                          : std::min(k > 0 ? arcs[k] - arcs[k - 1] : 1e300,
                                                     k < segments ? arcs[k + 1] - arcs[k] : 1e300);
      const double leg = kLegFraction * std::min({step, a0 > 0 ? a0 : 1e300, a1 > 0 ? a1 : 1e300});
      const double exclusion = feat.sharp() ? 1.05 * std::max(leg, 0.75 * step) : 0.75 * step;
      const double t = GCPnts_AbscissaPoint(curve, arcs[k], t0).Parameter();
      const Index id = builder.add(curve.Value(t), SampleKind::Edge, e, exclusion);
      info.samples.push_back(id);
      ctx.edgeParams[e].push_back(t);
    }
    info.samples.push_back(ctx.vertexSample[v1]);
    ctx.edgeParams[e].push_back(t1);

    if (feat.kind == EdgeKind::Convex)
      for (Index id : info.samples) set.onConvexEdge[id] = 1;
  }

  // A vertex inside a convex edge chain (a tangent pass-through, e.g. where a
  // split rim circle joins) is not a corner, but its interior tangent cone is
  // a wedge: the inner axis must attach there exactly as at a non-concave
  // corner, so core completes the axis at it the same way.
  for (int v = 0; v < topo.vertexCount(); ++v) {
    const VertexFeature& vf = ctx.vertexFeatures[v];
    if (vf.isCorner || vf.sharpEdgeEnds != 2) continue;
    bool allConvex = true;
    for (int e : topo.vertexEdges[v])
      if (ctx.edgeFeatures[e].kind == EdgeKind::Concave) allConvex = false;
    if (allConvex) set.isNonConcaveCorner[ctx.vertexSample[v]] = 1;
  }
}

namespace {

// The point of `face` at distance `leg` from s in the plane through s normal
// to the unit `tangent`, found by Newton's method in UV from `uv`. Converged
// when within 1e-13 × the leg, plus what rounding leaves of p − s where the
// coordinates are large: a part 1 m from the origin has p and s each a few
// 1e-13 off, more than 1e-13 × a 1 mm leg, and every Newton run failed there
// (a filleted box moved by (1, −2, 0.5) m lost 157 of 267 triplets and 55 %
// of its convex-edge attachment; moved by 10 m, 263 of them).
bool solveLegPoint(const BRepAdaptor_Surface& surf, const gp_Pnt& s, const gp_Vec& tangent, double leg,
                   gp_Pnt2d& uv) {
  const double rounding = 16 * std::numeric_limits<double>::epsilon() *
                          (std::abs(s.X()) + std::abs(s.Y()) + std::abs(s.Z()) + leg);
  for (int iter = 0; iter < 30; ++iter) {
    gp_Pnt p;
    gp_Vec su, sv;
    surf.D1(uv.X(), uv.Y(), p, su, sv);
    const gp_Vec d(s, p);
    const double f1 = d.Dot(tangent), f2 = d.SquareMagnitude() - leg * leg;
    if (std::abs(f1) < 1e-13 * leg + rounding && std::abs(f2) < 1e-13 * leg * leg + 2 * leg * rounding) return true;
    const double a = su.Dot(tangent), b = sv.Dot(tangent);
    const double c = 2 * d.Dot(su), e = 2 * d.Dot(sv);
    const double det = a * e - b * c;
    if (std::abs(det) < 1e-300) return false;
    uv.SetCoord(uv.X() - (f1 * e - b * f2) / det, uv.Y() - (a * f2 - c * f1) / det);
  }
  return false;
}

// A reproducible number in [0, 1) per (edge, sample): a small integer hash.
double legJitter(unsigned edge, unsigned k) {
  std::uint32_t x = edge * 2654435761u ^ (k + 0x9e3779b9u + (edge << 6) + (edge >> 2));
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return (x & 0xFFFFFF) / static_cast<double>(0x1000000);
}

// UV of the point s + leg * dir on the face's tangent plane (first-order).
gp_Pnt2d uvStep(const BRepAdaptor_Surface& surf, const gp_Pnt2d& uv, const gp_Vec& dir) {
  gp_Pnt p;
  gp_Vec su, sv;
  surf.D1(uv.X(), uv.Y(), p, su, sv);
  const double a = su.Dot(su), b = su.Dot(sv), c = sv.Dot(sv);
  const double r1 = su.Dot(dir), r2 = sv.Dot(dir);
  const double det = a * c - b * b;
  if (std::abs(det) < 1e-300) return uv;
  return gp_Pnt2d(uv.X() + (r1 * c - b * r2) / det, uv.Y() + (a * r2 - b * r1) / det);
}

// Where the two faces of a convex edge meet at a small angle α (a knife
// edge), the chord across the wedge at distance d from the edge is
// 2 d sin(α/2): shorter than the spacing out to d = spacing / (2 sin(α/2)),
// 7 spacings at 8°. Face samples there, unpaired across a wall thinner
// than their spacing, put Voronoi vertices far off the bisector and out of
// the solid (an 8° wedge at h 1.69: vertices 0.17 mm outside at 0.8 mm
// from the edge, the sheet in 130 pieces, β 2,19). Rungs continue a
// triplet's legs: pairs of samples at equal distance from the edge sample
// in its normal plane, one on each face, out to where that chord is
// kRungWallFraction × the edge spacing (kMaxRungs at most). Each pair is a
// mirror image across the bisector (exactly on planar faces), and the
// Voronoi vertices between mirror pairs lie on it. Spaced like face
// samples (a gap of ~0.85 × the edge spacing, with the face samples'
// exclusion radius, so that darts keep out of the ladder); the ladder
// stops where either rung of a pair would leave its face, come within half
// a gap of another sample or inside its exclusion radius, or no longer
// solves. Returns the number of rung samples placed. Not in seed 002 (its
// triplets only).
struct LadderSide {
  const BRepAdaptor_Surface* surf;
  int face;
  FaceUVClassifier* classifier;
  gp_Vec tangent;
  gp_Pnt2d uv;   // last rung's (the leg's to start)
  gp_Pnt point;  // last rung's
};

// One triplet's ladder, placed once every triplet is (a rung must not take
// the spot of another edge's leg).
struct Ladder {
  Index s;
  gp_Pnt sp;
  double leg, step, sinHalfAngle;
  unsigned edge, k;
  LadderSide sides[2];
};

constexpr int kMaxRungs = 40;  // per side: a wedge of ~2° reaches that far

std::size_t placeRungs(SamplingContext& ctx, SampleBuilder& builder, Ladder& ladder) {
  const double reach = kRungWallFraction * ladder.step / (2 * ladder.sinHalfAngle);
  std::size_t placed = 0;
  double d = ladder.leg;
  for (unsigned rung = 1; rung <= kMaxRungs; ++rung) {
    const double gap = kRungGapFraction * ladder.step * (1.0 - 0.1 * legJitter(ladder.edge, 7919 * ladder.k + rung));
    d += gap;
    if (d > reach) break;
    gp_Pnt2d uv[2];
    for (int i = 0; i < 2; ++i) {
      LadderSide& side = ladder.sides[i];
      gp_Vec out(ladder.sp, side.point);
      if (out.Magnitude() <= 0) return placed;
      out.Normalize();
      uv[i] = uvStep(*side.surf, side.uv, out * gap);
      if (!solveLegPoint(*side.surf, ladder.sp, side.tangent, d, uv[i]) ||
          side.classifier->Perform(uv[i]) != TopAbs_IN ||
          !builder.isClear(side.surf->Value(uv[i].X(), uv[i].Y()), 0.5 * gap, ladder.s))
        return placed;
    }
    for (int i = 0; i < 2; ++i) {
      LadderSide& side = ladder.sides[i];
      side.uv = uv[i];
      side.point = side.surf->Value(uv[i].X(), uv[i].Y());
      ctx.recordFaceUv(builder.add(side.point, SampleKind::Face, side.face, 0.75 * ladder.step), uv[i]);
      ++placed;
    }
  }
  return placed;
}

}  // namespace

void placeTriplets(SamplingContext& ctx, SampleBuilder& builder) {
  const SolidTopology& topo = ctx.topo;
  SampleSet& set = builder.set();
  std::map<int, std::unique_ptr<FaceUVClassifier>> classifiers;
  auto classifier = [&](int f) -> FaceUVClassifier& {
    auto& slot = classifiers[f];
    if (!slot) slot = std::make_unique<FaceUVClassifier>(topo.face(f), 1e-9);
    return *slot;
  };
  std::map<int, std::unique_ptr<BRepAdaptor_Surface>> surfaces;  // the ladders' (kept past their edge)
  auto surface = [&](int f) -> const BRepAdaptor_Surface& {
    auto& slot = surfaces[f];
    if (!slot) slot = std::make_unique<BRepAdaptor_Surface>(topo.face(f), false);
    return *slot;
  };
  std::vector<Ladder> ladders;

  for (int e = 0; e < topo.edgeCount(); ++e) {
    if (ctx.edgeFeatures[e].kind != EdgeKind::Convex) continue;
    const EdgeInfo& info = set.edges[e];
    const int faces[2] = {info.faceLeft, info.faceRight};
    BRepAdaptor_Surface surfs[2] = {BRepAdaptor_Surface(topo.face(faces[0]), false),
                                    BRepAdaptor_Surface(topo.face(faces[1]), false)};
    const std::size_t n = info.samples.size();
    for (std::size_t k = 1; k + 1 < n; ++k) {  // ends are vertex samples: no triplet
      const Index s = info.samples[k];
      const double t = ctx.edgeParams[e][k];
      EdgeFaceFrame frames[2] = {edgeFaceFrame(topo.edge(e), topo.face(faces[0]), t),
                                 edgeFaceFrame(topo.edge(e), topo.face(faces[1]), t)};
      if (!frames[0].valid || !frames[1].valid) {
        ++ctx.tripletsDropped;
        continue;
      }
      const gp_Pnt sp(set.points[s][0], set.points[s][1], set.points[s][2]);
      // Leg: a fraction of the distance to the neighbouring edge samples and balls.
      const auto& prev = set.points[info.samples[k - 1]];
      const auto& next = set.points[info.samples[k + 1]];
      // Legs vary by up to -10 % from triplet to triplet (deterministically):
      // equal legs on consecutive triplets of a straight edge would make
      // rectangles s s' s'_l s_l, four cocircular coplanar samples whose flat
      // Delaunay cells have no circumcenter.
      const double jitter = 1.0 - 0.1 * legJitter(static_cast<unsigned>(e), static_cast<unsigned>(k));
      const double step =
          std::min(sp.Distance(gp_Pnt(prev[0], prev[1], prev[2])), sp.Distance(gp_Pnt(next[0], next[1], next[2])));
      double leg = jitter * kLegFraction * step;
      bool placed = false;
      for (int attempt = 0; attempt < 4 && !placed; ++attempt, leg *= 0.5) {
        gp_Pnt2d uv[2];
        bool ok = true;
        for (int side = 0; side < 2 && ok; ++side) {
          uv[side] = uvStep(surfs[side], frames[side].uv, frames[side].intoFace * leg);
          ok = solveLegPoint(surfs[side], sp, frames[side].tangent, leg, uv[side]) &&
               classifier(faces[side]).Perform(uv[side]) == TopAbs_IN &&
               builder.isClear(surfs[side].Value(uv[side].X(), uv[side].Y()), 0.5 * leg, s, false);
        }
        if (!ok) continue;
        Index legs[2];
        for (int side = 0; side < 2; ++side) {
          legs[side] = builder.add(surfs[side].Value(uv[side].X(), uv[side].Y()), SampleKind::Face, faces[side],
                                   1.05 * leg);
          ctx.recordFaceUv(legs[side], uv[side]);
        }
        Triplet trip;
        trip.s = s;
        trip.sLeft = legs[0];
        trip.sRight = legs[1];
        trip.prev = info.samples[k - 1];
        trip.next = info.samples[k + 1];
        trip.edge = e;
        set.triplets.push_back(trip);
        placed = true;
        // Knife edge: the into-face directions make the wedge's angle α.
        const double lengths = frames[0].intoFace.Magnitude() * frames[1].intoFace.Magnitude();
        const double cosAngle = lengths > 1e-300 ? frames[0].intoFace.Dot(frames[1].intoFace) / lengths : 1.0;
        const double sinHalfAngle = std::sqrt(std::max(0.0, 0.5 * (1 - cosAngle)));
        if (sinHalfAngle > 0 && kRungWallFraction * step / (2 * sinHalfAngle) > leg) {
          Ladder ladder{s, sp, leg, step, sinHalfAngle, static_cast<unsigned>(e), static_cast<unsigned>(k), {}};
          for (int side = 0; side < 2; ++side)
            ladder.sides[side] = {&surface(faces[side]), faces[side], &classifier(faces[side]), frames[side].tangent,
                                  uv[side], surfs[side].Value(uv[side].X(), uv[side].Y())};
          ladders.push_back(ladder);
        }
      }
      if (!placed) ++ctx.tripletsDropped;
    }
  }
  for (Ladder& ladder : ladders) ctx.rungSamples += placeRungs(ctx, builder, ladder);
}

}  // namespace cadmedial
