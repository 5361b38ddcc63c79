// The double-precision simplex of the pair-mesh repair against CGAL's exact
// LP solver: same optimal value on random programs of the repair's shape
// (normalized rows, boxed unknowns) and of a general one (rows through one
// vertex, infeasible starts), and the right refusals.
#include <gtest/gtest.h>

#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "small_lp.hpp"

namespace cadmedial {
namespace {

struct Program {
  std::size_t n = 0;
  std::vector<double> A, b, c;
};

// The exact optimum of max c.x, A x <= b, x >= 0 (nullopt: infeasible or unbounded).
std::optional<double> exactOptimum(const Program& p) {
  CGAL::Quadratic_program<double> lp(CGAL::SMALLER, true, 0, false, 0);
  for (std::size_t r = 0; r < p.b.size(); ++r) {
    for (std::size_t j = 0; j < p.n; ++j) lp.set_a(static_cast<int>(j), static_cast<int>(r), p.A[r * p.n + j]);
    lp.set_b(static_cast<int>(r), p.b[r]);
  }
  for (std::size_t j = 0; j < p.n; ++j) lp.set_c(static_cast<int>(j), -p.c[j]);  // CGAL minimizes
  const auto s = CGAL::solve_linear_program(lp, CGAL::Gmpzf());
  if (!s.is_optimal()) return std::nullopt;
  return -CGAL::to_double(s.objective_value());
}

double value(const Program& p, const std::vector<double>& x) {
  double v = 0;
  for (std::size_t j = 0; j < p.n; ++j) v += p.c[j] * x[j];
  return v;
}

// x is feasible up to rounding (x >= 0 holds by construction: the solver
// clamps its basic values at 0; the rows check what that clamp could hide).
void expectFeasible(const Program& p, const std::vector<double>& x) {
  for (std::size_t r = 0; r < p.b.size(); ++r) {
    double lhs = 0, scale = std::abs(p.b[r]);
    for (std::size_t j = 0; j < p.n; ++j) {
      lhs += p.A[r * p.n + j] * x[j];
      scale += std::abs(p.A[r * p.n + j] * x[j]);
    }
    EXPECT_LE(lhs, p.b[r] + 1e-9 * (1 + scale)) << "row " << r;
  }
}

// Rows of the repair: unit normals, offsets from -1 to 3; x_j <= 2 boxes.
Program repairShaped(std::mt19937& rng, std::size_t rows, bool throughOneVertex) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> offset(-1, 3);
  Program p;
  p.n = 4;
  const double shared = offset(rng);
  for (std::size_t r = 0; r < rows; ++r) {
    double a[3] = {normal(rng), normal(rng), normal(rng)};
    const double norm = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    for (double& x : a) x /= norm;
    const double b = throughOneVertex && r % 2 == 0 ? shared : offset(rng);
    p.A.insert(p.A.end(), {a[0], a[1], a[2], -1.0});
    p.b.push_back(b - 1 + a[0] + a[1] + a[2]);
  }
  for (int j = 0; j < 3; ++j) {
    for (int k = 0; k < 4; ++k) p.A.push_back(k == j ? 1 : 0);
    p.b.push_back(2);
  }
  p.c = {0, 0, 0, -1};
  return p;
}

TEST(SmallLp, MatchesTheExactSolverOnProgramsOfTheRepair) {
  std::mt19937 rng(7);
  int solved = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Program p = repairShaped(rng, 4 + trial % 40, trial % 3 == 0);
    const auto exact = exactOptimum(p);
    ASSERT_TRUE(exact.has_value());  // feasible (s large) and bounded (s >= 0)
    const auto x = maximizeSmallLp(p.A, p.b, p.c);
    if (!x) continue;  // allowed to be unsure; counted below
    ++solved;
    expectFeasible(p, *x);
    EXPECT_NEAR(value(p, *x), *exact, 1e-9 * (1 + std::abs(*exact))) << "trial " << trial;
  }
  EXPECT_GE(solved, 396);
}

TEST(SmallLp, MatchesTheExactSolverOnGeneralPrograms) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coefficient(-1, 1), bound(-0.5, 2);
  int optimal = 0, solved = 0, refused = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Program p;
    p.n = 2 + trial % 5;
    const std::size_t rows = 1 + trial % 13;
    for (std::size_t r = 0; r < rows; ++r) {
      for (std::size_t j = 0; j < p.n; ++j) p.A.push_back(coefficient(rng));
      p.b.push_back(bound(rng));  // negative: x = 0 infeasible, phase one
    }
    for (std::size_t j = 0; j < p.n; ++j) {  // a box keeps most bounded
      if (trial % 7 == 0 && j == 0) continue;  // x0 free above: sometimes unbounded
      for (std::size_t k = 0; k < p.n; ++k) p.A.push_back(k == j ? 1 : 0);
      p.b.push_back(3);
    }
    for (std::size_t j = 0; j < p.n; ++j) p.c.push_back(coefficient(rng));
    const auto exact = exactOptimum(p);
    const auto x = maximizeSmallLp(p.A, p.b, p.c);
    if (!exact) {
      EXPECT_FALSE(x.has_value()) << "trial " << trial;  // infeasible or unbounded
      ++refused;
      continue;
    }
    ++optimal;
    if (!x) continue;
    ++solved;
    expectFeasible(p, *x);
    EXPECT_NEAR(value(p, *x), *exact, 1e-9 * (1 + std::abs(*exact))) << "trial " << trial;
  }
  std::printf("general programs: %d optimal, %d infeasible or unbounded, %d solved in doubles\n", optimal, refused, solved);
  EXPECT_GE(optimal, 100);  // the test exercises both kinds
  EXPECT_GE(refused, 10);
  EXPECT_GE(solved, optimal - 2);
}

TEST(SmallLp, RefusesInfeasibleAndUnboundedPrograms) {
  // x <= 1 and -x <= -2 (x >= 2): infeasible.
  EXPECT_FALSE(maximizeSmallLp({1, -1}, {1, -2}, {1}).has_value());
  // max x with only x - y <= 1: unbounded.
  EXPECT_FALSE(maximizeSmallLp({1, -1}, {1}, {1, 0}).has_value());
  // Malformed sizes and non-finite input.
  EXPECT_FALSE(maximizeSmallLp({1, 2, 3}, {1}, {1, 1}).has_value());
  EXPECT_FALSE(maximizeSmallLp({NAN}, {1}, {1}).has_value());
  // max x + y, x + 2y <= 4, 3x + y <= 6: (1.6, 1.2).
  const auto x = maximizeSmallLp({1, 2, 3, 1}, {4, 6}, {1, 1});
  ASSERT_TRUE(x.has_value());
  EXPECT_NEAR((*x)[0], 1.6, 1e-12);
  EXPECT_NEAR((*x)[1], 1.2, 1e-12);
}

}  // namespace
}  // namespace cadmedial
