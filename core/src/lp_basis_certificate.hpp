// Private to core: checks one basis of a small linear program in exact
// arithmetic, so that the pair-mesh repair can trust the basis its
// double-precision simplex ends on instead of solving the program again with
// CGAL's exact solver (about 0.2 ms each, more than half the repair on small
// planar parts).
//
// The program: maximize objective . x over x in R^4 subject to
// normal_i . x <= bound_i. A basis is four constraints taken as equalities;
// their intersection is the basis's vertex. The vertex is feasible when it
// satisfies every constraint, and optimal when it is feasible and the
// objective is a non-negative combination of the four normals (the dual
// multipliers). Both are decided exactly from the doubles given (interval
// arithmetic first, rationals where the intervals cannot tell).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace cadmedial {

struct LinearConstraint {
  std::array<double, 4> normal;
  double bound;  // normal . x <= bound
};

struct CertifiedVertex {
  std::array<double, 4> x;  // the vertex, rounded to doubles
  bool feasible = false;    // every constraint holds exactly at the exact vertex
  bool optimal = false;     // feasible, and no other feasible point does better
  int objectiveSign = 0;    // sign of objective . vertex, exactly
};

// The basis's vertex, checked. When it is not optimal but primal or dual
// feasible, up to `maxPivots` exact simplex pivots move on to an optimal
// vertex, which is returned instead (a caller then knows the optimum's
// sign); if none is reached, the basis's own vertex is returned, checked.
// A basis rounding made neither primal nor dual feasible gets no pivots;
// the pivots then start from `feasibleStart`, when given (a basis the
// caller knows to be feasible, or likely so; checked like any other). nullopt when the
// four constraints do not meet in one point (a singular basis), an index is
// out of range or an input is not finite.
std::optional<CertifiedVertex> certifyBasis(const std::vector<LinearConstraint>& constraints,
                                            const std::array<std::size_t, 4>& basis,
                                            const std::array<double, 4>& objective, int maxPivots = 32,
                                            const std::optional<std::array<std::size_t, 4>>& feasibleStart = std::nullopt);

}  // namespace cadmedial
