// A box with every edge filleted: the commonest CAD rounding, and a shape
// whose exact normal is known everywhere (the points at distance r from the
// inner box). Its eight corner spheres have poles (degenerate edges) and
// cospherical samples; both used to break the axis.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cadmedial/medial.hpp"
#include "cadmedial/umbrella.hpp"
// OCCT after CGAL (OCCT's Handle macro).
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "cadmedial/sampling.hpp"

namespace cadmedial {
namespace {

constexpr double kSize[3] = {60, 30, 50};
constexpr double kRadius = 2.5;

TopoDS_Shape filletedBox() {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(kSize[0], kSize[1], kSize[2]).Shape();
  BRepFilletAPI_MakeFillet fillet(box);
  for (TopExp_Explorer e(box, TopAbs_EDGE); e.More(); e.Next()) fillet.Add(kRadius, TopoDS::Edge(e.Current()));
  return fillet.Shape();
}

// Outward normal of the rounded box at a point on it: away from the nearest
// point of the inner box [r, size - r].
Vec3 exactNormal(const Vec3& p) {
  Vec3 n;
  for (int k = 0; k < 3; ++k) n[k] = p[k] - std::clamp(p[k], kRadius, kSize[k] - kRadius);
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (double& c : n) c /= len;
  return n;
}

TEST(FilletedBox, EveryUmbrellaTriangleFollowsTheSurface) {
  // At a corner sphere's pole, one point is a whole segment in UV: the UV
  // triangle from one end of it to two samples of the edge leaving the other
  // end stood on edge in 3D (normal ~90° off). Its normal in the umbrellas
  // made the Angle condition reject edges straight across a thin wall
  // (bottle.brep: holes in the wall's sheet at every such corner).
  const SolidSampling s = sampleSolid(filletedBox());
  ASSERT_EQ(s.report.facesFailed, 0);
  ASSERT_TRUE(s.report.surface.closedManifold());
  const UmbrellaData u = computeUmbrellaData(s.samples);
  double worst = 1;
  std::size_t checked = 0;
  for (std::size_t i = 0; i < s.samples.size(); ++i) {
    const Vec3 n = exactNormal(s.samples.points[i]);
    for (Index k = u.offsets[i]; k < u.offsets[i + 1]; ++k) {
      const auto& t = u.normals[k];
      worst = std::min(worst, t[0] * n[0] + t[1] * n[1] + t[2] * n[2]);
      ++checked;
    }
    EXPECT_GT(u.offsets[i + 1], u.offsets[i]) << "sample " << i << " has no umbrella";
  }
  std::printf("filleted box: %zu samples, %zu umbrella normals, worst cosine to the exact normal %.3f; "
              "%d edges flipped, %d triangles left off the surface\n",
              s.samples.size(), checked, worst, s.report.flippedEdges, s.report.misalignedTriangles);
  EXPECT_GT(worst, std::cos(45 * M_PI / 180));
  // Here flips mend every such triangle (none left for umbrellas to skip).
  EXPECT_EQ(s.report.misalignedTriangles, 0);
}

TEST(FilletedBox, AxisIsOneComponentWithoutLoops) {
  // The corner spheres' samples are cospherical: a Voronoi facet between two
  // of them can have all its vertices at the sphere's centre, and when no
  // other inner polygon uses those cells it was a component of its own
  // (β0 = 2 at the default spacing).
  const SolidSampling s = sampleSolid(filletedBox());
  const MedialResult m = computeCadMedial(s.samples);
  std::printf("filleted box: %zu polygons, b0 %lld b1 %lld, point islands dropped %zu\n", m.polygonCount(),
              m.topology.beta0, m.topology.beta1, m.counts.pointIslands);
  EXPECT_EQ(m.topology.beta0, 1);
  EXPECT_EQ(m.topology.beta1, 0);
}

TEST(FilletedBox, VariableFilletsLeaveNoNestedIsland) {
  // Every edge of a 60 x 40 x 30 box filleted from radius 1.5 to 5: at one
  // corner blend the filter kept a single facet (r up to 3.3) apart from
  // the rest, its balls inside the main axis's (β0 = 2, 2026-12-06; dropped
  // as a nested island since).
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(60, 40, 30).Shape();
  BRepFilletAPI_MakeFillet fillet(box);
  for (TopExp_Explorer e(box, TopAbs_EDGE); e.More(); e.Next()) fillet.Add(1.5, 5.0, TopoDS::Edge(e.Current()));
  const SolidSampling s = sampleSolid(fillet.Shape());
  const MedialResult m = computeCadMedial(s.samples);
  std::printf("variable fillets: %zu polygons, b0 %lld b1 %lld, nested islands dropped %zu\n", m.polygonCount(),
              m.topology.beta0, m.topology.beta1, m.counts.nestedIslands);
  EXPECT_EQ(m.topology.beta0, 1);
  EXPECT_EQ(m.topology.beta1, 0);
}

// How far a point is from the exact medial axis of the rounded box, which is
// the axis of the inner box [r, size - r] (with the same contacts moved out
// by r): outside the inner box, its distance to it (the fillets' centre
// curves and corner centres close the sheets); inside, the distance to the
// nearest bisector of two faces, (d2 - d1) / sqrt 2 for its two smallest
// distances d1 <= d2 to the inner box's faces (exact near a bisector plane).
double distanceToExactAxis(const Vec3& p) {
  double outside2 = 0;
  for (int k = 0; k < 3; ++k) {
    const double o = std::max({kRadius - p[k], p[k] - (kSize[k] - kRadius), 0.0});
    outside2 += o * o;
  }
  if (outside2 > 0) return std::sqrt(outside2);
  double d[6];
  for (int k = 0; k < 3; ++k) {
    d[2 * k] = p[k] - kRadius;
    d[2 * k + 1] = kSize[k] - kRadius - p[k];
  }
  std::sort(d, d + 6);
  return (d[1] - d[0]) / std::sqrt(2.0);
}

TEST(FilletedBox, FringeAroundTheFilletCentreCurvesIsCollapsed) {
  // Every fillet's centre curve ends two sheets. The Angle condition keeps
  // the facets of chords between neighbouring fillet samples there (the
  // fillet is curved far beyond what h resolves): fins reaching from the
  // curve towards the fillet, whose vertices have one contact. The thinning
  // collapses them without changing the topology.
  const SolidSampling s = sampleSolid(filletedBox());
  const double diagonal = std::sqrt(kSize[0] * kSize[0] + kSize[1] * kSize[1] + kSize[2] * kSize[2]);
  const double tol = 0.005 * diagonal;  // the eval's tolerance (DESIGN.md §6)
  auto offAxisShare = [&](const MedialResult& m) {
    std::size_t used = 0, off = 0;
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
      if (!(m.radius[v] > 0)) continue;
      ++used;
      off += distanceToExactAxis(m.vertices[v]) > tol;
    }
    return used ? double(off) / used : 1.0;
  };
  MedialParams keep;
  keep.thinFringe = false;
  const MedialResult raw = computeCadMedial(s.samples, keep);
  const MedialResult thinned = computeCadMedial(s.samples);
  std::printf("filleted box: off the exact axis by > tol: %.2f %% of %zu vertices with the fringe, %.2f %% of %zu "
              "thinned (%zu polygons collapsed); b0,b1 %lld,%lld\n",
              100 * offAxisShare(raw), raw.vertices.size(), 100 * offAxisShare(thinned), thinned.vertices.size(),
              thinned.counts.fringePolygonsThinned, thinned.topology.beta0, thinned.topology.beta1);
  EXPECT_GT(thinned.counts.fringePolygonsThinned, 0u);
  EXPECT_LT(offAxisShare(thinned), 0.01);
  EXPECT_LT(offAxisShare(thinned), offAxisShare(raw) / 2);
  EXPECT_EQ(thinned.topology.beta0, raw.topology.beta0);
  EXPECT_EQ(thinned.topology.beta1, raw.topology.beta1);
  // The thinning removes only Voronoi facets: every forced triangle stays.
  auto forcedCount = [](const MedialResult& m) {
    return std::count_if(m.provenance.begin(), m.provenance.end(),
                         [](PolygonProvenance p) { return p != PolygonProvenance::DelaunayEdgeFacet; });
  };
  EXPECT_EQ(forcedCount(thinned), forcedCount(raw));
}

}  // namespace
}  // namespace cadmedial
