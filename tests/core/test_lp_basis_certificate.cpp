// The exact basis check of the pair-mesh repair's node LP against CGAL's
// exact LP solver: on programs of the repair's shape (maximize the margin t
// subject to a . q + t <= b, |q_j| <= 1, t <= 1), many built so that the
// optimal margin is within rounding of zero, the sign of the optimum it
// reports must be CGAL's, from the basis the double simplex ends on and
// from a box corner; and it must refuse what is not a basis.
#include <gtest/gtest.h>

#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "lp_basis_certificate.hpp"
#include "small_lp.hpp"

namespace cadmedial {
namespace {

struct Program {
  std::vector<std::array<double, 3>> a;
  std::vector<double> b;
};

// Rows, then q_j <= 1, then -q_j <= 1, then t <= 1 (the repair's order).
std::vector<LinearConstraint> constraintsOf(const Program& p) {
  std::vector<LinearConstraint> c;
  for (std::size_t r = 0; r < p.b.size(); ++r) c.push_back({{p.a[r][0], p.a[r][1], p.a[r][2], 1.0}, p.b[r]});
  for (double side : {1.0, -1.0})
    for (int j = 0; j < 3; ++j) {
      LinearConstraint bound{{0, 0, 0, 0}, 1.0};
      bound.normal[j] = side;
      c.push_back(bound);
    }
  c.push_back({{0, 0, 0, 1.0}, 1.0});
  return c;
}

// CGAL's exact optimum of t, and its sign.
struct ExactOptimum {
  double value;
  int sign;
};

ExactOptimum exactOptimum(const Program& p) {
  CGAL::Quadratic_program<double> lp(CGAL::SMALLER, false, 0, false, 0);
  for (std::size_t r = 0; r < p.b.size(); ++r) {
    for (int j = 0; j < 3; ++j) lp.set_a(j, static_cast<int>(r), p.a[r][j]);
    lp.set_a(3, static_cast<int>(r), 1.0);
    lp.set_b(static_cast<int>(r), p.b[r]);
  }
  for (int j = 0; j < 3; ++j) {
    lp.set_l(j, true, -1.0);
    lp.set_u(j, true, 1.0);
  }
  lp.set_u(3, true, 1.0);
  lp.set_c(3, -1.0);
  const auto s = CGAL::solve_linear_program(lp, CGAL::Gmpzf());
  EXPECT_TRUE(s.is_optimal());
  const auto value = -s.objective_value();
  return {CGAL::to_double(value), static_cast<int>(CGAL::sign(value))};
}

// The double simplex's final basis, in the ids of constraintsOf (the
// transform of pair_mesh_node_position.cpp: x_j = q_j + 1, s = 1 - t).
std::optional<std::array<std::size_t, 4>> doubleBasis(const Program& p) {
  std::vector<double> A, b;
  for (std::size_t r = 0; r < p.b.size(); ++r) {
    A.insert(A.end(), {p.a[r][0], p.a[r][1], p.a[r][2], -1.0});
    b.push_back(p.b[r] - 1 + p.a[r][0] + p.a[r][1] + p.a[r][2]);
  }
  for (int j = 0; j < 3; ++j) {
    for (int k = 0; k < 4; ++k) A.push_back(k == j ? 1 : 0);
    b.push_back(2);
  }
  std::vector<std::size_t> tight;
  maximizeSmallLp(A, b, {0, 0, 0, -1}, &tight);
  if (tight.size() != 4) return std::nullopt;
  const std::size_t m = p.b.size();
  std::array<std::size_t, 4> basis;
  for (int i = 0; i < 4; ++i) {
    const std::size_t id = tight[i];
    basis[i] = id < 3 ? m + 3 + id : id == 3 ? m + 6 : id - 4;
  }
  return basis;
}

// Unit normals; with `throughOnePoint`, every row's plane passes (up to the
// rounding of b) through one point (q0, 0), so the optimal margin is within
// rounding of zero, of either sign: the repair's hard case.
Program randomProgram(std::mt19937& rng, std::size_t rows, bool throughOnePoint) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> offset(-0.5, 2), inside(-0.9, 0.9);
  const std::array<double, 3> q0{inside(rng), inside(rng), inside(rng)};
  Program p;
  for (std::size_t r = 0; r < rows; ++r) {
    std::array<double, 3> a{normal(rng), normal(rng), normal(rng)};
    const double norm = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    for (double& x : a) x /= norm;
    p.a.push_back(a);
    p.b.push_back(throughOnePoint ? a[0] * q0[0] + a[1] * q0[1] + a[2] * q0[2] : offset(rng));
  }
  return p;
}

TEST(LpBasisCertificate, AgreesWithTheExactSolverFromTheDoubleBasisOrACorner) {
  std::mt19937 rng(5);
  int settled = 0, nearZero = 0, positive = 0, negative = 0, fromCorner = 0;
  const int trials = 600;
  for (int trial = 0; trial < trials; ++trial) {
    const bool degenerate = trial % 2 == 0;
    const Program p = randomProgram(rng, 4 + trial % 30, degenerate);
    const auto constraints = constraintsOf(p);
    const ExactOptimum exact = exactOptimum(p);
    // From the double solver's basis, as the repair does.
    if (const auto basis = doubleBasis(p)) {
      const auto vertex = certifyBasis(constraints, *basis, {0, 0, 0, 1});
      ASSERT_TRUE(vertex.has_value()) << "trial " << trial;
      if (vertex->optimal) {
        ++settled;
        EXPECT_EQ(vertex->objectiveSign, exact.sign) << "trial " << trial;
        EXPECT_NEAR(vertex->x[3], exact.value, 1e-12 * (1 + std::abs(exact.value))) << "trial " << trial;
      } else if (vertex->feasible) {
        // Not proven optimal: still a feasible point, so no better than the optimum.
        EXPECT_LE(vertex->objectiveSign, exact.sign) << "trial " << trial;
      }
    }
    // From the corner q = (-1, -1, -1) with t as large as the rows allow,
    // the tightest row found exactly here (long double is not enough in
    // general, but these offsets are far apart unless degenerate).
    const std::size_t m = p.b.size();
    std::size_t tightest = m + 6;
    double room = 1;
    for (std::size_t r = 0; r < m; ++r) {
      const double at = p.b[r] + p.a[r][0] + p.a[r][1] + p.a[r][2];
      if (at < room) {
        room = at;
        tightest = r;
      }
    }
    const std::array<std::size_t, 4> corner{m + 3, m + 4, m + 5, tightest};
    // An infeasible start with no feasible fallback: at most a checked vertex.
    const auto fromCornerVertex = certifyBasis(constraints, corner, {0, 0, 0, 1}, 64);
    ASSERT_TRUE(fromCornerVertex.has_value()) << "trial " << trial;
    if (fromCornerVertex->optimal) {
      ++fromCorner;
      EXPECT_EQ(fromCornerVertex->objectiveSign, exact.sign) << "trial " << trial;
      EXPECT_NEAR(fromCornerVertex->x[3], exact.value, 1e-12 * (1 + std::abs(exact.value))) << "trial " << trial;
    }
    if (std::abs(exact.value) < 1e-12) {
      ++nearZero;
      (exact.sign > 0 ? positive : negative) += 1;
    }
  }
  std::printf("certificate: %d of %d settled from the double basis, %d from the corner; optimum within 1e-12 of "
              "zero: %d (%d positive, %d not)\n",
              settled, trials, fromCorner, nearZero, positive, negative);
  EXPECT_GE(settled, trials * 9 / 10);
  EXPECT_GE(fromCorner, trials * 9 / 10);
  EXPECT_GE(positive, 10);  // the near-zero programs do test both signs
  EXPECT_GE(negative, 10);
}

TEST(LpBasisCertificate, ReportsWhatTheBasisIsWithoutPivots) {
  // max t with t <= 1 - q0, t <= 1 + q0 and the box: optimum t = 1 at q0 = 0.
  Program p;
  p.a = {{1, 0, 0}, {-1, 0, 0}};
  p.b = {1, 1};
  const auto c = constraintsOf(p);  // 0, 1 rows; 2-4 q <= 1; 5-7 -q <= 1; 8 t <= 1
  // {row 0, row 1, q1 <= 1, q2 <= 1}: q = (0, 1, 1), t = 1; optimal.
  auto v = certifyBasis(c, {0, 1, 3, 4}, {0, 0, 0, 1}, 0);
  ASSERT_TRUE(v.has_value());
  EXPECT_TRUE(v->feasible);
  EXPECT_TRUE(v->optimal);
  EXPECT_EQ(v->objectiveSign, 1);
  EXPECT_DOUBLE_EQ(v->x[3], 1);
  // {q0 <= 1, row 0, q1 <= 1, q2 <= 1}: q0 = 1, t = 0; feasible, not optimal.
  v = certifyBasis(c, {2, 0, 3, 4}, {0, 0, 0, 1}, 0);
  ASSERT_TRUE(v.has_value());
  EXPECT_TRUE(v->feasible);
  EXPECT_FALSE(v->optimal);
  EXPECT_EQ(v->objectiveSign, 0);
  // ... and with pivots it moves on to the optimum t = 1.
  v = certifyBasis(c, {2, 0, 3, 4}, {0, 0, 0, 1});
  ASSERT_TRUE(v.has_value());
  EXPECT_TRUE(v->optimal);
  EXPECT_DOUBLE_EQ(v->x[3], 1);
  // {-q0 <= 1 (q0 = -1), row 0, q1, q2}: t = 2 breaks t <= 1 and row 1: infeasible.
  v = certifyBasis(c, {5, 0, 3, 4}, {0, 0, 0, 1}, 0);
  ASSERT_TRUE(v.has_value());
  EXPECT_FALSE(v->feasible);
  EXPECT_FALSE(v->optimal);
  // A third row, q1 + t <= 0.5 (the optimum stays t = 1, at q1 <= -0.5).
  // {row 2, row 0, q1 <= 1, q2 <= 1}: q = (1.5, 1, 1), t = -0.5 breaks
  // q0 <= 1, and q1 <= 1's multiplier is -1: neither primal nor dual
  // feasible, so no pivots; from the corner q = (-1, -1, -1) (tightest:
  // row 1, t = 0) they reach the optimum.
  Program p3 = p;
  p3.a.push_back({0, 1, 0});
  p3.b.push_back(0.5);
  const auto c3 = constraintsOf(p3);  // rows 0-2; 3-5 q <= 1; 6-8 -q <= 1; 9 t <= 1
  v = certifyBasis(c3, {2, 0, 4, 5}, {0, 0, 0, 1});
  ASSERT_TRUE(v.has_value());
  EXPECT_FALSE(v->feasible);
  EXPECT_FALSE(v->optimal);
  v = certifyBasis(c3, {2, 0, 4, 5}, {0, 0, 0, 1}, 32, std::array<std::size_t, 4>{6, 7, 8, 1});
  ASSERT_TRUE(v.has_value());
  EXPECT_TRUE(v->optimal);
  EXPECT_DOUBLE_EQ(v->x[3], 1);
  // Singular (q0 <= 1 and -q0 <= 1 are parallel), a repeated id, out of range, a NaN.
  EXPECT_FALSE(certifyBasis(c, {2, 5, 3, 4}, {0, 0, 0, 1}).has_value());
  EXPECT_FALSE(certifyBasis(c, {0, 0, 3, 4}, {0, 0, 0, 1}).has_value());
  EXPECT_FALSE(certifyBasis(c, {0, 1, 3, 99}, {0, 0, 0, 1}).has_value());
  auto bad = c;
  bad[7].bound = NAN;
  EXPECT_FALSE(certifyBasis(bad, {0, 1, 3, 4}, {0, 0, 0, 1}).has_value());
}

}  // namespace
}  // namespace cadmedial
