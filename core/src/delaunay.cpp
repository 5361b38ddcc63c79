#include "cadmedial/delaunay.hpp"

#include <tbb/parallel_for.h>

#include <CGAL/Mpzf.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "cadmedial/timer.hpp"

namespace cadmedial {

namespace {

// A nearly flat cell's fourth sample within this fraction of its longest
// edge of the other three's circle counts as cocircular (see below); edge
// samples and triplet legs are placed to ~1e-13.
constexpr double kCocircularTolerance = 1e-7;

// The circumcenter from exact products: relative to a, with b' = b - a etc.,
// it is (|b'|² c'×d' + |c'|² d'×b' + |d'|² b'×c') / (2 b'·(c'×d')). Mpzf adds,
// subtracts and multiplies doubles exactly without reducing fractions; the
// two conversions to double (within an ulp or two each), the division and
// the shift by a round: a few ulps of the offset, not the correctly rounded
// exact centre but far below the 1e-9 × diagonal at which coincident
// Voronoi vertices are welded (outputs matched the rational version byte
// for byte on every bundled, public and robustness part).
// Exact rationals spent ~30 µs a cell reducing fractions: the cylinder at
// h/4 has 18 k such slivers, and its Voronoi stage took 0.34 s (now 0.06 s).
DelaunayVoronoi::Point exactCircumcenter(const DelaunayVoronoi::Point& a, const DelaunayVoronoi::Point& b,
                                         const DelaunayVoronoi::Point& c, const DelaunayVoronoi::Point& d) {
  using CGAL::Mpzf;
  const Mpzf ax(a.x()), ay(a.y()), az(a.z());
  const Mpzf bx = Mpzf(b.x()) - ax, by = Mpzf(b.y()) - ay, bz = Mpzf(b.z()) - az;
  const Mpzf cx = Mpzf(c.x()) - ax, cy = Mpzf(c.y()) - ay, cz = Mpzf(c.z()) - az;
  const Mpzf dx = Mpzf(d.x()) - ax, dy = Mpzf(d.y()) - ay, dz = Mpzf(d.z()) - az;
  const Mpzf cdx = cy * dz - cz * dy, cdy = cz * dx - cx * dz, cdz = cx * dy - cy * dx;  // c' × d'
  const Mpzf dbx = dy * bz - dz * by, dby = dz * bx - dx * bz, dbz = dx * by - dy * bx;  // d' × b'
  const Mpzf bcx = by * cz - bz * cy, bcy = bz * cx - bx * cz, bcz = bx * cy - by * cx;  // b' × c'
  const Mpzf b2 = bx * bx + by * by + bz * bz, c2 = cx * cx + cy * cy + cz * cz, d2 = dx * dx + dy * dy + dz * dz;
  const double den = 2 * (bx * cdx + by * cdy + bz * cdz).to_double();
  return {a.x() + (b2 * cdx + c2 * dbx + d2 * bcx).to_double() / den,
          a.y() + (b2 * cdy + c2 * dby + d2 * bcy).to_double() / den,
          a.z() + (b2 * cdz + c2 * dbz + d2 * bcz).to_double() / den};
}

// Circumcenter of a Delaunay cell. A nearly flat cell (volume below 1e-10 of
// its longest edge cubed) is one of two things:
// * four cocircular samples (a rectangle of edge samples and triplet legs on
//   a planar face) lifted off their plane by rounding: the circumsphere is
//   then undefined up to that rounding and CGAL's formula returns a point
//   anywhere on the circle's axis, at infinity or far outside. The Voronoi
//   vertex degenerates to the circle's centre, which the largest facet's
//   circumcenter gives.
// * a genuine sliver, its fourth sample well off the others' circle: its
//   circumsphere is huge and its centre far away (outside the solid, over a
//   planar face of the hull). Taking the circle's centre there put a bogus
//   Voronoi vertex next to the face, with a radius that is no empty ball's
//   (trj4_d2-tc-214: an inner island of three such vertices, radius 7.4 with
//   a sample 1.65 away). Its centre comes from exact products instead.
DelaunayVoronoi::Point robustCircumcenter(const DelaunayVoronoi::Point& a, const DelaunayVoronoi::Point& b,
                                         const DelaunayVoronoi::Point& c, const DelaunayVoronoi::Point& d) {
  using K = DelaunayVoronoi::Kernel;
  const double volume = std::abs(CGAL::volume(a, b, c, d));
  double longest = 0;
  const DelaunayVoronoi::Point* pts[4] = {&a, &b, &c, &d};
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) longest = std::max(longest, CGAL::squared_distance(*pts[i], *pts[j]));
  const double scale = longest * std::sqrt(longest);  // ~ edge length cubed
  if (volume > 1e-10 * scale) {
    const auto cc = CGAL::circumcenter(a, b, c, d);
    if (std::isfinite(cc.x()) && std::isfinite(cc.y()) && std::isfinite(cc.z())) return cc;
  }
  int skip = 0;
  double bestArea = -1;
  for (int i = 0; i < 4; ++i) {
    const auto& p = *pts[(i + 1) % 4];
    const auto& q = *pts[(i + 2) % 4];
    const auto& r = *pts[(i + 3) % 4];
    const double area = K::Compute_squared_area_3()(p, q, r);
    if (area > bestArea) {
      bestArea = area;
      skip = i;
    }
  }
  const auto centre = CGAL::circumcenter(*pts[(skip + 1) % 4], *pts[(skip + 2) % 4], *pts[(skip + 3) % 4]);
  const double circleRadius = std::sqrt(CGAL::squared_distance(centre, *pts[(skip + 1) % 4]));
  const double fourth = std::sqrt(CGAL::squared_distance(centre, *pts[skip]));
  if (std::abs(fourth - circleRadius) <= kCocircularTolerance * std::sqrt(longest)) return centre;
  // A sliver. Its double circumcenter is enough when it lands 10^6 edges
  // away: at that distance only "far" matters (every later stage treats it
  // as outside), not the rounded direction. Otherwise the exact one
  // (exactCircumcenter, a few µs).
  const auto rounded = CGAL::circumcenter(a, b, c, d);
  if (std::isfinite(rounded.x()) && std::isfinite(rounded.y()) && std::isfinite(rounded.z()) &&
      CGAL::squared_distance(rounded, a) > 1e12 * longest)
    return rounded;
  const DelaunayVoronoi::Point far = exactCircumcenter(a, b, c, d);
  if (std::isfinite(far.x()) && std::isfinite(far.y()) && std::isfinite(far.z())) return far;
  return centre;
}

}  // namespace

DelaunayVoronoi::DelaunayVoronoi(const std::vector<Vec3>& points) {
  const std::size_t n = points.size();
  if (n >= kNoIndex) throw std::invalid_argument("too many samples for 32-bit indices");
  std::vector<std::pair<Point, Index>> input;
  input.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& p = points[i];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw std::invalid_argument("sample " + std::to_string(i) + " has a non-finite coordinate");
    input.emplace_back(Point(p[0], p[1], p[2]), static_cast<Index>(i));
  }

  Stopwatch watch;
  dt_.insert(input.begin(), input.end());  // spatial sort inside CGAL
  delaunaySeconds_ = watch.seconds();
  watch.restart();

  // Samples -> vertices. CGAL keeps the first-inserted info of merged points;
  // the others are found by locating their point (it lands on a vertex).
  vertex_.assign(n, Vertex_handle());
  canonical_.assign(n, kNoIndex);
  for (auto v = dt_.finite_vertices_begin(); v != dt_.finite_vertices_end(); ++v) {
    vertex_[v->info()] = v;
    canonical_[v->info()] = v->info();
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (canonical_[i] != kNoIndex) continue;
    ++duplicates_;
    Triangulation::Locate_type lt;
    int li = 0, lj = 0;
    Cell_handle c = dt_.locate(input[i].first, lt, li, lj);
    if (lt != Triangulation::VERTEX)
      throw std::logic_error("Delaunay: a merged sample is not at a vertex");
    vertex_[i] = c->vertex(li);
  }
  // The canonical sample of a location is its lowest sample index (whose
  // umbrella and flags the later stages use), whatever order CGAL inserted in.
  if (duplicates_ > 0) {
    for (std::size_t i = 0; i < n; ++i) {
      Vertex_handle v = vertex_[i];
      if (i < v->info()) v->info() = static_cast<Index>(i);
    }
  }
  for (std::size_t i = 0; i < n; ++i) canonical_[i] = vertex_[i]->info();

  // Dense cell ids and per-cell circumcenters (computed once, in parallel).
  cells_.clear();
  if (dt_.dimension() == 3) {
    cells_.reserve(dt_.number_of_cells() + dt_.number_of_finite_cells() / 8 + 16);
    for (auto c = dt_.all_cells_begin(); c != dt_.all_cells_end(); ++c) {
      c->info() = static_cast<Index>(cells_.size());
      cells_.push_back(c);
    }
  }
  const std::size_t m = cells_.size();
  infinite_.assign(m, 0);
  cellSamples_.resize(m);
  cellNeighbors_.resize(m);
  center_.resize(m);
  radius_.resize(m);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, m, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t id = r.begin(); id != r.end(); ++id) {
      Cell_handle c = cells_[id];
      for (int i = 0; i < 4; ++i) {
        const Vertex_handle v = c->vertex(i);
        cellSamples_[id][i] = dt_.is_infinite(v) ? kNoIndex : v->info();
        cellNeighbors_[id][i] = c->neighbor(i)->info();
      }
      if (dt_.is_infinite(c)) {
        infinite_[id] = 1;
        center_[id] = {nan, nan, nan};
        radius_[id] = inf;
        continue;
      }
      const Point& p0 = c->vertex(0)->point();
      const Point cc = robustCircumcenter(p0, c->vertex(1)->point(), c->vertex(2)->point(), c->vertex(3)->point());
      center_[id] = {cc.x(), cc.y(), cc.z()};
      radius_[id] = std::sqrt(CGAL::squared_distance(cc, p0));
    }
  });
  finiteCells_ = 0;
  for (std::uint8_t f : infinite_) finiteCells_ += f ? 0 : 1;
  sideArraySeconds_ = watch.seconds();
}

bool DelaunayVoronoi::cellHasSample(Index id, Index sample) const {
  const std::array<Index, 4>& s = cellSamples_[id];
  return sample != kNoIndex && (s[0] == sample || s[1] == sample || s[2] == sample || s[3] == sample);
}

// Not thread-safe: CGAL's incident-facet walk marks the cells it visits.
void DelaunayVoronoi::finiteIncidentFacets(Index sample, std::vector<Facet>& out) const {
  out.clear();
  dt_.finite_incident_facets(vertex_[sample], std::back_inserter(out));
  for (Facet& f : out) {
    const Cell_handle other = f.first->neighbor(f.second);
    if (cellId(other) < cellId(f.first)) f = Facet(other, other->index(f.first));
  }
  std::sort(out.begin(), out.end(), [](const Facet& a, const Facet& b) {
    return cellId(a.first) != cellId(b.first) ? cellId(a.first) < cellId(b.first) : a.second < b.second;
  });
}

}  // namespace cadmedial
