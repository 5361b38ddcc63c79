#include "synthetic_samples.hpp"

#include "cadmedial/vec3_ops.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <stdexcept>
#include <unordered_map>

namespace cadmedial::testing {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

using vec3::add;
using vec3::cross;
using vec3::dot;
using vec3::mul;
using vec3::norm;
using vec3::sub;
Vec3 unit(const Vec3& a) { return mul(a, 1.0 / norm(a)); }

struct FaceFrame {
  Vec3 origin, n, u, v;
  Vec2 to2d(const Vec3& p) const {
    const Vec3 d = sub(p, origin);
    return {dot(d, u), dot(d, v)};
  }
  Vec3 to3d(const Vec2& q) const { return add(origin, add(mul(u, q[0]), mul(v, q[1]))); }
};

FaceFrame frameOf(const PlanarFace& f) {
  const auto& L = f.loops[0];
  Vec3 n{0, 0, 0};  // Newell
  for (std::size_t i = 0; i < L.size(); ++i) {
    const Vec3& a = L[i];
    const Vec3& b = L[(i + 1) % L.size()];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  FaceFrame fr;
  fr.origin = L[0];
  fr.n = unit(n);
  fr.u = unit(sub(L[1], L[0]));
  fr.v = cross(fr.n, fr.u);
  return fr;
}

bool insidePolygon2d(const std::vector<std::vector<Vec2>>& loops, const Vec2& p) {
  bool in = false;
  for (const auto& L : loops)
    for (std::size_t i = 0, j = L.size() - 1; i < L.size(); j = i++) {
      const Vec2& a = L[i];
      const Vec2& b = L[j];
      if ((a[1] > p[1]) != (b[1] > p[1]) && p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0]) in = !in;
    }
  return in;
}

double segmentDistance2d(const Vec2& p, const Vec2& a, const Vec2& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  double t = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy);
  t = std::clamp(t, 0.0, 1.0);
  const double ex = a[0] + t * dx - p[0], ey = a[1] + t * dy - p[1];
  return std::sqrt(ex * ex + ey * ey);
}

double boundaryDistance2d(const std::vector<std::vector<Vec2>>& loops, const Vec2& p) {
  double d = 1e300;
  for (const auto& L : loops)
    for (std::size_t i = 0; i < L.size(); ++i) d = std::min(d, segmentDistance2d(p, L[i], L[(i + 1) % L.size()]));
  return d;
}

std::vector<std::vector<Vec2>> loops2d(const PlanarFace& f, const FaceFrame& fr) {
  std::vector<std::vector<Vec2>> out;
  for (const auto& L : f.loops) {
    out.emplace_back();
    for (const auto& p : L) out.back().push_back(fr.to2d(p));
  }
  return out;
}

void computeBbox(SampleSet& s) {
  s.bboxMin = {1e300, 1e300, 1e300};
  s.bboxMax = {-1e300, -1e300, -1e300};
  for (const auto& p : s.points)
    for (int k = 0; k < 3; ++k) {
      s.bboxMin[k] = std::min(s.bboxMin[k], p[k]);
      s.bboxMax[k] = std::max(s.bboxMax[k], p[k]);
    }
}

Index addPoint(SampleSet& s, const Vec3& p, SampleKind kind, int owner) {
  s.points.push_back(p);
  s.kind.push_back(kind);
  s.owner.push_back(owner);
  s.onConvexEdge.push_back(0);
  s.isNonConcaveCorner.push_back(0);
  return static_cast<Index>(s.points.size() - 1);
}

// Per-face constrained Delaunay of the face's samples.
void triangulateFace(SampleSet& s, int faceId, const FaceFrame& fr, const std::vector<std::vector<Vec2>>& loops,
                     const std::vector<Index>& members, const std::vector<std::pair<Index, Index>>& constraints) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<Index, K>;
  using Fb = CGAL::Constrained_triangulation_face_base_2<K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
  CDT cdt;
  std::unordered_map<Index, CDT::Vertex_handle> handle;
  for (Index m : members) {
    const Vec2 q = fr.to2d(s.points[m]);
    auto vh = cdt.insert(K::Point_2(q[0], q[1]));
    vh->info() = m;
    handle[m] = vh;
  }
  for (const auto& c : constraints) cdt.insert_constraint(handle.at(c.first), handle.at(c.second));
  if (cdt.number_of_vertices() != members.size()) throw std::logic_error("face samples collide in 2D");
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const auto c = CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    if (!insidePolygon2d(loops, {c.x(), c.y()})) continue;
    s.triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
    s.triangleFace.push_back(faceId);
  }
}

}  // namespace

PlanarSolid extrudedPolygon(std::string name, const std::vector<Vec2>& outer, const std::vector<std::vector<Vec2>>& holes,
                            double height) {
  PlanarSolid solid;
  solid.name = std::move(name);
  std::vector<std::vector<Vec2>> all{outer};
  all.insert(all.end(), holes.begin(), holes.end());
  PlanarFace top, bottom;
  for (const auto& L : all) {
    std::vector<Vec3> t, b;
    for (const auto& p : L) t.push_back({p[0], p[1], height});
    for (auto it = L.rbegin(); it != L.rend(); ++it) b.push_back({(*it)[0], (*it)[1], 0.0});
    top.loops.push_back(t);
    bottom.loops.push_back(b);
  }
  solid.faces.push_back(top);
  solid.faces.push_back(bottom);
  for (const auto& L : all)
    for (std::size_t i = 0; i < L.size(); ++i) {
      const Vec2& p = L[i];
      const Vec2& q = L[(i + 1) % L.size()];
      PlanarFace side;
      side.loops.push_back({{p[0], p[1], 0.0}, {q[0], q[1], 0.0}, {q[0], q[1], height}, {p[0], p[1], height}});
      solid.faces.push_back(side);
    }
  solid.inside = [all, height](const Vec3& x) {
    return x[2] > 0 && x[2] < height && insidePolygon2d(all, {x[0], x[1]});
  };
  solid.boundaryDistance = [all, height](const Vec3& x) {
    double d = std::min(std::abs(x[2]), std::abs(height - x[2]));
    return std::min(d, boundaryDistance2d(all, {x[0], x[1]}));
  };
  return solid;
}

PlanarSolid makeBox(double a, double b, double c) {
  return extrudedPolygon("box", {{0, 0}, {a, 0}, {a, b}, {0, b}}, {}, c);
}

PlanarSolid makeLPrism() {
  return extrudedPolygon("L-prism", {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {}, 0.8);
}

PlanarSolid makeBoxWithSquareHole() {
  return extrudedPolygon("holed box", {{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{{0.6, 0.6}, {0.6, 1.4}, {1.4, 1.4}, {1.4, 0.6}}},
                         0.6);
}

SampleSet samplePlanarSolid(const PlanarSolid& solid, const SamplingOptions& o) {
  const double h = o.spacing;
  SampleSet s;
  s.spacing = h;
  s.faceCount = static_cast<int>(solid.faces.size());
  std::vector<FaceFrame> frames;
  std::vector<std::vector<std::vector<Vec2>>> faceLoops;
  for (const auto& f : solid.faces) {
    frames.push_back(frameOf(f));
    faceLoops.push_back(loops2d(f, frames.back()));
  }

  // Vertices -> corner samples.
  std::map<Vec3, int> vertexId;
  for (const auto& f : solid.faces)
    for (const auto& L : f.loops)
      for (const auto& p : L)
        if (!vertexId.count(p)) {
          const int id = static_cast<int>(vertexId.size());
          vertexId[p] = id;
        }
  s.vertices.resize(vertexId.size());
  std::vector<Index> cornerSample(vertexId.size());
  for (const auto& [p, id] : vertexId) {
    cornerSample[id] = addPoint(s, p, SampleKind::Corner, id);
    s.vertices[id].sample = cornerSample[id];
    s.vertices[id].isCorner = true;
    s.vertices[id].ballRadius = o.cornerBall * h;
  }

  // Edges: the face where a->b runs along its loop is faceLeft.
  struct EdgeRec {
    int a, b, faceLeft = -1, faceRight = -1;
  };
  std::vector<EdgeRec> edges;
  std::map<std::pair<int, int>, int> edgeOf;
  for (std::size_t fi = 0; fi < solid.faces.size(); ++fi)
    for (const auto& L : solid.faces[fi].loops)
      for (std::size_t i = 0; i < L.size(); ++i) {
        const int a = vertexId[L[i]], b = vertexId[L[(i + 1) % L.size()]];
        const auto key = std::make_pair(std::min(a, b), std::max(a, b));
        auto it = edgeOf.find(key);
        if (it == edgeOf.end()) {
          edgeOf[key] = static_cast<int>(edges.size());
          edges.push_back({a, b, static_cast<int>(fi), -1});
        } else {
          edges[it->second].faceRight = static_cast<int>(fi);
        }
      }
  std::vector<Vec3> vpos(vertexId.size());
  for (const auto& [p, id] : vertexId) vpos[id] = p;

  s.edges.resize(edges.size());
  std::vector<std::vector<Index>> legsOnFace(solid.faces.size());
  for (std::size_t ei = 0; ei < edges.size(); ++ei) {
    const EdgeRec& E = edges[ei];
    if (E.faceRight < 0) throw std::logic_error("open edge in test solid");
    const Vec3 A = vpos[E.a], B = vpos[E.b];
    const double L = norm(sub(B, A));
    const Vec3 e = mul(sub(B, A), 1.0 / L);
    const Vec3 nF = frames[E.faceLeft].n, nG = frames[E.faceRight].n;
    const Vec3 uF = cross(nF, e);  // into faceLeft
    const Vec3 uG = cross(e, nG);  // into faceRight
    const bool convex = dot(nF, uG) < 0;
    EdgeInfo& info = s.edges[ei];
    info.kind = convex ? EdgeKind::Convex : EdgeKind::Concave;
    info.faceLeft = E.faceLeft;
    info.faceRight = E.faceRight;
    info.length = L;
    info.maxDihedralDeviationDeg = 90.0;
    const double r = o.cornerBall * h;
    if (L < 2 * r + 0.1 * h) throw std::logic_error("edge too short for the corner balls");
    const int m = static_cast<int>(std::ceil((L - 2 * r) / (o.edgeStep * h)));
    info.samples.push_back(cornerSample[E.a]);
    for (int k = 0; k <= m; ++k) {
      const double t = r + (L - 2 * r) * k / m;
      info.samples.push_back(addPoint(s, add(A, mul(e, t)), SampleKind::Edge, static_cast<int>(ei)));
    }
    info.samples.push_back(cornerSample[E.b]);
    if (!convex) continue;
    for (Index v : info.samples) s.onConvexEdge[v] = 1;
    s.isNonConcaveCorner[cornerSample[E.a]] = 1;
    s.isNonConcaveCorner[cornerSample[E.b]] = 1;
    for (std::size_t k = 1; k + 1 < info.samples.size(); ++k) {
      const Index sv = info.samples[k];
      const Vec3 P = s.points[sv];
      Triplet t;
      t.s = sv;
      t.sLeft = addPoint(s, add(P, mul(uF, o.leg * h)), SampleKind::Face, E.faceLeft);
      t.sRight = addPoint(s, add(P, mul(uG, o.leg * h)), SampleKind::Face, E.faceRight);
      t.prev = info.samples[k - 1];
      t.next = info.samples[k + 1];
      t.edge = static_cast<int>(ei);
      s.triplets.push_back(t);
      legsOnFace[E.faceLeft].push_back(t.sLeft);
      legsOnFace[E.faceRight].push_back(t.sRight);
    }
  }
  for (auto& v : s.vertices) v.nonConcave = s.isNonConcaveCorner[v.sample] != 0;

  // Face interiors: dart throwing (Poisson disk) clear of the boundary band.
  std::mt19937 rng(o.seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  const double rmin = o.faceMinDistance * h;
  for (std::size_t fi = 0; fi < solid.faces.size(); ++fi) {
    const FaceFrame& fr = frames[fi];
    const auto& loops = faceLoops[fi];
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (const auto& L : loops)
      for (const auto& p : L)
        for (int k = 0; k < 2; ++k) {
          lo[k] = std::min(lo[k], p[k]);
          hi[k] = std::max(hi[k], p[k]);
        }
    const double cell = rmin;
    const int nx = static_cast<int>((hi[0] - lo[0]) / cell) + 1, ny = static_cast<int>((hi[1] - lo[1]) / cell) + 1;
    std::vector<std::vector<Vec2>> grid(static_cast<std::size_t>(nx) * ny);
    auto cellOf = [&](const Vec2& p) {
      const int i = std::clamp(static_cast<int>((p[0] - lo[0]) / cell), 0, nx - 1);
      const int j = std::clamp(static_cast<int>((p[1] - lo[1]) / cell), 0, ny - 1);
      return std::make_pair(i, j);
    };
    auto farEnough = [&](const Vec2& p, double r) {
      const auto [ci, cj] = cellOf(p);
      for (int i = std::max(0, ci - 2); i <= std::min(nx - 1, ci + 2); ++i)
        for (int j = std::max(0, cj - 2); j <= std::min(ny - 1, cj + 2); ++j)
          for (const auto& q : grid[static_cast<std::size_t>(i) * ny + j])
            if ((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) < r * r) return false;
      return true;
    };
    const double area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
    const std::size_t tries = static_cast<std::size_t>(30.0 * area / (rmin * rmin)) + 100;
    for (std::size_t t = 0; t < tries; ++t) {
      const Vec2 p{lo[0] + (hi[0] - lo[0]) * uni(rng), lo[1] + (hi[1] - lo[1]) * uni(rng)};
      if (!insidePolygon2d(loops, p) || boundaryDistance2d(loops, p) < o.clearance * h || !farEnough(p, rmin)) continue;
      const auto [ci, cj] = cellOf(p);
      grid[static_cast<std::size_t>(ci) * ny + cj].push_back(p);
      addPoint(s, fr.to3d(p), SampleKind::Face, static_cast<int>(fi));
    }
  }

  // Per-face reconstruction with the boundary samples as constraints.
  std::vector<std::vector<Index>> members(solid.faces.size());
  for (std::size_t i = 0; i < s.points.size(); ++i)
    if (s.kind[i] == SampleKind::Face) members[s.owner[i]].push_back(static_cast<Index>(i));
  for (std::size_t fi = 0; fi < solid.faces.size(); ++fi) {
    std::vector<std::pair<Index, Index>> constraints;
    std::vector<Index> boundary;
    for (const auto& L : solid.faces[fi].loops)
      for (std::size_t i = 0; i < L.size(); ++i) {
        const int a = vertexId[L[i]], b = vertexId[L[(i + 1) % L.size()]];
        const auto& info = s.edges[edgeOf[{std::min(a, b), std::max(a, b)}]];
        std::vector<Index> chain = info.samples;
        if (chain.front() != cornerSample[a]) std::reverse(chain.begin(), chain.end());
        for (std::size_t k = 0; k + 1 < chain.size(); ++k) constraints.emplace_back(chain[k], chain[k + 1]);
        boundary.insert(boundary.end(), chain.begin(), chain.end() - 1);
      }
    std::vector<Index> all = members[fi];
    all.insert(all.end(), boundary.begin(), boundary.end());
    triangulateFace(s, static_cast<int>(fi), frames[fi], faceLoops[fi], all, constraints);
  }
  s.buildUmbrellas();
  computeBbox(s);
  s.validate();
  return s;
}

SampleSet gridBoxSamples(int n, double h) {
  SampleSet s;
  s.spacing = h;
  s.faceCount = 6;
  std::map<std::array<int, 3>, Index> id;
  auto onSurface = [n](int i, int j, int k) { return i == 0 || j == 0 || k == 0 || i == n || j == n || k == n; };
  auto boundaryCount = [n](int i, int j, int k) {
    return (i == 0 || i == n) + (j == 0 || j == n) + (k == 0 || k == n);
  };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        if (!onSurface(i, j, k)) continue;
        const int b = boundaryCount(i, j, k);
        const SampleKind kind = b == 3 ? SampleKind::Corner : b == 2 ? SampleKind::Edge : SampleKind::Face;
        const Index v = addPoint(s, {i * h, j * h, k * h}, kind, 0);
        if (b >= 2) s.onConvexEdge[v] = 1;
        if (b == 3) s.isNonConcaveCorner[v] = 1;
        id[{i, j, k}] = v;
      }
  // Faces: axis a fixed at value 0 or n; triangulate the grid, orient outward.
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int face = axis * 2 + side;
      const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
      for (int u = 0; u < n; ++u)
        for (int v = 0; v < n; ++v) {
          auto P = [&](int du, int dv) {
            std::array<int, 3> c{};
            c[axis] = side * n;
            c[a1] = u + du;
            c[a2] = v + dv;
            return id.at(c);
          };
          // (a1, a2, axis) is right-handed: CCW in (a1,a2) has normal +axis.
          std::array<Index, 3> t1{P(0, 0), P(1, 0), P(1, 1)}, t2{P(0, 0), P(1, 1), P(0, 1)};
          if (side == 0) {
            std::swap(t1[1], t1[2]);
            std::swap(t2[1], t2[2]);
          }
          s.triangles.push_back(t1);
          s.triangles.push_back(t2);
          s.triangleFace.push_back(face);
          s.triangleFace.push_back(face);
        }
    }
  // Triplets on every edge point (not corners): legs are the grid neighbours
  // perpendicular to the edge, on the two faces.
  for (const auto& [c, v] : id) {
    if (s.kind[v] != SampleKind::Edge) continue;
    int along = -1;
    std::vector<int> fixedAxes;
    for (int a = 0; a < 3; ++a) {
      if (c[a] == 0 || c[a] == n) fixedAxes.push_back(a);
      else along = a;
    }
    Triplet t;
    t.s = v;
    std::array<int, 3> l = c, r = c, pv = c, nx = c;
    l[fixedAxes[0]] += c[fixedAxes[0]] == 0 ? 1 : -1;
    r[fixedAxes[1]] += c[fixedAxes[1]] == 0 ? 1 : -1;
    pv[along] -= 1;
    nx[along] += 1;
    t.sLeft = id.at(l);
    t.sRight = id.at(r);
    t.prev = id.at(pv);
    t.next = id.at(nx);
    s.triplets.push_back(t);
  }
  s.buildUmbrellas();
  computeBbox(s);
  s.validate();
  return s;
}

void finishPointCloud(SampleSet& s) {
  const std::size_t n = s.points.size();
  s.kind.assign(n, SampleKind::Face);
  s.owner.assign(n, 0);
  s.onConvexEdge.assign(n, 0);
  s.isNonConcaveCorner.assign(n, 0);
  computeBbox(s);
}

void hullUmbrellas(SampleSet& s) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<Index, K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb>;
  using DT = CGAL::Delaunay_triangulation_3<K, Tds>;
  std::vector<std::pair<K::Point_3, Index>> pts;
  Vec3 centroid{0, 0, 0};
  for (Index i = 0; i < s.points.size(); ++i) {
    pts.emplace_back(K::Point_3(s.points[i][0], s.points[i][1], s.points[i][2]), i);
    centroid = add(centroid, s.points[i]);
  }
  centroid = mul(centroid, 1.0 / static_cast<double>(s.points.size()));
  DT dt(pts.begin(), pts.end());
  s.triangles.clear();
  s.triangleFace.clear();
  std::vector<DT::Cell_handle> cells;
  dt.incident_cells(dt.infinite_vertex(), std::back_inserter(cells));
  for (auto c : cells) {
    const int inf = c->index(dt.infinite_vertex());
    std::array<Index, 3> t;
    int k = 0;
    for (int i = 0; i < 4; ++i)
      if (i != inf) t[k++] = c->vertex(i)->info();
    const Vec3 nrm = cross(sub(s.points[t[1]], s.points[t[0]]), sub(s.points[t[2]], s.points[t[0]]));
    if (dot(nrm, sub(s.points[t[0]], centroid)) < 0) std::swap(t[1], t[2]);
    s.triangles.push_back(t);
    s.triangleFace.push_back(0);
  }
  s.buildUmbrellas();
}

SampleSet ellipsoidCloud(const Vec3& axes, std::size_t count, unsigned seed, double jitter) {
  SampleSet s;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uni(-0.5, 0.5);
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (std::size_t i = 0; i < count; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5 + jitter * uni(rng)) / count;
    const double rr = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden * (i + jitter * uni(rng));
    s.points.push_back({axes[0] * rr * std::cos(phi), axes[1] * rr * std::sin(phi), axes[2] * z});
  }
  s.spacing = std::sqrt(4 * M_PI * axes[0] * axes[0] / count);
  s.faceCount = 1;
  finishPointCloud(s);
  hullUmbrellas(s);
  s.validate();
  return s;
}

}  // namespace cadmedial::testing
