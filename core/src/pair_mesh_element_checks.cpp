#include "pair_mesh_element_checks.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <functional>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

namespace cadmedial {

bool elementNeedsRepair(const std::vector<Vec3>& nodes, const std::array<Index, 4>& t) {
  if (hasCoincidentCorners(nodes, t)) return false;
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  auto point = [&](Index n) { return Point(nodes[n][0], nodes[n][1], nodes[n][2]); };
  return CGAL::orientation(point(t[0]), point(t[1]), point(t[2]), point(t[3])) != CGAL::POSITIVE;
}

void flagElementsNeedingRepair(const std::vector<Vec3>& nodes, const std::vector<std::array<Index, 4>>& tets,
                               std::vector<std::uint8_t>& flags, std::size_t first) {
  flags.resize(tets.size());
  if (first >= tets.size()) return;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(first, tets.size()), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) flags[i] = elementNeedsRepair(nodes, tets[i]) ? 1 : 0;
  });
}

std::size_t countElementsNeedingRepair(const std::vector<Vec3>& nodes, const std::vector<std::array<Index, 4>>& tets) {
  return countElements(tets.size(), [&](std::size_t i) { return elementNeedsRepair(nodes, tets[i]); });
}

std::size_t countElements(std::size_t count, const std::function<bool(std::size_t)>& test) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, count), std::size_t{0},
      [&](const tbb::blocked_range<std::size_t>& r, std::size_t n) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) n += test(i) ? 1 : 0;
        return n;
      },
      std::plus<std::size_t>());
}

std::vector<std::size_t> selectElements(std::size_t count, const std::function<bool(std::size_t)>& test) {
  std::vector<std::uint8_t> passes(count, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) passes[i] = test(i) ? 1 : 0;
  });
  std::vector<std::size_t> selected;
  for (std::size_t i = 0; i < count; ++i)
    if (passes[i]) selected.push_back(i);
  return selected;
}

bool hasCoincidentCorners(const std::vector<Vec3>& nodes, const std::array<Index, 4>& t) {
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      if (nodes[t[a]] == nodes[t[b]]) return true;
  return false;
}

double signedTetVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
  return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0])) /
         6.0;
}

}  // namespace cadmedial
