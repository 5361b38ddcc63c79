// Two-phase simplex on a dictionary (the slack form of CLRS ch. 29) with
// Bland's rule, which cannot cycle on degenerate vertices; those are common
// here (many elements' planes through one Voronoi vertex).
#include "small_lp.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cadmedial {

namespace {

// Pivots smaller than this (coefficients are O(1) for the repair's
// normalized rows) are not trusted.
constexpr double kPivotTolerance = 1e-11;
constexpr int kMaxPivots = 1000;

// x_basic[i] = b[i] - sum_j a(i, j) x_nonbasic[j];  z = v + sum_j c[j] x_nonbasic[j].
struct Dictionary {
  std::size_t rows = 0, cols = 0;
  std::vector<double> a, b, c;
  double v = 0;
  std::vector<std::size_t> basic, nonbasic;  // variable ids

  double& at(std::size_t i, std::size_t j) { return a[i * cols + j]; }

  void pivot(std::size_t l, std::size_t e) {
    const double inverse = 1 / at(l, e);
    b[l] *= inverse;
    for (std::size_t j = 0; j < cols; ++j)
      if (j != e) at(l, j) *= inverse;
    at(l, e) = inverse;
    for (std::size_t i = 0; i < rows; ++i) {
      if (i == l) continue;
      const double f = at(i, e);
      if (f == 0) continue;
      b[i] -= f * b[l];
      for (std::size_t j = 0; j < cols; ++j)
        if (j != e) at(i, j) -= f * at(l, j);
      at(i, e) = -f * inverse;
    }
    const double f = c[e];
    v += f * b[l];
    for (std::size_t j = 0; j < cols; ++j)
      if (j != e) c[j] -= f * at(l, j);
    c[e] = -f * inverse;
    std::swap(basic[l], nonbasic[e]);
  }

  enum class Outcome { Optimal, Unbounded, Unsure };

  // Bland: the entering variable with the smallest id among those that
  // raise z, the leaving one with the smallest id among the tightest rows.
  Outcome maximize() {
    for (int pivots = 0; pivots < kMaxPivots; ++pivots) {
      std::size_t e = cols;
      for (std::size_t j = 0; j < cols; ++j)
        if (c[j] > kPivotTolerance && (e == cols || nonbasic[j] < nonbasic[e])) e = j;
      if (e == cols) return Outcome::Optimal;
      std::size_t l = rows;
      double ratio = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < rows; ++i) {
        const double coefficient = at(i, e);
        if (!(coefficient > kPivotTolerance)) continue;
        const double r = std::max(0.0, b[i]) / coefficient;
        if (l == rows || r < ratio || (r == ratio && basic[i] < basic[l])) {
          ratio = r;
          l = i;
        }
      }
      if (l == rows) return Outcome::Unbounded;
      pivot(l, e);
    }
    return Outcome::Unsure;
  }
};

}  // namespace

std::optional<std::vector<double>> maximizeSmallLp(const std::vector<double>& A, const std::vector<double>& b,
                                                   const std::vector<double>& c, std::vector<std::size_t>* tight) {
  if (tight) tight->clear();
  const std::size_t n = c.size(), m = b.size();
  if (n == 0 || A.size() != m * n) return std::nullopt;
  for (double x : A)
    if (!std::isfinite(x)) return std::nullopt;
  for (double x : b)
    if (!std::isfinite(x)) return std::nullopt;

  // Phase 1 (only when x = 0 is not feasible): an auxiliary variable, id
  // n + m, relaxes every row; maximizing its negative finds a feasible
  // vertex, after one pivot onto the most violated row.
  const std::size_t auxiliary = n + m;
  const std::size_t mostViolated = m == 0 ? 0 : static_cast<std::size_t>(std::min_element(b.begin(), b.end()) - b.begin());
  const bool phaseOne = m > 0 && b[mostViolated] < 0;
  Dictionary d;
  d.rows = m;
  d.cols = n + (phaseOne ? 1 : 0);
  d.a.assign(m * d.cols, 0);
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = 0; j < n; ++j) d.at(i, j) = A[i * n + j];
    if (phaseOne) d.at(i, n) = -1;
    d.basic.push_back(n + i);
  }
  d.b = b;
  for (std::size_t j = 0; j < n; ++j) d.nonbasic.push_back(j);
  if (phaseOne) {
    d.nonbasic.push_back(auxiliary);
    d.c.assign(d.cols, 0);
    d.c[n] = -1;
    d.pivot(mostViolated, n);
    if (d.maximize() != Dictionary::Outcome::Optimal) return std::nullopt;
    if (d.v < -1e-9 * (1 + std::abs(b[mostViolated]))) return std::nullopt;  // infeasible
    // The auxiliary variable leaves (it is 0): a degenerate pivot if basic.
    const auto row = std::find(d.basic.begin(), d.basic.end(), auxiliary);
    if (row != d.basic.end()) {
      const std::size_t l = static_cast<std::size_t>(row - d.basic.begin());
      std::size_t e = d.cols;
      for (std::size_t j = 0; j < d.cols; ++j)
        if (std::abs(d.at(l, j)) > kPivotTolerance && (e == d.cols || std::abs(d.at(l, j)) > std::abs(d.at(l, e))))
          e = j;
      if (e == d.cols) return std::nullopt;
      d.pivot(l, e);
    }
    // Drop its column.
    const std::size_t gone =
        static_cast<std::size_t>(std::find(d.nonbasic.begin(), d.nonbasic.end(), auxiliary) - d.nonbasic.begin());
    std::vector<double> a(m * n);
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t j = 0, k = 0; j < d.cols; ++j)
        if (j != gone) a[i * n + k++] = d.at(i, j);
    d.a = std::move(a);
    d.nonbasic.erase(d.nonbasic.begin() + static_cast<std::ptrdiff_t>(gone));
    d.cols = n;
  }
  // The objective in the current nonbasic variables.
  d.c.assign(n, 0);
  d.v = 0;
  for (std::size_t j = 0; j < n; ++j)
    if (d.nonbasic[j] < n) d.c[j] += c[d.nonbasic[j]];
  for (std::size_t i = 0; i < m; ++i)
    if (d.basic[i] < n) {
      const double w = c[d.basic[i]];
      d.v += w * d.b[i];
      for (std::size_t j = 0; j < n; ++j) d.c[j] -= w * d.at(i, j);
    }
  if (d.maximize() != Dictionary::Outcome::Optimal) return std::nullopt;
  if (tight) *tight = d.nonbasic;
  std::vector<double> x(n, 0);
  for (std::size_t i = 0; i < m; ++i)
    if (d.basic[i] < n) x[d.basic[i]] = std::max(0.0, d.b[i]);
  return x;
}

}  // namespace cadmedial
