// Exact check of one LP basis (see the header), division-free: with M the
// basis's 4x4 matrix of normals, D = det M and A = adj M (so M^-1 = A / D),
// the vertex is x = A r / D, the dual multipliers y = A^T c / D, and every
// sign the check needs is the sign of a polynomial in the input doubles
// times sign(D). Those polynomials are evaluated first in interval
// arithmetic, which settles them unless the vertex is (nearly) degenerate,
// then exactly in CGAL's Mpzf (the exact type of its own filtered
// predicates: integers times powers of two, no gcd, no division).
#include "lp_basis_certificate.hpp"

#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace cadmedial {

namespace {

// Unprotected intervals: the rounding mode is set once per check (see
// `check`), not per operation, which costs more than the arithmetic.
using Interval = CGAL::Interval_nt<false>;
using Exact = CGAL::Mpzf;

enum class Sign { Negative, Zero, Positive, Unknown };

Sign signOf(const Interval& v) {
  if (v.inf() > 0) return Sign::Positive;
  if (v.sup() < 0) return Sign::Negative;
  if (v.inf() == 0 && v.sup() == 0) return Sign::Zero;
  return Sign::Unknown;
}

Sign signOf(const Exact& v) {
  const CGAL::Sign s = v.sign();
  return s == CGAL::POSITIVE ? Sign::Positive : s == CGAL::NEGATIVE ? Sign::Negative : Sign::Zero;
}

Sign times(Sign a, Sign b) {
  if (a == Sign::Unknown || b == Sign::Unknown) return Sign::Unknown;
  if (a == Sign::Zero || b == Sign::Zero) return Sign::Zero;
  return a == b ? Sign::Positive : Sign::Negative;
}

// adj M (so M^-1 = adj M / det M) from the twelve 2x2 minors of rows 0-1
// (s) and rows 2-3 (c) that its 3x3 cofactors share (Laplace expansion):
// 72 products instead of 144 for sixteen separate 3x3 determinants, the
// same exact values.
template <class NT>
std::array<std::array<NT, 4>, 4> adjugate(const std::array<std::array<NT, 4>, 4>& m) {
  const NT s0 = m[0][0] * m[1][1] - m[1][0] * m[0][1];
  const NT s1 = m[0][0] * m[1][2] - m[1][0] * m[0][2];
  const NT s2 = m[0][0] * m[1][3] - m[1][0] * m[0][3];
  const NT s3 = m[0][1] * m[1][2] - m[1][1] * m[0][2];
  const NT s4 = m[0][1] * m[1][3] - m[1][1] * m[0][3];
  const NT s5 = m[0][2] * m[1][3] - m[1][2] * m[0][3];
  const NT c5 = m[2][2] * m[3][3] - m[3][2] * m[2][3];
  const NT c4 = m[2][1] * m[3][3] - m[3][1] * m[2][3];
  const NT c3 = m[2][1] * m[3][2] - m[3][1] * m[2][2];
  const NT c2 = m[2][0] * m[3][3] - m[3][0] * m[2][3];
  const NT c1 = m[2][0] * m[3][2] - m[3][0] * m[2][2];
  const NT c0 = m[2][0] * m[3][1] - m[3][0] * m[2][1];
  std::array<std::array<NT, 4>, 4> a;
  a[0][0] = m[1][1] * c5 - m[1][2] * c4 + m[1][3] * c3;
  a[0][1] = m[0][2] * c4 - m[0][1] * c5 - m[0][3] * c3;
  a[0][2] = m[3][1] * s5 - m[3][2] * s4 + m[3][3] * s3;
  a[0][3] = m[2][2] * s4 - m[2][1] * s5 - m[2][3] * s3;
  a[1][0] = m[1][2] * c2 - m[1][0] * c5 - m[1][3] * c1;
  a[1][1] = m[0][0] * c5 - m[0][2] * c2 + m[0][3] * c1;
  a[1][2] = m[3][2] * s2 - m[3][0] * s5 - m[3][3] * s1;
  a[1][3] = m[2][0] * s5 - m[2][2] * s2 + m[2][3] * s1;
  a[2][0] = m[1][0] * c4 - m[1][1] * c2 + m[1][3] * c0;
  a[2][1] = m[0][1] * c2 - m[0][0] * c4 - m[0][3] * c0;
  a[2][2] = m[3][0] * s4 - m[3][1] * s2 + m[3][3] * s0;
  a[2][3] = m[2][1] * s2 - m[2][0] * s4 - m[2][3] * s0;
  a[3][0] = m[1][1] * c1 - m[1][0] * c3 - m[1][2] * c0;
  a[3][1] = m[0][0] * c3 - m[0][1] * c1 + m[0][2] * c0;
  a[3][2] = m[3][1] * s1 - m[3][0] * s3 - m[3][2] * s0;
  a[3][3] = m[2][0] * s3 - m[2][1] * s1 + m[2][2] * s0;
  return a;
}

// One basis in exact form: D, the adjugate, the homogeneous vertex X = A r
// (x = X / D) and multipliers Y = A^T c (y = Y / D).
template <class NT>
struct Basis {
  NT D;
  std::array<std::array<NT, 4>, 4> adj;  // adj[i][j] = (A)_ij
  std::array<NT, 4> X, Y;
  Sign signD = Sign::Unknown;

  Basis(const std::vector<LinearConstraint>& constraints, const std::array<std::size_t, 4>& basis,
        const std::array<double, 4>& objective) {
    std::array<std::array<NT, 4>, 4> M;
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 4; ++k) M[i][k] = NT(constraints[basis[i]].normal[k]);
    adj = adjugate(M);
    D = NT(0);
    for (int k = 0; k < 4; ++k) D = D + M[0][k] * adj[k][0];
    signD = signOf(D);
    for (int i = 0; i < 4; ++i) {
      X[i] = NT(0);
      Y[i] = NT(0);
      for (int j = 0; j < 4; ++j) {
        X[i] = X[i] + adj[i][j] * NT(constraints[basis[j]].bound);
        Y[i] = Y[i] + adj[j][i] * NT(objective[j]);
      }
    }
  }

  // a . v for a constraint's normal and a homogeneous vector.
  static NT dot(const LinearConstraint& constraint, const std::array<NT, 4>& v) {
    NT sum(0);
    for (int k = 0; k < 4; ++k)
      if (constraint.normal[k] != 0) sum = sum + NT(constraint.normal[k]) * v[k];
    return sum;
  }

  // D times the slack bound - a . x, and its sign as a slack (times sign D).
  NT scaledSlack(const LinearConstraint& constraint) const { return NT(constraint.bound) * D - dot(constraint, X); }
  Sign slackSign(const LinearConstraint& constraint) const { return times(signOf(scaledSlack(constraint)), signD); }
  Sign multiplierSign(int i) const { return times(signOf(Y[i]), signD); }
  Sign objectiveSign(const std::array<double, 4>& objective) const {
    NT value(0);
    for (int k = 0; k < 4; ++k) value = value + NT(objective[k]) * X[k];
    return times(signOf(value), signD);
  }
  std::array<double, 4> vertex() const {
    const double d = CGAL::to_double(D);
    return {CGAL::to_double(X[0]) / d, CGAL::to_double(X[1]) / d, CGAL::to_double(X[2]) / d, CGAL::to_double(X[3]) / d};
  }
};

bool inBasis(const std::array<std::size_t, 4>& basis, std::size_t i) {
  return std::find(basis.begin(), basis.end(), i) != basis.end();
}

int toInt(Sign s) { return s == Sign::Positive ? 1 : s == Sign::Negative ? -1 : 0; }

// What an NT's arithmetic needs set around it: upward rounding for the
// intervals, nothing for the exact numbers.
template <class NT>
struct RoundingFor {};
template <>
struct RoundingFor<Interval> : Interval::Protector {};

// The signs a basis's check needs. Kept apart from the vertex's doubles:
// with intervals they are computed under upward rounding, which must not
// reach the plain double arithmetic of `Basis::vertex`.
struct BasisSigns {
  bool known = false, singular = false, feasible = true, dualFeasible = true;
  Sign objective = Sign::Unknown;
};

template <class NT>
BasisSigns signsOf(const Basis<NT>& b, const std::vector<LinearConstraint>& constraints,
                   const std::array<std::size_t, 4>& basis, const std::array<double, 4>& objective) {
  BasisSigns signs;
  signs.singular = b.signD == Sign::Zero;
  if (b.signD == Sign::Unknown || signs.singular) return signs;
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    if (inBasis(basis, i)) continue;  // holds with equality
    const Sign s = b.slackSign(constraints[i]);
    if (s == Sign::Unknown) return signs;
    if (s == Sign::Negative) signs.feasible = false;
  }
  for (int i = 0; i < 4; ++i) {
    const Sign s = b.multiplierSign(i);
    if (s == Sign::Unknown) return signs;
    if (s == Sign::Negative) signs.dualFeasible = false;
  }
  signs.objective = b.objectiveSign(objective);
  signs.known = signs.objective != Sign::Unknown;
  return signs;
}

// The basis's vertex checked with NT; nullopt when a sign is unknown (or,
// exactly, when the basis is singular: `singular` says so).
template <class NT>
std::optional<CertifiedVertex> check(const std::vector<LinearConstraint>& constraints,
                                     const std::array<std::size_t, 4>& basis, const std::array<double, 4>& objective,
                                     bool& singular) {
  std::optional<Basis<NT>> b;
  BasisSigns signs;
  {
    [[maybe_unused]] const RoundingFor<NT> rounding;
    b.emplace(constraints, basis, objective);
    signs = signsOf(*b, constraints, basis, objective);
  }
  singular = signs.singular;
  if (!signs.known) return std::nullopt;
  CertifiedVertex vertex;
  vertex.feasible = signs.feasible;
  vertex.optimal = signs.feasible && signs.dualFeasible;
  vertex.objectiveSign = toInt(signs.objective);
  vertex.x = b->vertex();
  return vertex;
}

// Exact simplex from a basis that is primal or dual feasible, in the form
// where a basis is four tight constraints. Primal feasible: the constraint
// whose multiplier is negative leaves (the vertex moves off its plane,
// raising the objective) and the first constraint met on the way enters.
// Dual feasible (the double solver's basis, a rounding away from
// feasible): a violated constraint enters and the basis constraint whose
// multiplier first reaches zero leaves, keeping the multipliers
// non-negative. Bland's rule (lowest index on every choice) cannot cycle on
// the degenerate vertices that are common here. Each basis is recomputed
// from the input doubles, so the numbers never grow. nullopt when the basis
// is neither, singular, or the pivots run out.
std::optional<CertifiedVertex> exactSimplex(const std::vector<LinearConstraint>& constraints,
                                            std::array<std::size_t, 4> basis, const std::array<double, 4>& objective,
                                            int maxPivots) {
  // Per basis, the signs are first asked of intervals (one rounding-mode
  // switch for all), and computed exactly only where those cannot tell:
  // at the degenerate vertices that bring a basis here, a few constraints
  // of ~20.
  std::vector<Sign> quickSlack(constraints.size()), quickRate(constraints.size());
  for (int pivots = 0; pivots <= maxPivots; ++pivots) {
    const Basis<Exact> b(constraints, basis, objective);
    if (b.signD == Sign::Zero) return std::nullopt;
    const bool flip = b.signD == Sign::Negative;  // multiply the scaled values by sign D
    auto normalized = [flip](Exact v) { return flip ? Exact(0) - v : v; };
    std::optional<Basis<Interval>> quick;
    {
      [[maybe_unused]] const RoundingFor<Interval> rounding;
      quick.emplace(constraints, basis, objective);
      for (std::size_t i = 0; i < constraints.size(); ++i)
        quickSlack[i] = inBasis(basis, i) ? Sign::Zero : quick->slackSign(constraints[i]);
    }
    auto slackSign = [&](std::size_t i) {
      return quickSlack[i] != Sign::Unknown ? quickSlack[i] : b.slackSign(constraints[i]);
    };
    std::size_t violated = constraints.size();
    for (std::size_t i = 0; i < constraints.size() && violated == constraints.size(); ++i)
      if (!inBasis(basis, i) && slackSign(i) == Sign::Negative) violated = i;
    int leaving = -1;
    for (int i = 0; i < 4; ++i)
      if (b.multiplierSign(i) == Sign::Negative && (leaving < 0 || basis[i] < basis[leaving])) leaving = i;
    if (violated == constraints.size() && leaving < 0) {
      CertifiedVertex vertex;
      vertex.feasible = vertex.optimal = true;
      vertex.objectiveSign = toInt(b.objectiveSign(objective));
      vertex.x = b.vertex();
      return vertex;
    }
    if (pivots == maxPivots) return std::nullopt;
    if (violated == constraints.size()) {
      // Primal pivot: off the leaving plane along d = -A e_leaving / D (its
      // normal . d = -1, the other three stay tight). Per other constraint,
      // scaled by |D|: rate = a . d, room = r - a . x; the step to it is
      // room / rate.
      std::array<Exact, 4> direction;
      for (int i = 0; i < 4; ++i) direction[i] = Exact(0) - b.adj[i][leaving];
      {  // the rates' signs: sign D times a . -A e_leaving
        [[maybe_unused]] const RoundingFor<Interval> rounding;
        std::array<Interval, 4> quickDirection;
        for (int i = 0; i < 4; ++i) quickDirection[i] = Interval(0) - quick->adj[i][leaving];
        for (std::size_t i = 0; i < constraints.size(); ++i)
          quickRate[i] = inBasis(basis, i) ? Sign::Zero
                                            : times(signOf(Basis<Interval>::dot(constraints[i], quickDirection)),
                                                    quick->signD);
      }
      std::size_t entering = constraints.size();
      Exact bestRoom, bestRate;
      for (std::size_t i = 0; i < constraints.size(); ++i) {
        if (inBasis(basis, i)) continue;
        if (quickRate[i] == Sign::Negative || quickRate[i] == Sign::Zero) continue;
        const Exact rate = normalized(Basis<Exact>::dot(constraints[i], direction));
        if (rate.sign() != CGAL::POSITIVE) continue;
        const Exact room = normalized(b.scaledSlack(constraints[i]));
        // room / rate < bestRoom / bestRate (rates positive); ties keep the lower index.
        if (entering == constraints.size() || room * bestRate < bestRoom * rate) {
          entering = i;
          bestRoom = room;
          bestRate = rate;
        }
      }
      if (entering == constraints.size()) return std::nullopt;  // unbounded
      basis[leaving] = entering;
    } else {
      if (leaving >= 0) return std::nullopt;  // neither primal nor dual feasible
      // Dual pivot: the violated normal in the basis's normals,
      // a = sum_i lambda_i n_i with lambda = A^T a / D; multipliers move as
      // y - s lambda, so the first to reach zero among lambda_i > 0 leaves.
      std::array<Exact, 4> lambda;
      for (int i = 0; i < 4; ++i) {
        Exact sum(0);
        for (int j = 0; j < 4; ++j)
          if (constraints[violated].normal[j] != 0) sum = sum + b.adj[j][i] * Exact(constraints[violated].normal[j]);
        lambda[i] = normalized(sum);
      }
      int out = -1;
      Exact bestY, bestLambda;
      for (int i = 0; i < 4; ++i) {
        if (lambda[i].sign() != CGAL::POSITIVE) continue;
        const Exact y = normalized(b.Y[i]);  // >= 0
        if (out < 0 || y * bestLambda < bestY * lambda[i] ||
            (y * bestLambda == bestY * lambda[i] && basis[i] < basis[out])) {
          out = i;
          bestY = y;
          bestLambda = lambda[i];
        }
      }
      if (out < 0) return std::nullopt;  // the program is infeasible
      basis[out] = violated;
    }
  }
  return std::nullopt;
}

bool validBasis(const std::vector<LinearConstraint>& constraints, const std::array<std::size_t, 4>& basis) {
  for (std::size_t i = 0; i < 4; ++i) {
    if (basis[i] >= constraints.size()) return false;
    for (std::size_t j = 0; j < i; ++j)
      if (basis[i] == basis[j]) return false;
  }
  return true;
}

}  // namespace

std::optional<CertifiedVertex> certifyBasis(const std::vector<LinearConstraint>& constraints,
                                            const std::array<std::size_t, 4>& basis,
                                            const std::array<double, 4>& objective, int maxPivots,
                                            const std::optional<std::array<std::size_t, 4>>& feasibleStart) {
  if (!validBasis(constraints, basis)) return std::nullopt;
  for (const auto& constraint : constraints) {
    if (!std::isfinite(constraint.bound)) return std::nullopt;
    for (double a : constraint.normal)
      if (!std::isfinite(a)) return std::nullopt;
  }
  for (double a : objective)
    if (!std::isfinite(a)) return std::nullopt;
  bool singular = false;
  const std::optional<CertifiedVertex> quick = check<Interval>(constraints, basis, objective, singular);
  if (singular) return std::nullopt;
  if (quick && (quick->optimal || maxPivots <= 0)) return quick;
  if (maxPivots > 0) {
    if (auto optimum = exactSimplex(constraints, basis, objective, maxPivots)) return optimum;
    if (feasibleStart && validBasis(constraints, *feasibleStart))
      if (auto optimum = exactSimplex(constraints, *feasibleStart, objective, maxPivots)) return optimum;
  }
  return quick ? quick : check<Exact>(constraints, basis, objective, singular);
}

}  // namespace cadmedial
