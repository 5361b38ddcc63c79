// Newton's method for the foot of a point on a surface, started close to it.
//
// ExactOracle starts a projection from the mesh foot (within the mesh
// deflection of the exact one) for every query. OCCT's
// Extrema_GenLocateExtPS solves the same equations with
// math_FunctionSetRoot, which runs a Brent line search at every step: on
// B-spline faces that was 60 % of the run's walk check (a box with variable
// fillets: 35 s for 67 k queries, the axis itself 0.5 s), tens of surface
// evaluations per step. From such a start plain Newton converges in a few
// steps, one second-derivative evaluation each. Where it does not (a start
// far off, a degenerate foot as from the centre of a tube, a foot on or
// beyond the UV bounds) it says so, and the caller falls back to OCCT.
#pragma once

#include <Adaptor3d_Surface.hxx>
#include <gp_Pnt.hxx>

namespace cadmedial {

struct SurfaceFoot {
  double u = 0, v = 0;
  gp_Pnt point;
};

enum class NewtonResult {
  Converged,     // foot holds a critical point of |S(u, v) − p| (p − S normal to both tangents)
  LeftBounds,    // a step left the surface's UV bounds: the nearest point is on or past them
  Singular,      // the Hessian of the squared distance is singular on the way (a degenerate foot)
  NotConverged,  // no settling within a few steps (a start far from any foot)
};

// Newton steps from (u0, v0) on the gradient of |S(u, v) − p|² / 2.
NewtonResult newtonFoot(const Adaptor3d_Surface& surface, const gp_Pnt& p, double u0, double v0, SurfaceFoot& foot);

}  // namespace cadmedial
