// Per-face reconstruction (seed 002 §4.2.4): constrained Delaunay triangulation
// of each face's samples in its metric-scaled UV domain, with the boundary
// samples as constraints and holes removed. Edge samples are shared by index,
// so the union over faces is one stitched surface.
#include <algorithm>
#include <array>
#include <cmath>
#include <list>
#include <stdexcept>
#include <string>

#include <tbb/parallel_for.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS.hxx>

#include "sampling_context.hpp"

namespace cadmedial {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
struct DomainInfo {
  int nesting = -1;
  bool inDomain() const { return nesting % 2 == 1; }
};
// Sample index of a CDT vertex; kNoIndex marks a vertex CGAL created itself.
struct SampleRef {
  Index id = kNoIndex;
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<SampleRef, K>;
using Fbb = CGAL::Triangulation_face_base_with_info_2<DomainInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbb>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

// Nesting level of every face: 0 outside, +1 each time a constraint is crossed.
void markDomains(Cdt& cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info().nesting = -1;
  std::list<Cdt::Edge> border;
  auto flood = [&](Cdt::Face_handle start, int level) {
    std::list<Cdt::Face_handle> queue{start};
    while (!queue.empty()) {
      Cdt::Face_handle fh = queue.front();
      queue.pop_front();
      if (fh->info().nesting != -1) continue;
      fh->info().nesting = level;
      for (int i = 0; i < 3; ++i) {
        Cdt::Face_handle nb = fh->neighbor(i);
        if (nb->info().nesting != -1) continue;
        if (cdt.is_constrained(Cdt::Edge(fh, i)))
          border.push_back(Cdt::Edge(fh, i));
        else
          queue.push_back(nb);
      }
    }
  };
  flood(cdt.infinite_face(), 0);
  while (!border.empty()) {
    Cdt::Edge e = border.front();
    border.pop_front();
    Cdt::Face_handle nb = e.first->neighbor(e.second);
    if (nb->info().nesting == -1) flood(nb, e.first->info().nesting + 1);
  }
}

double triangleArea(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

struct LoopPoint {
  gp_Pnt2d uv;
  Index sample;
  int edge = -1;       // B-rep edge and 3D-curve parameter (edge = -1 at poles)
  double param = 0;
};

// Boundary loops of a face in UV, following wire order and edge orientation.
std::vector<std::vector<LoopPoint>> boundaryLoops(const SamplingContext& ctx, const SampleSet& set, int f) {
  const TopoDS_Face face = TopoDS::Face(ctx.topo.face(f).Oriented(TopAbs_FORWARD));
  std::vector<std::vector<LoopPoint>> loops;
  for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) {
    std::vector<LoopPoint> loop;
    for (BRepTools_WireExplorer we(TopoDS::Wire(w.Current()), face); we.More(); we.Next()) {
      const TopoDS_Edge& edge = we.Current();
      const int e = ctx.topo.edges.FindIndex(edge) - 1;
      double first, last;
      Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
      if (pcurve.IsNull() || e < 0) continue;
      std::vector<LoopPoint> pts;
      if (ctx.topo.edgeDegenerate[e]) {
        // A pole: one 3D point, a segment in UV. Several UV points, one sample.
        const auto [v0, v1] = ctx.topo.edgeVertices[e];
        (void)v1;
        constexpr int kPolePoints = 8;
        for (int k = 0; k <= kPolePoints; ++k)
          pts.push_back({pcurve->Value(first + (last - first) * k / kPolePoints), ctx.vertexSample[v0]});
      } else {
        const auto& samples = set.edges[e].samples;
        for (std::size_t k = 0; k < samples.size(); ++k)
          pts.push_back({uvOnFace(edge, face, ctx.edgeParams[e][k]), samples[k], e, ctx.edgeParams[e][k]});
      }
      if (we.Orientation() == TopAbs_REVERSED) std::reverse(pts.begin(), pts.end());
      // Consecutive edges share their vertex sample; their pcurves may miss
      // each other by the edge tolerance in UV, so keep one point per joint.
      std::size_t start = (!loop.empty() && !pts.empty() && loop.back().sample == pts.front().sample) ? 1 : 0;
      loop.insert(loop.end(), pts.begin() + start, pts.end());
    }
    if (loop.size() > 1 && loop.front().sample == loop.back().sample) loop.pop_back();
    // A loop of one or two samples bounds nothing the triangulation can
    // follow: the face would lose its hole, or have no triangle at all.
    // minimumEdgeSegments prevents it; a wire of degenerate edges only
    // (a face squeezed to a point) still ends here.
    if (loop.size() < 3)
      throw std::runtime_error("a boundary loop has only " + std::to_string(loop.size()) + " sample(s)");
    loops.push_back(std::move(loop));
  }
  return loops;
}

// Largest B-rep tolerance on a face, its edges and vertices: samples on the
// edges lie on the 3D curves, which miss the face's surface by up to this.
double faceTolerance(const TopoDS_Face& face) {
  double tolerance = BRep_Tool::Tolerance(face);
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next())
    tolerance = std::max(tolerance, BRep_Tool::Tolerance(TopoDS::Edge(e.Current())));
  for (TopExp_Explorer v(face, TopAbs_VERTEX); v.More(); v.Next())
    tolerance = std::max(tolerance, BRep_Tool::Tolerance(TopoDS::Vertex(v.Current())));
  return tolerance;
}

// True if a vertex of the triangulation adjacent to `from` (other than `to`
// itself) carries `to`'s sample id.
bool joinedElsewhere(const Cdt& cdt, Cdt::Vertex_handle from, Cdt::Vertex_handle to) {
  auto around = cdt.incident_vertices(from);
  const auto start = around;
  if (around == nullptr) return false;
  do {
    if (!cdt.is_infinite(around) && Cdt::Vertex_handle(around) != to && around->info().id == to->info().id) return true;
  } while (++around != start);
  return false;
}

constexpr double kOffSurfaceCos = 0.70710678;  // cos 45°: a triangle this far off the surface normal is wrong

// How well a UV triangle (counter-clockwise in the plane) follows the face:
// the cosine between its 3D normal and the exact surface normal Su x Sv at its
// UV centroid. Both are in the UV orientation, so the face's orientation
// cancels. 1 when the surface normal is undefined there (no verdict), 0 for a
// triangle without area in 3D. The vertices' sample ids must be set.
double alignmentWithSurface(const BRepAdaptor_Surface& surf, const SampleSet& set, double su, double sv,
                            Cdt::Vertex_handle a, Cdt::Vertex_handle b, Cdt::Vertex_handle c) {
  const Vec3 &pa = set.points[a->info().id], &pb = set.points[b->info().id], &pc = set.points[c->info().id];
  const gp_Vec n3 = gp_Vec(pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2])
                        .Crossed(gp_Vec(pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]));
  const double u = (a->point().x() + b->point().x() + c->point().x()) / (3 * su);
  const double v = (a->point().y() + b->point().y() + c->point().y()) / (3 * sv);
  gp_Pnt p;
  gp_Vec du, dv;
  surf.D1(u, v, p, du, dv);
  const gp_Vec ns = du.Crossed(dv);
  if (!(ns.Magnitude() > 1e-12 * du.Magnitude() * dv.Magnitude())) return 1.0;
  const double lengths = n3.Magnitude() * ns.Magnitude();
  return lengths > 0 ? n3.Dot(ns) / lengths : 0.0;
}

// A triangle that is fine in UV can stand on edge in space. At the pole of a
// degenerate edge, one 3D point is a whole UV segment: the triangle from one
// end of it to the next two samples of the edge leaving the other end has
// three points of one edge curve (bottle.brep, fillet corners: its normal was
// horizontal on a nearly horizontal surface). In the umbrella of those
// samples such a normal makes the Angle condition reject the edges straight
// across a thin wall, which leaves holes in the wall's medial sheet. Flip a
// free edge of a triangle more than 45° off the surface when both new
// triangles are convex in UV, have three distinct samples, and the worse of
// the two follows the surface better than the worse of the old two.
// The new edge a-d must not exist already in 3D: at a pole one sample has
// several UV copies, and an edge from d to another copy of a's sample would
// then be shared by more than two triangles of the stitched surface.
// Returns the number of edges flipped.
int flipTrianglesOffTheSurface(Cdt& cdt, const BRepAdaptor_Surface& surf, const SampleSet& set, double su,
                               double sv) {
  constexpr int kPasses = 8;
  auto distinct = [](Cdt::Vertex_handle a, Cdt::Vertex_handle b, Cdt::Vertex_handle c) {
    const Index x = a->info().id, y = b->info().id, z = c->info().id;
    return x != kNoIndex && y != kNoIndex && z != kNoIndex && x != y && y != z && x != z;
  };
  auto alignment = [&](Cdt::Face_handle f) {
    return distinct(f->vertex(0), f->vertex(1), f->vertex(2))
               ? alignmentWithSurface(surf, set, su, sv, f->vertex(0), f->vertex(1), f->vertex(2))
               : 1.0;  // pole triangles are dropped later
  };
  int flips = 0;
  for (int pass = 0; pass < kPasses; ++pass) {
    int flipsThisPass = 0;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      if (!f->info().inDomain()) continue;
      const double here = alignment(f);
      if (here >= kOffSurfaceCos) continue;
      int bestEdge = -1;
      double best = -2;
      for (int i = 0; i < 3; ++i) {
        if (f->is_constrained(i)) continue;
        const Cdt::Face_handle g = f->neighbor(i);
        if (cdt.is_infinite(g) || !g->info().inDomain()) continue;
        const auto a = f->vertex(i), b = f->vertex(Cdt::ccw(i)), c = f->vertex(Cdt::cw(i));
        const auto d = g->vertex(cdt.mirror_index(f, i));
        if (!distinct(a, b, d) || !distinct(a, d, c)) continue;
        if (joinedElsewhere(cdt, a, d) || joinedElsewhere(cdt, d, a)) continue;
        if (CGAL::orientation(a->point(), b->point(), d->point()) != CGAL::LEFT_TURN ||
            CGAL::orientation(a->point(), d->point(), c->point()) != CGAL::LEFT_TURN)
          continue;
        const double before = std::min(here, alignment(g));
        const double after = std::min(alignmentWithSurface(surf, set, su, sv, a, b, d),
                                      alignmentWithSurface(surf, set, su, sv, a, d, c));
        if (after > before + 1e-9 && after > best) {
          best = after;
          bestEdge = i;
        }
      }
      if (bestEdge < 0) continue;
      Cdt::Face_handle flipped = f;
      cdt.flip(flipped, bestEdge);  // both faces keep their (equal) nesting
      ++flipsThisPass;
    }
    flips += flipsThisPass;
    if (flipsThisPass == 0) break;
  }
  return flips;
}

// One face's triangles (already oriented outward) or the reason it failed.
struct FaceMesh {
  std::vector<std::array<Index, 3>> triangles;
  std::vector<double> deviation;  // per triangle, SampleSet::triangleDeviation
  int droppedTriangles = 0;
  int flippedEdges = 0;         // flipTrianglesOffTheSurface
  std::vector<std::uint8_t> offSurface;  // per triangle, SampleSet::triangleOffSurface
  double areaError = 0;  // |mesh area / exact area - 1|
  std::string problem;   // empty on success
};

FaceMesh reconstructFace(const SamplingContext& ctx, const SampleSet& set, int f, const std::vector<Index>& interior) {
  FaceMesh out;
  const TopoDS_Face& face = ctx.topo.face(f);
  try {
    BRepAdaptor_Surface surf(face, false);
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    // Scale UV by the mean metric so the 2D Delaunay criterion is close to 3D.
    double su = 0, sv = 0;
    constexpr int n = 6;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        gp_Pnt p;
        gp_Vec du, dv;
        surf.D1(u0 + (u1 - u0) * (i + 0.5) / n, v0 + (v1 - v0) * (j + 0.5) / n, p, du, dv);
        su += du.Magnitude();
        sv += dv.Magnitude();
      }
    su = su > 0 ? su / (n * n) : 1.0;
    sv = sv > 0 ? sv / (n * n) : 1.0;
    auto toPlane = [&](const gp_Pnt2d& uv) { return K::Point_2(uv.X() * su, uv.Y() * sv); };

    Cdt cdt;
    const auto loops = boundaryLoops(ctx, set, f);
    // The triangles' boundary sides are chords of the edge curves: the strip
    // of face between a chord and its arc has no triangle of its own, so the
    // triangle on the chord answers for it (its deviation includes the arc's
    // distance from the chord, measured on the 3D curve).
    std::vector<std::pair<std::array<Index, 2>, double>> chordErrors;
    for (const auto& loop : loops)
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const LoopPoint &a = loop[k], &b = loop[(k + 1) % loop.size()];
        if (a.edge < 0 || a.edge != b.edge || a.sample == b.sample) continue;
        const Vec3 &pa = set.points[a.sample], &pb = set.points[b.sample];
        const gp_Pnt ga(pa[0], pa[1], pa[2]), gb(pb[0], pb[1], pb[2]);
        const gp_Vec chord(ga, gb);
        const double length2 = chord.SquareMagnitude();
        BRepAdaptor_Curve curve(ctx.topo.edge(a.edge));
        double worst = 0;
        constexpr int kArcPoints = 7;
        for (int i = 1; i <= kArcPoints; ++i) {
          const gp_Pnt x = curve.Value(a.param + (b.param - a.param) * i / (kArcPoints + 1));
          const double t = length2 > 0 ? std::clamp(gp_Vec(ga, x).Dot(chord) / length2, 0.0, 1.0) : 0.0;
          worst = std::max(worst, x.Distance(ga.Translated(t * chord)));
        }
        chordErrors.push_back({{std::min(a.sample, b.sample), std::max(a.sample, b.sample)}, worst});
      }
    std::sort(chordErrors.begin(), chordErrors.end());
    for (const auto& loop : loops) {
      std::vector<Cdt::Vertex_handle> handles;
      for (const LoopPoint& p : loop) {
        Cdt::Vertex_handle vh = cdt.insert(toPlane(p.uv));
        vh->info().id = p.sample;
        handles.push_back(vh);
      }
      for (std::size_t k = 0; k < handles.size(); ++k) {
        Cdt::Vertex_handle a = handles[k], b = handles[(k + 1) % handles.size()];
        if (a != b) cdt.insert_constraint(a, b);
      }
    }
    // Interior samples in spatial (Hilbert) order, each located from the last
    // one: in dart order every insertion walked across the face, which made
    // this stage grow like n^1.5 (18 s of a 10^6-sample box). The Delaunay
    // triangulation of points in general position does not depend on the order.
    std::vector<K::Point_2> plane(interior.size());
    for (std::size_t k = 0; k < interior.size(); ++k) plane[k] = toPlane(ctx.faceSampleUv[interior[k]]);
    std::vector<std::size_t> order(interior.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    using SortTraits = CGAL::Spatial_sort_traits_adapter_2<K, CGAL::Pointer_property_map<K::Point_2>::type>;
    CGAL::spatial_sort(order.begin(), order.end(), SortTraits(CGAL::make_property_map(plane)));
    Cdt::Face_handle hint;
    for (std::size_t k : order) {
      Cdt::Vertex_handle vh = cdt.insert(plane[k], hint);
      hint = vh->face();
      if (vh->info().id == kNoIndex) vh->info().id = interior[k];
    }
    if (cdt.dimension() < 2) throw std::runtime_error("its samples do not span an area in UV");
    markDomains(cdt);
    out.flippedEdges = flipTrianglesOffTheSurface(cdt, surf, set, su, sv);
    const double tolerance = faceTolerance(face);
    // Bound on |S(uv) - T(uv)| over the UV triangle (SampleSet::triangleDeviation).
    // The error is e = S - T, linear in the vertex errors (samples off the
    // surface by up to the B-rep tolerance) plus a part that vanishes at the
    // vertices. For a quadratic part q = sum c_ij l_i l_j (l barycentric)
    // |q| <= sum_ij |c_ij| / 4 = sum of |q| at the 3 edge midpoints; the
    // factor 1.5 covers the higher-order terms, which are small against the
    // quadratic one at the sampling's density, and the grid maximum covers the
    // rest. Planar faces: S is affine in UV, only the tolerance remains.
    auto deviationOf = [&](Cdt::Face_handle fh) {
      gp_Pnt2d uv[3];
      gp_XYZ p[3];
      for (int i = 0; i < 3; ++i) {
        const K::Point_2& q = fh->vertex(i)->point();
        uv[i] = gp_Pnt2d(q.x() / su, q.y() / sv);
        const Vec3& x = set.points[fh->vertex(i)->info().id];
        p[i] = gp_XYZ(x[0], x[1], x[2]);
      }
      constexpr int kSteps = 4;
      double gridMax = 0, vertexMax = 0, midpointSum = 0;
      for (int i = 0; i <= kSteps; ++i)
        for (int j = 0; i + j <= kSteps; ++j) {
          const int k = kSteps - i - j;
          const double l[3] = {double(i) / kSteps, double(j) / kSteps, double(k) / kSteps};
          const gp_Pnt s = surf.Value(l[0] * uv[0].X() + l[1] * uv[1].X() + l[2] * uv[2].X(),
                                      l[0] * uv[0].Y() + l[1] * uv[1].Y() + l[2] * uv[2].Y());
          const double e = s.Distance(gp_Pnt(l[0] * p[0] + l[1] * p[1] + l[2] * p[2]));
          gridMax = std::max(gridMax, e);
          if (i == kSteps || j == kSteps || k == kSteps) vertexMax = std::max(vertexMax, e);
          constexpr int half = kSteps / 2;  // the edge midpoints (2,2,0), (0,2,2), (2,0,2)
          if ((i == 0 && j == half) || (j == 0 && k == half) || (k == 0 && i == half)) midpointSum += e;
        }
      double chordMax = 0;
      for (int i = 0; i < 3; ++i) {
        const Index a = fh->vertex(i)->info().id, b = fh->vertex((i + 1) % 3)->info().id;
        const std::array<Index, 2> key{std::min(a, b), std::max(a, b)};
        auto it = std::lower_bound(chordErrors.begin(), chordErrors.end(), std::make_pair(key, -1.0));
        for (; it != chordErrors.end() && it->first == key; ++it) chordMax = std::max(chordMax, it->second);
      }
      return 1.5 * std::max({gridMax, midpointSum + 4 * vertexMax, chordMax}) + 2 * tolerance;
    };
    // Pole fans: a UV triangle with two corners on one sample has no mesh
    // triangle; its patch is bounded by its deviation around the segment the
    // mesh has instead, which lies on the kept triangles at that sample.
    std::vector<std::pair<Index, double>> poles;
    double meshArea = 0;
    for (auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh) {
      if (!fh->info().inDomain()) continue;
      std::array<Index, 3> tri{fh->vertex(0)->info().id, fh->vertex(1)->info().id, fh->vertex(2)->info().id};
      if (tri[0] == kNoIndex || tri[1] == kNoIndex || tri[2] == kNoIndex)
        throw std::runtime_error("boundary constraints intersect in UV (surface type " +
                                 std::to_string(static_cast<int>(surf.GetType())) + ")");
      if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
        ++out.droppedTriangles;
        poles.emplace_back(tri[0] == tri[1] || tri[0] == tri[2] ? tri[0] : tri[1], deviationOf(fh));
        continue;
      }
      const bool offSurface =
          alignmentWithSurface(surf, set, su, sv, fh->vertex(0), fh->vertex(1), fh->vertex(2)) < kOffSurfaceCos;
      if (face.Orientation() == TopAbs_REVERSED) std::swap(tri[1], tri[2]);
      out.triangles.push_back(tri);
      out.offSurface.push_back(offSurface ? 1 : 0);
      out.deviation.push_back(deviationOf(fh));
      meshArea += triangleArea(set.points[tri[0]], set.points[tri[1]], set.points[tri[2]]);
    }
    for (const auto& [pole, d] : poles)
      for (std::size_t t = 0; t < out.triangles.size(); ++t)
        if (std::find(out.triangles[t].begin(), out.triangles[t].end(), pole) != out.triangles[t].end())
          out.deviation[t] = std::max(out.deviation[t], d);
    GProp_GProps props;
    BRepGProp::SurfaceProperties(face, props);
    out.areaError = props.Mass() > 0 ? std::abs(meshArea / props.Mass() - 1.0) : 0.0;
  } catch (const std::exception& e) {
    out.triangles.clear();
    out.deviation.clear();
    out.offSurface.clear();
    out.problem = e.what();
  } catch (const Standard_Failure& e) {
    out.triangles.clear();
    out.deviation.clear();
    out.offSurface.clear();
    out.problem = e.GetMessageString();
  }
  return out;
}

}  // namespace

ReconstructionReport reconstructFaces(SamplingContext& ctx, SampleSet& set) {
  ReconstructionReport report;
  const int nf = ctx.topo.faceCount();
  std::vector<std::vector<Index>> interior(nf);
  for (Index i = 0; i < set.points.size(); ++i)
    if (set.kind[i] == SampleKind::Face) interior[set.owner[i]].push_back(i);

  // Faces are independent: triangulate them in parallel, merge in face order
  // so the output does not depend on scheduling.
  std::vector<FaceMesh> meshes(nf);
  tbb::parallel_for(0, nf, [&](int f) { meshes[f] = reconstructFace(ctx, set, f, interior[f]); });

  std::vector<std::uint8_t> used(set.points.size(), 0);
  for (int f = 0; f < nf; ++f) {
    const FaceMesh& m = meshes[f];
    if (!m.problem.empty()) {
      ++report.facesFailed;
      report.problems.push_back("face " + std::to_string(f) + ": " + m.problem);
      continue;
    }
    report.droppedTriangles += m.droppedTriangles;
    report.flippedEdges += m.flippedEdges;
    report.misalignedTriangles += static_cast<int>(std::count(m.offSurface.begin(), m.offSurface.end(), 1));
    set.triangleOffSurface.insert(set.triangleOffSurface.end(), m.offSurface.begin(), m.offSurface.end());
    if (m.areaError > report.worstFaceAreaError) {
      report.worstFaceAreaError = m.areaError;
      report.worstFace = f;
    }
    for (const auto& tri : m.triangles) {
      set.triangles.push_back(tri);
      set.triangleFace.push_back(f);
      for (Index v : tri) used[v] = 1;
    }
    set.triangleDeviation.insert(set.triangleDeviation.end(), m.deviation.begin(), m.deviation.end());
  }
  for (Index i = 0; i < set.points.size(); ++i)
    if (set.kind[i] == SampleKind::Face && !used[i]) ++report.orphanSamples;
  return report;
}

}  // namespace cadmedial
