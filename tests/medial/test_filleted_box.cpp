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

}  // namespace
}  // namespace cadmedial
