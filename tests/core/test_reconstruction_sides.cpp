// The side of the closed reconstruction per Voronoi vertex, checked against
// the exact solid (planar-faced solids: their reconstruction is their
// boundary), and the bound that lets most Voronoi edges skip the AABB tree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

#include "cadmedial/delaunay.hpp"
#include "cadmedial/cell_sides.hpp"
#include "cadmedial/medial.hpp"
#include "cadmedial/surface_mesh_checks.hpp"
#include "cadmedial/reconstruction_sides.hpp"
#include "synthetic_samples.hpp"
#include "triangle_reach_grid.hpp"

using namespace cadmedial;
using namespace cadmedial::testing;

namespace {

double distance(const soup::Kernel::Point_3& a, const soup::Kernel::Point_3& b) {
  return std::sqrt(CGAL::squared_distance(a, b));
}

// Every cell's side against the solid's exact inside test, and how many
// Voronoi edges went to the tree (segmentTests) out of all tested.
void expectSidesMatchTheSolid(const PlanarSolid& solid, double spacing) {
  SamplingOptions options;
  options.spacing = spacing;
  const SampleSet samples = samplePlanarSolid(solid, options);
  const DelaunayVoronoi dv(samples.points);
  ASSERT_EQ(dv.dimension(), 3);
  const ReconstructionSides sides =
      reconstructionSides(dv, samples, std::vector<double>(samples.triangles.size(), 0.0));
  std::size_t checked = 0, inside = 0, finiteFacets = 0;
  for (Index c = 0; c < dv.cellCount(); ++c) {
    if (dv.isInfinite(c)) continue;
    for (int i = 0; i < 4; ++i) finiteFacets += dv.isInfinite(DelaunayVoronoi::cellId(dv.cell(c)->neighbor(i))) ? 0 : 1;
    const Vec3& p = dv.circumcenter(c);
    const bool in = solid.inside(p);
    if (in && !(solid.boundaryDistance(p) > 1e-9)) continue;  // on a face: either answer
    ASSERT_TRUE(sides.side[c] == kReconstructionInside || sides.side[c] == kReconstructionOutside)
        << "cell " << c << " side " << int(sides.side[c]);
    EXPECT_EQ(sides.side[c] == kReconstructionInside, in) << solid.name << " cell " << c << " at " << p[0] << ", "
                                                          << p[1] << ", " << p[2];
    ++checked;
    inside += in ? 1 : 0;
  }
  EXPECT_GT(inside, 100u);
  EXPECT_GT(checked - inside, 100u);
  // The reach bound clears most segments: far fewer go to the tree than
  // there are Voronoi edges (each finite facet is counted from both cells).
  EXPECT_LT(sides.segmentTests, finiteFacets / 2 / 3) << "tree queries " << sides.segmentTests;
}

// "near" exactly where some triangle t is within its deviation d_t (brute
// force over all triangles, for every 11th cell), and the others on the
// solid's side. The reach bound spares most near queries, and the largest
// deviation around a centre shrinks the cube it queries; a wrong bound
// would call near cells far.
void expectNearWithinEachTrianglesDeviation(const std::function<double(const soup::Kernel::Triangle_3&)>& deviationOf) {
  SamplingOptions options;
  options.spacing = 0.05;
  const PlanarSolid solid = makeLPrism();
  const SampleSet samples = samplePlanarSolid(solid, options);
  const DelaunayVoronoi dv(samples.points);
  std::vector<soup::Kernel::Triangle_3> triangles;
  std::vector<double> deviation;
  for (const auto& t : samples.triangles) {
    const auto& a = samples.points[t[0]], &b = samples.points[t[1]], &d = samples.points[t[2]];
    triangles.emplace_back(soup::Kernel::Point_3(a[0], a[1], a[2]), soup::Kernel::Point_3(b[0], b[1], b[2]),
                           soup::Kernel::Point_3(d[0], d[1], d[2]));
    deviation.push_back(deviationOf(triangles.back()));
  }
  const double band = *std::max_element(deviation.begin(), deviation.end());
  const ReconstructionSides sides = reconstructionSides(dv, samples, deviation);
  std::size_t near = 0, far = 0;
  for (Index c = 0; c < dv.cellCount(); c += 11) {
    if (dv.isInfinite(c) || sides.side[c] == kReconstructionSkipped) continue;
    const Vec3& x = dv.circumcenter(c);
    const soup::Kernel::Point_3 p(x[0], x[1], x[2]);
    bool within = false, onEdge = false;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      const double gap = std::sqrt(CGAL::squared_distance(p, triangles[t])) - deviation[t];
      within = within || gap < 0;
      onEdge = onEdge || std::abs(gap) < 1e-9;
    }
    if (onEdge) continue;  // on a band's edge: either answer
    const bool outsideBox = x[0] < samples.bboxMin[0] - band || x[0] > samples.bboxMax[0] + band ||
                            x[1] < samples.bboxMin[1] - band || x[1] > samples.bboxMax[1] + band ||
                            x[2] < samples.bboxMin[2] - band || x[2] > samples.bboxMax[2] + band;
    if (outsideBox) continue;  // never asked: outside the box grown by the band
    EXPECT_EQ(sides.side[c] == kReconstructionNear, within) << "cell " << c << " at " << x[0] << ", " << x[1] << ", " << x[2];
    if (within) {
      ++near;
    } else {
      ++far;
      EXPECT_EQ(sides.side[c] == kReconstructionInside, solid.inside(x)) << "cell " << c;
    }
  }
  EXPECT_GT(near, 50u);
  EXPECT_GT(far, 100u);
}

}  // namespace

TEST(ReconstructionSides, NearCellsAreThoseWithinTheBandOfATriangle) {
  expectNearWithinEachTrianglesDeviation([](const soup::Kernel::Triangle_3&) { return 0.3 * 0.05; });
}

// Deviations that differ by 30x from triangle to triangle (as a coarse
// fillet's beside planar faces do), one in five large, scattered: each
// triangle's own deviation counts, also where the centre's grid cell holds
// only small ones and a large one is in the next cell.
TEST(ReconstructionSides, NearCellsAreThoseWithinTheirOwnTrianglesDeviation) {
  std::mt19937 random(11);
  expectNearWithinEachTrianglesDeviation([&](const soup::Kernel::Triangle_3&) {
    return random() % 5 == 0 ? 0.3 * 0.05 : 0.01 * 0.05;
  });
}

TEST(ReconstructionSides, EveryVoronoiVertexOnTheSolidsSide) {
  expectSidesMatchTheSolid(makeLPrism(), 0.05);
  expectSidesMatchTheSolid(makeBoxWithSquareHole(), 0.06);
}

// reach(t) bounds the distance from any point of t to t's nearest corner:
// random points of acute, right, obtuse and needle triangles, and the
// bound is not loose by more than a factor 3 (it would still be sound, but
// clear fewer segments).
TEST(ReconstructionSides, TriangleReachBoundsTheDistanceToTheNearestCorner) {
  using P = soup::Kernel::Point_3;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0, 1);
  const std::vector<soup::Kernel::Triangle_3> shapes{
      {P(0, 0, 0), P(1, 0, 0), P(0.5, 0.8, 0)},       // acute
      {P(0, 0, 0), P(1, 0, 0), P(0, 1, 0)},           // right
      {P(0, 0, 0), P(1, 0, 0), P(0.5, 0.1, 0.05)},    // obtuse
      {P(0, 0, 0), P(1, 0, 0), P(0.999, 0.001, 0)},   // needle
      {P(0, 0, 0), P(1e-3, 2, 0), P(-1e-3, 4, 1e-3)}, // nearly a segment
  };
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    const auto& t = shapes[s];
    const double reach = soup::TriangleReachGrid::reach(t);
    double worst = 0;
    for (int k = 0; k < 20000; ++k) {
      double u = unit(random), v = unit(random);
      if (u + v > 1) u = 1 - u, v = 1 - v;
      const P q(t[0].x() + u * (t[1].x() - t[0].x()) + v * (t[2].x() - t[0].x()),
                t[0].y() + u * (t[1].y() - t[0].y()) + v * (t[2].y() - t[0].y()),
                t[0].z() + u * (t[1].z() - t[0].z()) + v * (t[2].z() - t[0].z()));
      worst = std::max(worst, std::min({distance(q, t[0]), distance(q, t[1]), distance(q, t[2])}));
    }
    EXPECT_LE(worst, reach * (1 + 1e-12)) << "shape " << s;
    EXPECT_GT(worst, reach / 3) << "shape " << s;
  }
  // The grid: a box that meets no triangle's cells reaches 0; one over a
  // triangle reaches at least that triangle's reach.
  const soup::Triangles triangles{shapes[0], {P(10, 10, 10), P(11, 10, 10), P(10, 11, 10)}};
  const soup::TriangleReachGrid grid(triangles);
  EXPECT_GE(grid.reachWithin(CGAL::Bbox_3(0.4, 0.1, -0.1, 0.6, 0.2, 0.1)), soup::TriangleReachGrid::reach(shapes[0]));
  EXPECT_EQ(grid.reachWithin(CGAL::Bbox_3(20, 20, 20, 21, 21, 21)), 0.0);
}

// deviationWithin: for any point p, every triangle t within its deviation
// d_t of p has d_t <= the largest deviation the grid holds around p (in the
// cube of half-side max d_t); +inf without deviations, 0 where no
// triangle is. 3000 small triangles along a bent strip (a grid of 11
// cells a side), one in five of its middle fifth deviating by 2, the
// others by less than 0.05; 2000 random points near it.
TEST(ReconstructionSides, GridDeviationBoundsEveryTriangleWithinItsDeviation) {
  using P = soup::Kernel::Point_3;
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0, 1);
  soup::Triangles triangles;
  std::vector<double> deviation;
  for (int i = 0; i < 3000; ++i) {
    const double x = 100 * unit(random), y = 10 * std::sin(x / 10) + unit(random), z = 5 * unit(random);
    triangles.emplace_back(P(x, y, z), P(x + 0.5, y, z), P(x, y + 0.5 * unit(random), z + 0.5));
    deviation.push_back(x > 40 && x < 60 && i % 5 == 0 ? 2.0 : 0.05 * unit(random));
  }
  const double largest = *std::max_element(deviation.begin(), deviation.end());
  const soup::TriangleReachGrid grid(triangles, deviation);
  std::size_t within = 0, shrunk = 0;
  for (int k = 0; k < 2000; ++k) {
    const double x = 100 * unit(random);
    const P p(x, 10 * std::sin(x / 10) + 3 * unit(random) - 1, 7 * unit(random) - 1);
    const CGAL::Bbox_3 cube(p.x() - largest, p.y() - largest, p.z() - largest, p.x() + largest, p.y() + largest,
                            p.z() + largest);
    const double bound = grid.deviationWithin(cube, 1 << 20);
    shrunk += bound < largest;
    for (std::size_t t = 0; t < triangles.size(); ++t)
      if (CGAL::squared_distance(p, triangles[t]) <= deviation[t] * deviation[t]) {
        ++within;
        EXPECT_GE(bound, deviation[t]) << "point " << k << " triangle " << t;
      }
  }
  EXPECT_GT(within, 500u);
  EXPECT_GT(shrunk, 100u);  // the bound is local: often below the largest deviation anywhere
  EXPECT_EQ(grid.deviationWithin(CGAL::Bbox_3(500, 500, 500, 501, 501, 501)), 0.0);
  EXPECT_EQ(soup::TriangleReachGrid(triangles).deviationWithin(CGAL::Bbox_3(0, 0, 0, 1, 1, 1)),
            std::numeric_limits<double>::infinity());
}

// A caller that has checked the reconstruction already (the sampling) passes
// its check in; the point-in-mesh tree follows that check, not a new one.
TEST(ReconstructionSides, CellSideInputsFollowTheSurfaceCheckPassedIn) {
  SamplingOptions options;
  options.spacing = 0.2;
  const SampleSet samples = samplePlanarSolid(makeBoxWithSquareHole(), options);
  const SurfaceMeshStats check = checkSurfaceMesh(samples.points, samples.triangles);
  ASSERT_TRUE(check.closedManifold());
  EXPECT_NE(CellSideInputs(samples).mesh, nullptr);
  EXPECT_NE(CellSideInputs(samples, &check).mesh, nullptr);
  SurfaceMeshStats open = check;
  open.boundaryEdges = 1;
  EXPECT_EQ(CellSideInputs(samples, &open).mesh, nullptr);
  EXPECT_EQ(PreparedSamples(samples, true, &open).cellSides->mesh, nullptr);
  EXPECT_NE(PreparedSamples(samples, true, &check).cellSides->mesh, nullptr);
}

// The link groups do not depend on the deviations: the ones CellSideInputs
// keeps (made by the zero-band question of the CAD_MEDIAL cell sides) give
// the pair-mesh labels' band exactly the answers of groups made afresh. They
// are kept only when asked for, and only for the Delaunay they were made on.
TEST(ReconstructionSides, KeptLinkGroupsGiveTheAnswersOfFreshOnes) {
  SamplingOptions options;
  options.spacing = 0.1;
  const SampleSet samples = samplePlanarSolid(makeBoxWithSquareHole(), options);
  const DelaunayVoronoi dv(samples.points);
  const std::vector<double> zero(samples.triangles.size(), 0.0);

  const CellSideInputs notKeeping(samples);
  ASSERT_NE(notKeeping.mesh, nullptr);
  reconstructionSides(dv, notKeeping, zero);
  EXPECT_EQ(notKeeping.links(dv), nullptr);

  CellSideInputs inputs(samples);
  inputs.keepLinks = true;
  const ReconstructionSides first = reconstructionSides(dv, inputs, zero);
  const std::shared_ptr<const ReconstructionLinks> links = inputs.links(dv);
  ASSERT_NE(links, nullptr);
  EXPECT_EQ(links->group.size(), dv.cellCount());
  EXPECT_EQ(first.side, reconstructionSides(dv, samples, zero).side);
  std::vector<std::uint8_t> ring(dv.cellCount(), 0);
  for (Index c = 0; c < dv.cellCount(); c += 3) ring[c] = 1;
  const std::vector<std::uint8_t>* everyCell = nullptr;
  const std::vector<std::uint8_t>* someCells = &ring;
  for (const double band : {0.0, 0.02, 0.07}) {
    const std::vector<double> deviation(samples.triangles.size(), band);
    for (const std::vector<std::uint8_t>* wanted : {everyCell, someCells}) {
      const ReconstructionSides fresh = reconstructionSides(dv, samples, deviation, wanted);
      const ReconstructionSides shared = reconstructionSides(dv, inputs, deviation, wanted);
      EXPECT_EQ(shared.side, fresh.side) << "band " << band;
      EXPECT_EQ(shared.groups, fresh.groups);
      EXPECT_EQ(shared.rayCasts, fresh.rayCasts);
      EXPECT_EQ(shared.segmentTests, fresh.segmentTests);
      EXPECT_EQ(shared.linkSeconds, 0.0);  // not linked again
      EXPECT_GT(fresh.groups, 1u);
    }
  }
  EXPECT_EQ(inputs.links(dv), links);  // still the first ones
  // Another Delaunay (fewer points) has none kept.
  std::vector<Vec3> fewer(samples.points.begin(), samples.points.begin() + samples.points.size() / 2);
  const DelaunayVoronoi other(fewer);
  EXPECT_EQ(inputs.links(other), nullptr);
}
