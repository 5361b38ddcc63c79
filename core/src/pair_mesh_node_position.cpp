// The position of one pair-mesh node that keeps its elements as far from
// flat as possible: the volume of each element is an affine function of the
// node's position p, vol_i(p) = c_i + g_i . p, zero on a plane; the point
// that maximizes the smallest distance to those planes (on their positive
// sides) is the Chebyshev centre of the polytope where all elements are
// positive, a small linear program. It is solved in doubles (small_lp.cpp;
// the answer is only a candidate, which the repair checks with exact
// predicates). Where the double solver is not sure, the basis it ends on is
// checked exactly (lp_basis_certificate.hpp), and CGAL's exact solver runs
// only when that check cannot settle the sign of the margin. The
// node then moves from where it is toward that centre only as far as it
// must for every element to be clearly positive, so it stays near its
// Voronoi vertex.
#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

#include <cmath>

#include "pair_mesh_element_checks.hpp"
#include "lp_basis_certificate.hpp"
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
// and t is largest where -s is. nullopt when the solver is not sure; the
// basis it ended on, if any, goes to `basis` as constraint ids of
// `constraintsOf(program)` (empty when there is none).
std::optional<std::array<double, 4>> solveInDoubles(const ChebyshevProgram& program, std::vector<std::size_t>& basis) {
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
  std::vector<std::size_t> tight;
  const auto x = maximizeSmallLp(A, b, {0, 0, 0, -1}, &tight);
  basis.clear();
  const std::size_t m = program.b.size();
  for (std::size_t id : tight) {
    if (id < 3) basis.push_back(m + 3 + id);  // x_j = 0: q_j = -1
    else if (id == 3) basis.push_back(m + 6);  // s = 0: t = 1
    else basis.push_back(id - 4);  // a row: an element (< m) or q_j = 1
  }
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

// The program as constraints on (q, t): the rows, then q_j <= 1, -q_j <= 1
// and t <= 1, in the order solveInDoubles numbers them.
std::vector<LinearConstraint> constraintsOf(const ChebyshevProgram& program) {
  std::vector<LinearConstraint> constraints;
  for (std::size_t r = 0; r < program.b.size(); ++r) {
    const auto& a = program.a[r];
    constraints.push_back({{a[0], a[1], a[2], 1.0}, program.b[r]});
  }
  for (double side : {1.0, -1.0})
    for (int j = 0; j < 3; ++j) {
      LinearConstraint bound{{0, 0, 0, 0}, 1.0};
      bound.normal[j] = side;
      constraints.push_back(bound);
    }
  constraints.push_back({{0, 0, 0, 1.0}, 1.0});
  return constraints;
}

// What the exact check of the double solver's basis says about the margin.
struct CheckedBasis {
  enum class Verdict { PositiveMargin, NoPositiveMargin, Unsettled } verdict = Verdict::Unsettled;
  std::array<double, 4> q{};  // with a positive margin: a feasible (q, t) with t > 0
};

CheckedBasis checkBasis(const ChebyshevProgram& program, const std::vector<std::size_t>& basis) {
  CheckedBasis checked;
  if (basis.size() != 4) return checked;
  // Should rounding leave that basis neither primal nor dual feasible, the
  // exact pivots start from the corner q = (-1, -1, -1) instead, with t as
  // large as the rows let it be there: feasible, as t's coefficient is 1 in
  // every row (up to the doubles' choice of the tightest row).
  const std::size_t m = program.b.size();
  std::size_t tightest = m + 6;  // t <= 1
  double room = 1;
  for (std::size_t r = 0; r < m; ++r) {
    const double at = program.b[r] + program.a[r][0] + program.a[r][1] + program.a[r][2];
    if (at < room) {
      room = at;
      tightest = r;
    }
  }
  const auto vertex = certifyBasis(constraintsOf(program), {basis[0], basis[1], basis[2], basis[3]}, {0, 0, 0, 1}, 32,
                                   std::array<std::size_t, 4>{m + 3, m + 4, m + 5, tightest});
  if (!vertex || !vertex->feasible) return checked;
  if (vertex->objectiveSign > 0 && vertex->x[3] > 0) {  // (its double may underflow: then unsettled)
    checked.verdict = CheckedBasis::Verdict::PositiveMargin;
    checked.q = vertex->x;
  } else if (vertex->objectiveSign <= 0 && vertex->optimal) {
    checked.verdict = CheckedBasis::Verdict::NoPositiveMargin;
  }
  return checked;
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
  std::vector<std::size_t> basis;
  auto solution = solveInDoubles(program, basis);
  // A margin near zero in doubles may be rounding: exact arithmetic has the
  // last word there, first on the basis the double solver ended on, then,
  // when that basis does not settle the sign, CGAL's exact solver. A
  // clearly negative one (rows normalized, |q_j| <= 1: rounding is orders
  // of magnitude below 1e-7) means no position helps, and the exact solver
  // (0.2 ms each) would only say so again: the lever's repair asked it 599
  // times (box 64, CTC-01 139), and it never found a positive margin.
  const bool nearZero = solution && (*solution)[3] >= -1e-7 && !((*solution)[3] > 1e-9);
  if (!solution || nearZero) {
    const CheckedBasis checked = checkBasis(program, basis);
    if (checked.verdict == CheckedBasis::Verdict::NoPositiveMargin) return std::nullopt;
    if (checked.verdict == CheckedBasis::Verdict::PositiveMargin) solution = checked.q;
    else solution = solveExactly(program);
  }
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
