#include "cadmedial/reconstruction_sides.hpp"
#include "triangle_reach_grid.hpp"
#include "triangle_soup_tree.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "cadmedial/timer.hpp"
#include "cadmedial/union_find.hpp"

namespace cadmedial {

namespace {

using namespace soup;

// A cell whose volume is above 1e-6 of its longest edge cubed: its double
// circumcentre is off by ~eps × 3e6 of its radius at worst (nearly flat cells get
// theirs from other formulas, delaunay.cpp, and some are no empty ball's).
bool farFromFlat(const DelaunayVoronoi& dv, Index c) {
  const auto cell = dv.cell(c);
  const DelaunayVoronoi::Point* p[4];
  for (int k = 0; k < 4; ++k) p[k] = &cell->vertex(k)->point();
  double longest = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) longest = std::max(longest, CGAL::squared_distance(*p[i], *p[j]));
  return std::abs(CGAL::volume(*p[0], *p[1], *p[2], *p[3])) > 1e-6 * longest * std::sqrt(longest);
}

// Per cell: 0 skipped (infinite, or a centre that is not finite), 1 centre
// inside the mesh's box, 2 outside it (so outside the mesh).
enum : std::uint8_t { kNone = 0, kInBox = 1, kOutOfBox = 2 };

// p inside `box` grown by `grow` on every side.
bool inGrownBox(const CGAL::Bbox_3& box, const Kernel::Point_3& p, double grow) {
  return p.x() >= box.xmin() - grow && p.x() <= box.xmax() + grow && p.y() >= box.ymin() - grow &&
         p.y() <= box.ymax() + grow && p.z() >= box.zmin() - grow && p.z() <= box.zmax() + grow;
}

// What the near test, the links and the rays read of every cell.
struct CellCentres {
  std::vector<std::uint8_t> where, wellShaped;
  std::vector<Kernel::Point_3> centre;  // in the tree's (permuted) frame
};

CellCentres cellCentres(const SoupTree& mesh, const DelaunayVoronoi& dv) {
  const std::size_t m = dv.cellCount();
  const CGAL::Bbox_3 box = mesh.tree.bbox();
  const bool samplesAreVertices = dv.sampleCount() + 1 == mesh.firstTriangle.size();
  CellCentres out;
  out.where.assign(m, kNone);
  out.wellShaped.assign(m, 0);
  out.centre.resize(m);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, m, 1024), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t id = r.begin(); id != r.end(); ++id) {
      const Index c = static_cast<Index>(id);
      if (dv.isInfinite(c)) continue;
      const Vec3& x = dv.circumcenter(c);
      if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2])) continue;
      const Kernel::Point_3 p = mesh.permuted(x);
      out.centre[id] = p;
      out.where[id] = inGrownBox(box, p, 0) ? kInBox : kOutOfBox;
      out.wellShaped[id] = samplesAreVertices && farFromFlat(dv, c);
    }
  });
  return out;
}

// Links: two adjacent cells whose centres are joined by a segment touching
// no triangle (exact predicate) are on the same side of the closed mesh.
// Most segments (Voronoi edges) stay farther from every sample than any
// nearby triangle reaches (triangle_reach_grid.hpp): those are linked
// without the tree (84-91 % of them on the thin wall, torus and cylinder).
// Every point of the Voronoi edge dual to facet abc has a, b and c as its
// nearest samples, so its distance to the samples is its distance to a.
// That holds for the exact circumcentres: only cells far from flat, whose
// rounded centres are off by ~1e-9 of their radius at worst, take the
// short cut, with a margin of 1e-8 of it and 1 % of the reach. It also
// needs every triangle corner to be a vertex of dv (dv the Delaunay of the
// samples): without that, none is taken.
ReconstructionLinks linkCells(const SoupTree& mesh, const DelaunayVoronoi& dv, const CellCentres& cells,
                              const TriangleReachGrid& reachGrid) {
  Stopwatch watch;
  const std::size_t m = dv.cellCount();
  const Tree& tree = mesh.tree;
  const auto& where = cells.where;
  const auto& wellShaped = cells.wellShaped;
  const auto& centre = cells.centre;
  ReconstructionLinks out;
  std::vector<std::uint8_t> linked(4 * m, 0);
  std::atomic<std::size_t> tests{0};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, m, 1024), [&](const tbb::blocked_range<std::size_t>& r) {
    std::size_t testsHere = 0;
    for (std::size_t id = r.begin(); id != r.end(); ++id) {
      if (where[id] == kNone) continue;
      const auto cell = dv.cell(static_cast<Index>(id));
      for (int i = 0; i < 4; ++i) {
        const std::size_t other = dv.cellNeighbor(static_cast<Index>(id), i);
        if (other <= id || where[other] == kNone) continue;
        if (where[id] == kOutOfBox && where[other] == kOutOfBox) continue;  // both known outside
        if (centre[id] == centre[other]) {
          linked[4 * id + i] = 1;
          continue;
        }
        const Kernel::Segment_3 segment(centre[id], centre[other]);
        if (wellShaped[id] && wellShaped[other]) {
          const DelaunayVoronoi::Point& a = cell->vertex((i + 1) & 3)->point();
          const Kernel::Point_3 corner = mesh.permuted(Vec3{a.x(), a.y(), a.z()});
          const double clearance = std::sqrt(CGAL::squared_distance(corner, segment));
          const double margin = 1e-8 * (dv.circumradius(static_cast<Index>(id)) + dv.circumradius(static_cast<Index>(other))) +
                                1e-12 * (std::abs(a.x()) + std::abs(a.y()) + std::abs(a.z()));
          if (clearance - margin > 1.01 * reachGrid.reachWithin(segment.bbox())) {
            linked[4 * id + i] = 1;
            continue;
          }
        }
        ++testsHere;
        // Most of the others cross the surface through their own facet, when
        // it is a reconstruction triangle: one exact test instead of the tree.
        const Index own = mesh.triangleWith(dv.cellSample(static_cast<Index>(id), (i + 1) & 3),
                                            dv.cellSample(static_cast<Index>(id), (i + 2) & 3),
                                            dv.cellSample(static_cast<Index>(id), (i + 3) & 3));
        if (own != kNoIndex && CGAL::do_intersect(segment, mesh.triangles[own])) continue;
        if (!tree.do_intersect(segment)) linked[4 * id + i] = 1;
      }
    }
    tests += testsHere;
  });
  out.segmentTests = tests;
  UnionFind groups(m);
  for (std::size_t id = 0; id < m; ++id)
    for (int i = 0; i < 4; ++i)
      if (linked[4 * id + i])
        groups.unite(static_cast<Index>(id), dv.cellNeighbor(static_cast<Index>(id), i));
  out.group.resize(m);
  for (std::size_t id = 0; id < m; ++id) out.group[id] = groups.find(static_cast<Index>(id));
  out.seconds = watch.seconds();
  return out;
}

}  // namespace

ReconstructionSides reconstructionSides(const DelaunayVoronoi& dv, const SampleSet& samples,
                                        const std::vector<double>& deviation,
                                        const std::vector<std::uint8_t>* wanted) {
  if (samples.triangles.empty() || deviation.size() != samples.triangles.size()) {
    ReconstructionSides out;
    out.side.assign(dv.cellCount(), kReconstructionSkipped);
    return out;
  }
  Stopwatch watch;
  const SoupTree mesh(samples);
  const double treeSeconds = watch.seconds();
  ReconstructionSides out = reconstructionSides(mesh, dv, deviation, wanted);
  out.nearSeconds += treeSeconds;
  return out;
}

ReconstructionSides reconstructionSides(const SoupTree& mesh, const DelaunayVoronoi& dv,
                                        const std::vector<double>& deviation,
                                        const std::vector<std::uint8_t>* wanted, const ReconstructionLinks* links,
                                        ReconstructionLinks* made) {
  const std::size_t m = dv.cellCount();
  ReconstructionSides out;
  Stopwatch watch;
  out.side.assign(m, kReconstructionSkipped);
  if (mesh.triangles.empty() || deviation.size() != mesh.triangles.size()) return out;
  if (links && links->group.size() != m) links = nullptr;  // not this Delaunay's
  const Tree& tree = mesh.tree;
  const CGAL::Bbox_3 box = tree.bbox();
  const double maxDeviation = *std::max_element(deviation.begin(), deviation.end());

  // How far into a triangle a point can be from its corners, and the
  // largest deviation of its triangles, per grid cell
  // (triangle_reach_grid.hpp): they spare most near queries and segments.
  const TriangleReachGrid reachGrid(mesh.triangles, deviation);
  const CellCentres cells = cellCentres(mesh, dv);
  const auto& where = cells.where;
  const auto& wellShaped = cells.wellShaped;
  const auto& centre = cells.centre;
  std::vector<std::uint8_t> near(m, 0);
  std::atomic<std::size_t> nearCount{0};
  tbb::enumerable_thread_specific<std::vector<Tree::Primitive_id>> hitsPerThread;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, m, 1024), [&](const tbb::blocked_range<std::size_t>& r) {
    auto& hits = hitsPerThread.local();
    std::size_t nearHere = 0;
    for (std::size_t id = r.begin(); id != r.end(); ++id) {
      if (where[id] == kNone) continue;
      const Index c = static_cast<Index>(id);
      const Kernel::Point_3& p = centre[id];
      // A zero band (cell_sides) makes "near" mean "on a triangle": such a
      // centre's segments all touch that triangle, so it links to nothing and
      // its group's ray starts at the centre itself, the ray a near cell would
      // get from the caller. The near query is skipped: same answers.
      if (!(maxDeviation > 0) || (wanted && !(*wanted)[id]) || !inGrownBox(box, p, maxDeviation)) continue;
      // Every triangle t within d_t of the centre has d_t <= the largest
      // deviation of the triangles in the grid cells around it (only curved
      // faces' triangles deviate by more than their tolerance): that bounds
      // the cube below. Both cubes are grown by 1e-6 of their half-side and
      // by the rounding of the centre's coordinates, so a triangle at d_t
      // (1 + 1e-9) from it, which the test below counts as near, is in them.
      // (The squared distance of a large triangle is rounded by ~eps L²: one
      // truly beyond the grown cube could pass that test from the old cube of
      // the largest deviation; its centre is not near now, as it truly is not.)
      const double rounding = 1e-12 * (std::abs(p.x()) + std::abs(p.y()) + std::abs(p.z()));
      auto cubeAround = [&](double half) {
        half = half * (1 + 1e-6) + rounding;
        return CGAL::Bbox_3(p.x() - half, p.y() - half, p.z() - half, p.x() + half, p.y() + half, p.z() + half);
      };
      const double localDeviation = std::min(maxDeviation, reachGrid.deviationWithin(cubeAround(maxDeviation)));
      const CGAL::Bbox_3 cube = cubeAround(localDeviation);
      // A point of triangle t within d_t of the centre is within reach(t)
      // of a sample, so the nearest sample (at the circumradius) would be
      // within d_t + reach(t): farther than that, no query.
      const double margin = 1e-8 * dv.circumradius(c) + rounding;
      if (wellShaped[id] && dv.circumradius(c) - margin > 1.01 * (localDeviation + reachGrid.reachWithin(cube))) continue;
      // Near iff within d_t of some triangle t: the candidates are the
      // triangles whose boxes meet the cube.
      hits.clear();
      tree.all_intersected_primitives(cube, std::back_inserter(hits));
      for (const auto& t : hits) {
        const double d = deviation[static_cast<std::size_t>(t - mesh.triangles.begin())];
        // The squared distance is rounded; a relative margin keeps a centre at
        // exactly d_t on the safe (near) side.
        if (CGAL::squared_distance(p, *t) <= d * d * (1 + 1e-9)) {
          near[id] = 1;
          ++nearHere;
          break;
        }
      }
    }
    nearCount += nearHere;
  });
  out.nearCells = nearCount;
  out.nearSeconds = watch.seconds();

  // The groups, unless the caller has them (they do not depend on the
  // deviations: CellSideInputs keeps one set for the CAD_MEDIAL cell sides
  // and the pair-mesh labels). segmentTests: the tests that made them, here
  // or before.
  ReconstructionLinks own;
  if (!links) {
    own = linkCells(mesh, dv, cells, reachGrid);
    links = &own;
    out.linkSeconds = own.seconds;
  }
  out.segmentTests = links->segmentTests;
  const std::vector<Index>& group = links->group;
  watch.restart();

  // Side per group: outside when it holds a centre outside the box, else one
  // ray parity test from any member that is needed.
  constexpr std::uint8_t kUnknown = 255;
  std::vector<std::uint8_t> groupSide(m, kUnknown);
  std::vector<Index> needsRay;  // group roots
  for (std::size_t id = 0; id < m; ++id)
    if (where[id] == kOutOfBox) groupSide[group[id]] = kReconstructionOutside;
  std::vector<Index> rayFrom;
  for (std::size_t id = 0; id < m; ++id) {
    if (where[id] != kInBox || near[id] || (wanted && !(*wanted)[id])) continue;
    const Index root = group[id];
    if (groupSide[root] != kUnknown) continue;
    groupSide[root] = kReconstructionSkipped;  // claimed: one ray for this group
    needsRay.push_back(root);
    rayFrom.push_back(static_cast<Index>(id));
  }
  tbb::parallel_for(std::size_t(0), needsRay.size(), [&](std::size_t k) {
    groupSide[needsRay[k]] = RayCast()(centre[rayFrom[k]], tree) == CGAL::ON_BOUNDED_SIDE ? kReconstructionInside
                                                                                         : kReconstructionOutside;
  });
  out.rayCasts = needsRay.size();

  std::vector<std::uint8_t> counted(m, 0);
  for (std::size_t id = 0; id < m; ++id) {
    if (where[id] == kNone || (wanted && !(*wanted)[id])) continue;
    if (near[id]) {
      out.side[id] = kReconstructionNear;
      continue;
    }
    const Index root = group[id];
    out.side[id] = groupSide[root];
    if (!counted[root]) {
      counted[root] = 1;
      ++out.groups;
    }
  }
  out.raySeconds = watch.seconds();
  if (made && links == &own) *made = std::move(own);
  return out;
}

}  // namespace cadmedial
