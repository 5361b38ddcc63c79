// newtonFoot (sampling/src/surface_newton.hpp) against OCCT's own local
// solver on a wavy B-spline patch, and how it gives up: at a foot past the
// UV bounds and at a degenerate foot (the centre of a sphere).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Extrema_GenLocateExtPS.hxx>
#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_SphericalSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Ax3.hxx>

#include "surface_newton.hpp"

namespace cadmedial {
namespace {

// z = 3 sin(x / 7) cos(y / 9) over [0, 60]², interpolated by a B-spline.
Handle(Geom_BSplineSurface) wavyPatch() {
  TColgp_Array2OfPnt points(1, 13, 1, 13);
  for (int i = 1; i <= 13; ++i)
    for (int j = 1; j <= 13; ++j) {
      const double x = 5.0 * (i - 1), y = 5.0 * (j - 1);
      points(i, j) = gp_Pnt(x, y, 3 * std::sin(x / 7) * std::cos(y / 9));
    }
  GeomAPI_PointsToBSplineSurface fit(points);
  return fit.Surface();
}

TEST(SurfaceNewton, FindsOcctsFootFromANearbyStart) {
  const Handle(Geom_BSplineSurface) patch = wavyPatch();
  GeomAdaptor_Surface surface(patch);
  Extrema_GenLocateExtPS occt(surface);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.1, 0.9), offset(-4, 4), nudge(-0.02, 0.02);
  const double u1 = surface.FirstUParameter(), u2 = surface.LastUParameter();
  const double v1 = surface.FirstVParameter(), v2 = surface.LastVParameter();
  int converged = 0;
  for (int i = 0; i < 300; ++i) {
    // A point off the patch along the normal at a known foot (within the
    // curvature radius, > 5 here), and a start a little off that foot.
    const double u = u1 + unit(rng) * (u2 - u1), v = v1 + unit(rng) * (v2 - v1);
    gp_Pnt q;
    gp_Vec su, sv;
    surface.D1(u, v, q, su, sv);
    const gp_Pnt p = q.Translated(gp_Vec(su.Crossed(sv).Normalized()) * offset(rng));
    const double u0 = u + nudge(rng) * (u2 - u1), v0 = v + nudge(rng) * (v2 - v1);
    SurfaceFoot foot;
    if (newtonFoot(surface, p, u0, v0, foot) != NewtonResult::Converged) continue;
    ++converged;
    occt.Perform(p, u0, v0, false);
    ASSERT_TRUE(occt.IsDone());
    EXPECT_LT(foot.point.Distance(occt.Point().Value()), 1e-7) << "at " << u << " " << v;
    EXPECT_LT(foot.point.Distance(q), 1e-7);
    EXPECT_NEAR(p.Distance(foot.point), std::sqrt(occt.SquareDistance()), 1e-9);
  }
  EXPECT_GE(converged, 295);  // from a start 2 % of the range off, Newton must settle
}

TEST(SurfaceNewton, SaysWhenTheFootIsPastTheBounds) {
  GeomAdaptor_Surface square(new Geom_Plane(gp_Ax3()), 0, 10, 0, 10);
  SurfaceFoot foot;
  EXPECT_EQ(newtonFoot(square, gp_Pnt(12, 5, 3), 9, 5, foot), NewtonResult::LeftBounds);
  ASSERT_EQ(newtonFoot(square, gp_Pnt(7, 5, 3), 9, 5, foot), NewtonResult::Converged);
  EXPECT_LT(foot.point.Distance(gp_Pnt(7, 5, 0)), 1e-12);
}

TEST(SurfaceNewton, GivesUpAtADegenerateFoot) {
  // From a sphere's centre every point is a foot: the Hessian is zero.
  GeomAdaptor_Surface sphere(new Geom_SphericalSurface(gp_Ax3(), 5));
  SurfaceFoot foot;
  EXPECT_EQ(newtonFoot(sphere, gp_Pnt(0, 0, 0), 1, 0.3, foot), NewtonResult::Singular);
  // Off the centre it converges to the nearest point.
  ASSERT_EQ(newtonFoot(sphere, gp_Pnt(std::cos(1.0), std::sin(1.0), 0), 1.2, 0.1, foot), NewtonResult::Converged);
  EXPECT_LT(foot.point.Distance(gp_Pnt(5 * std::cos(1.0), 5 * std::sin(1.0), 0)), 1e-9);
}

}  // namespace
}  // namespace cadmedial
