// The position of one pair-mesh node that keeps its elements as far from
// flat as possible: the volume of each element is an affine function of the
// node's position p, vol_i(p) = c_i + g_i . p, zero on a plane; the point
// that maximizes the smallest distance to those planes (on their positive
// sides) is the Chebyshev centre of the polytope where all elements are
// positive, a small linear program. It is solved in doubles (small_lp.cpp;
// the answer is only a candidate, which the repair checks with exact
// predicates) and exactly by CGAL when the double solver is not sure. The
// node then moves from where it is toward that centre only as far as it
// must for every element to be clearly positive, so it stays near its
// Voronoi vertex.
#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

#include <cmath>

#include "pair_mesh_element_checks.hpp"
#include "pair_mesh_node_position.hpp"
#include "small_lp.hpp"

namespace cadmedial {

namespace {

// Rows a . q + t <= b (a normalized), unknowns |q_j| <= 1 and t <= 1.
struct ChebyshevProgram {
  std::vector<std::array<double, 3>> a;
  std::vector<double> b;
};

// (q, t) maximizing t, in doubles: with x_j = q_j + 1 in [0, 2] and
// s = 1 - t >= 0 the rows read a . x - s <= b - 1 + sum_j a_j, plus x_j <= 2,
// and t is largest where -s is. nullopt when the solver is not sure.
std::optional<std::array<double, 4>> solveInDoubles(const ChebyshevProgram& program) {
  std::vector<double> A, b;
  for (std::size_t r = 0; r < program.b.size(); ++r) {
    const auto& a = program.a[r];
    A.insert(A.end(), {a[0], a[1], a[2], -1.0});
    b.push_back(program.b[r] - 1 + a[0] + a[1] + a[2]);
  }
  for (int j = 0; j < 3; ++j) {
    for (int k = 0; k < 4; ++k) A.push_back(k == j ? 1 : 0);
    b.push_back(2);
  }
  const auto x = maximizeSmallLp(A, b, {0, 0, 0, -1});
  if (!x) return std::nullopt;
  // Rounding in the pivots is not bounded: an answer that breaks a row by
  // more than 1e-9 (rows are normalized) goes to the exact solver.
  for (std::size_t r = 0; r < b.size(); ++r) {
    double lhs = 0;
    for (int k = 0; k < 4; ++k) lhs += A[4 * r + k] * (*x)[k];
    if (!(lhs <= b[r] + 1e-9 * (1 + std::abs(b[r])))) return std::nullopt;
  }
  return std::array<double, 4>{(*x)[0] - 1, (*x)[1] - 1, (*x)[2] - 1, 1 - (*x)[3]};
}

// The same exactly (CGAL, Gmpzf): slow, about 0.2 ms for 20 rows.
std::optional<std::array<double, 4>> solveExactly(const ChebyshevProgram& program) {
  CGAL::Quadratic_program<double> lp(CGAL::SMALLER, false, 0, false, 0);
  for (std::size_t r = 0; r < program.b.size(); ++r) {
    const int row = static_cast<int>(r);
    for (int j = 0; j < 3; ++j) lp.set_a(j, row, program.a[r][j]);
    lp.set_a(3, row, 1.0);
    lp.set_b(row, program.b[r]);
  }
  for (int j = 0; j < 3; ++j) {
    lp.set_l(j, true, -1.0);
    lp.set_u(j, true, 1.0);
  }
  lp.set_u(3, true, 1.0);
  lp.set_c(3, -1.0);  // maximize t
  const auto solution = CGAL::solve_linear_program(lp, CGAL::Gmpzf());
  if (!solution.is_optimal()) return std::nullopt;
  std::array<double, 4> q{0, 0, 0, 0};
  int j = 0;
  for (auto it = solution.variable_values_begin(); it != solution.variable_values_end() && j < 4; ++it, ++j)
    q[j] = CGAL::to_double(*it);
  return q;
}

}  // namespace

std::optional<Vec3> nearestValidNodePosition(const std::vector<Vec3>& nodes, Index node,
                                     const std::vector<std::array<Index, 4>>& elements, double reach) {
  if (elements.empty() || !(reach > 0)) return std::nullopt;
  const Vec3 start = nodes[node];
  // Unknowns: q (p = start + reach q, |q_j| <= 1) and the margin t (<= 1).
  ChebyshevProgram program;
  std::vector<double> value, scale;  // per row: volume now, |gradient| (times reach)
  std::vector<std::array<double, 3>> gradients;
  for (const auto& e : elements) {
    // vol(start + reach q) = c + reach g . q, with g from the affine function.
    auto volumeAt = [&](const Vec3& p) {
      Vec3 q[4];
      for (int k = 0; k < 4; ++k) q[k] = e[k] == node ? p : nodes[e[k]];
      return signedTetVolume(q[0], q[1], q[2], q[3]);
    };
    const double c = volumeAt(start);
    double g[3], norm = 0;
    for (int j = 0; j < 3; ++j) {
      Vec3 p = start;
      p[j] += reach;
      g[j] = volumeAt(p) - c;  // = reach * gradient_j (exact for an affine function, up to rounding)
      norm += g[j] * g[j];
    }
    norm = std::sqrt(norm);
    if (!(norm > 0)) {  // the node does not move this element
      if (c <= 0) return std::nullopt;  // and it is not positive: no position helps
      continue;
    }
    // c + g . q >= norm t   <=>   -g . q + norm t <= c   (all divided by norm)
    program.a.push_back({-g[0] / norm, -g[1] / norm, -g[2] / norm});
    program.b.push_back(c / norm);
    value.push_back(c);
    scale.push_back(norm);
    gradients.push_back({g[0], g[1], g[2]});
  }
  if (program.b.empty()) return std::nullopt;
  auto solution = solveInDoubles(program);
  // A margin near zero in doubles may be rounding: the exact solver has the
  // last word there. A clearly negative one (rows normalized, |q_j| <= 1:
  // rounding is orders of magnitude below 1e-7) means no position helps,
  // and the exact solver (0.2 ms each) would only say so again: the lever's
  // repair asked it 599 times (box 64, CTC-01 139), and it never found a
  // positive margin.
  const bool nearZero = solution && (*solution)[3] >= -1e-7 && !((*solution)[3] > 1e-9);
  if (!solution || nearZero) solution = solveExactly(program);
  if (!solution) return std::nullopt;
  const auto& q = *solution;
  const double margin = q[3];
  if (!(margin > 0)) return std::nullopt;  // no position makes every element positive
  // Along start + s reach q (s in [0, 1]) each volume is c + s g . q; the
  // smallest s where all reach a tenth of the optimal margin.
  double step = 0;
  for (std::size_t r = 0; r < value.size(); ++r) {
    const double along = gradients[r][0] * q[0] + gradients[r][1] * q[1] + gradients[r][2] * q[2];
    const double wanted = 0.1 * margin * scale[r];
    if (value[r] >= wanted) continue;
    if (!(along > 0)) return std::nullopt;  // rounding: the LP point is not better for this element
    step = std::min(1.0, std::max(step, (wanted - value[r]) / along));
  }
  return Vec3{start[0] + step * reach * q[0], start[1] + step * reach * q[1], start[2] + step * reach * q[2]};
}

}  // namespace cadmedial
