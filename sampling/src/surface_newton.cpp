#include "surface_newton.hpp"

#include <algorithm>
#include <cmath>

#include <gp_Vec.hxx>

namespace cadmedial {

NewtonResult newtonFoot(const Adaptor3d_Surface& surface, const gp_Pnt& p, double u0, double v0, SurfaceFoot& foot) {
  // Quadratic convergence: from a start within a mesh deflection, 3-5 steps
  // reach double precision; more means the start was not close.
  constexpr int kMaxSteps = 12;
  const double u1 = surface.FirstUParameter(), u2 = surface.LastUParameter();
  const double v1 = surface.FirstVParameter(), v2 = surface.LastVParameter();
  double u = u0, v = v0;
  for (int step = 0; step < kMaxSteps; ++step) {
    gp_Pnt q;
    gp_Vec su, sv, suu, svv, suv;
    surface.D2(u, v, q, su, sv, suu, svv, suv);
    const gp_Vec r(p, q);  // from p to the surface point
    // Gradient and Hessian of f = |S − p|² / 2.
    const double g1 = r.Dot(su), g2 = r.Dot(sv);
    const double a = su.Dot(su) + r.Dot(suu), b = su.Dot(sv) + r.Dot(suv), c = sv.Dot(sv) + r.Dot(svv);
    const double det = a * c - b * b;
    // Singular: a degenerate or saddle-like foot (p near a centre of
    // curvature); a quotient by it would throw the step anywhere.
    const double scale = su.SquareMagnitude() * sv.SquareMagnitude();
    if (!(std::abs(det) > 1e-12 * scale)) return NewtonResult::Singular;
    const double du = -(c * g1 - b * g2) / det, dv = -(a * g2 - b * g1) / det;
    u += du;
    v += dv;
    if (!(u >= u1 && u <= u2 && v >= v1 && v <= v2)) return NewtonResult::LeftBounds;
    // Converged when the step moves the point by less than 1e-10 of its
    // distance (or of the surface's size for a point on the surface).
    const double moved = (su * du + sv * dv).Magnitude();
    const double size = std::max(r.Magnitude(), 1e-6 * std::sqrt(std::max(su.SquareMagnitude(), sv.SquareMagnitude())));
    if (moved <= 1e-10 * size) {
      foot.u = u;
      foot.v = v;
      foot.point = surface.Value(u, v);
      return NewtonResult::Converged;
    }
  }
  return NewtonResult::NotConverged;
}

}  // namespace cadmedial
