#include "pair_mesh_flat_cells.hpp"

#include <algorithm>
#include <cmath>

namespace cadmedial {

namespace {

bool isFlat(const DelaunayVoronoi& dv, Index id) {
  const auto c = dv.cell(id);
  const auto& p0 = c->vertex(0)->point();
  const auto& p1 = c->vertex(1)->point();
  const auto& p2 = c->vertex(2)->point();
  const auto& p3 = c->vertex(3)->point();
  if (CGAL::orientation(p0, p1, p2, p3) == CGAL::ZERO) return true;
  double longest = 0;
  const DelaunayVoronoi::Point* p[4] = {&p0, &p1, &p2, &p3};
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) longest = std::max(longest, CGAL::squared_distance(*p[i], *p[j]));
  const double volume = std::abs(CGAL::volume(p0, p1, p2, p3));
  return volume <= 1e-12 * longest * std::sqrt(longest);
}

}  // namespace

std::size_t settleFlatCells(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner) {
  std::vector<Index> flat;
  for (Index id = 0; id < dv.cellCount(); ++id)
    if (!dv.isInfinite(id) && isFlat(dv, id)) flat.push_back(id);
  std::size_t relabelled = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (Index id : flat) {
      const auto c = dv.cell(id);
      int other = 0;
      for (int i = 0; i < 4; ++i) {
        const Index n = DelaunayVoronoi::cellId(c->neighbor(i));
        const bool neighbourInner = !dv.isInfinite(n) && inner[n] != 0;
        other += neighbourInner != (inner[id] != 0) ? 1 : 0;
      }
      if (other >= 3) {
        inner[id] = inner[id] ? 0 : 1;
        ++relabelled;
        changed = true;
      }
    }
  }
  return relabelled;
}

}  // namespace cadmedial
