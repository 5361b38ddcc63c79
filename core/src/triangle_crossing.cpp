#include "triangle_crossing.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>

namespace cadmedial {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

Point point(const std::vector<Vec3>& nodes, Index n) { return {nodes[n][0], nodes[n][1], nodes[n][2]}; }

// Rays v->p and v->q along each other (same line, same direction).
bool runAlong(const Point& v, const Point& p, const Point& q) {
  return CGAL::collinear(v, p, q) && CGAL::angle(p, v, q) == CGAL::ACUTE;
}

// In the plane of v, a, b (all coplanar with p): p strictly inside the angle a v b.
bool insideAngle(const Point& v, const Point& a, const Point& b, const Point& p) {
  const auto side = CGAL::coplanar_orientation(v, a, b);
  return side != CGAL::COLLINEAR && CGAL::coplanar_orientation(v, a, p) == side &&
         CGAL::coplanar_orientation(v, b, p) == CGAL::coplanar_orientation(v, b, a);
}

// Sharing corner v only: T = (v, t1, t2), U = (v, u1, u2).
bool crossAtCorner(const Point& v, const Point& t1, const Point& t2, const Point& u1, const Point& u2) {
  const Kernel::Triangle_3 T(v, t1, t2), U(v, u1, u2);
  if (CGAL::do_intersect(Kernel::Segment_3(t1, t2), U) || CGAL::do_intersect(Kernel::Segment_3(u1, u2), T))
    return true;
  // What else can meet: an edge from v running along one of the other's, or
  // (coplanar) one's edge from v inside the other's angle at v.
  for (const Point* a : {&t1, &t2})
    for (const Point* b : {&u1, &u2})
      if (runAlong(v, *a, *b)) return true;
  if (CGAL::orientation(v, u1, u2, t1) == CGAL::COPLANAR && CGAL::orientation(v, u1, u2, t2) == CGAL::COPLANAR)
    return insideAngle(v, u1, u2, t1) || insideAngle(v, u1, u2, t2) || insideAngle(v, t1, t2, u1) ||
           insideAngle(v, t1, t2, u2);
  return false;
}

// Sharing edge pq: T = (p, q, t), U = (p, q, u) meet beyond pq only when
// they are coplanar and on the same side of it (folded flat onto each other).
bool crossAtEdge(const Point& p, const Point& q, const Point& t, const Point& u) {
  if (CGAL::orientation(p, q, t, u) != CGAL::COPLANAR) return false;
  const auto st = CGAL::coplanar_orientation(p, q, t), su = CGAL::coplanar_orientation(p, q, u);
  return st == su || st == CGAL::COLLINEAR || su == CGAL::COLLINEAR;
}

}  // namespace

bool trianglesCross(const std::vector<Vec3>& nodes, const std::array<Index, 3>& t, const std::array<Index, 3>& u) {
  auto P = [&](Index i) { return point(nodes, i); };
  // A triangle without area (none of a Delaunay facet's, but a split point
  // could line up): counted as crossing, and CGAL's tests would not take it.
  if (CGAL::collinear(P(t[0]), P(t[1]), P(t[2])) || CGAL::collinear(P(u[0]), P(u[1]), P(u[2]))) return true;
  std::array<Index, 3> shared{};
  int n = 0;
  for (Index a : t)
    for (Index b : u)
      if (a == b) {
        if (n == 3) return true;  // a corner repeated: no triangle
        shared[n++] = a;
      }
  auto others = [&](const std::array<Index, 3>& tri) {
    std::array<Index, 3> o{};
    int k = 0;
    for (Index a : tri)
      if (std::find(shared.begin(), shared.begin() + n, a) == shared.begin() + n) o[k++] = a;
    return o;
  };
  const std::array<Index, 3> ot = others(t), ou = others(u);
  switch (n) {
    case 0:
      return CGAL::do_intersect(Kernel::Triangle_3(P(t[0]), P(t[1]), P(t[2])),
                                Kernel::Triangle_3(P(u[0]), P(u[1]), P(u[2])));
    case 1:
      return crossAtCorner(P(shared[0]), P(ot[0]), P(ot[1]), P(ou[0]), P(ou[1]));
    case 2:
      return crossAtEdge(P(shared[0]), P(shared[1]), P(ot[0]), P(ou[0]));
    default:
      return true;
  }
}

}  // namespace cadmedial
