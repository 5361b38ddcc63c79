// The position of one pair-mesh node that keeps its elements as far from
// flat as possible: the volume of each element is an affine function of the
// node's position p, vol_i(p) = c_i + g_i . p, zero on a plane; the point
// that maximizes the smallest distance to those planes (on their positive
// sides) is the Chebyshev centre of the polytope where all elements are
// positive, a small linear program solved exactly by CGAL. The node then
// moves from where it is toward that centre only as far as it must for every
// element to be clearly positive, so it stays near its Voronoi vertex.
#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

#include <cmath>

#include "pair_mesh_element_checks.hpp"
#include "pair_mesh_node_position.hpp"

namespace cadmedial {

std::optional<Vec3> nearestValidNodePosition(const std::vector<Vec3>& nodes, Index node,
                                     const std::vector<std::array<Index, 4>>& elements, double reach) {
  if (elements.empty() || !(reach > 0)) return std::nullopt;
  const Vec3 start = nodes[node];
  // Unknowns: q (p = start + reach q, |q_j| <= 1) and the margin t (<= 1).
  using Program = CGAL::Quadratic_program<double>;
  Program lp(CGAL::SMALLER, false, 0, false, 0);
  std::vector<double> value, scale;  // per row: volume now, |gradient| (times reach)
  std::vector<std::array<double, 3>> gradients;
  int row = 0;
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
    for (int j = 0; j < 3; ++j) lp.set_a(j, row, -g[j] / norm);
    lp.set_a(3, row, 1.0);
    lp.set_b(row, c / norm);
    value.push_back(c);
    scale.push_back(norm);
    gradients.push_back({g[0], g[1], g[2]});
    ++row;
  }
  if (row == 0) return std::nullopt;
  for (int j = 0; j < 3; ++j) {
    lp.set_l(j, true, -1.0);
    lp.set_u(j, true, 1.0);
  }
  lp.set_u(3, true, 1.0);
  lp.set_c(3, -1.0);  // maximize t
  const auto solution = CGAL::solve_linear_program(lp, CGAL::Gmpzf());
  if (!solution.is_optimal()) return std::nullopt;
  double q[4] = {0, 0, 0, 0};
  int j = 0;
  for (auto it = solution.variable_values_begin(); it != solution.variable_values_end() && j < 4; ++it, ++j)
    q[j] = CGAL::to_double(*it);
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
    step = std::max(step, (wanted - value[r]) / along);
  }
  step = std::min(1.0, step);
  return Vec3{start[0] + step * reach * q[0], start[1] + step * reach * q[1], start[2] + step * reach * q[2]};
}

}  // namespace cadmedial
