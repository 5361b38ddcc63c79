#include "pair_mesh_boundary_cells.hpp"

#include <algorithm>


namespace cadmedial {

namespace {

bool isInner(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner, Index c) {
  return !dv.isInfinite(c) && inner[c] != 0;
}

bool onBoundary(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner, Index id) {
  const auto c = dv.cell(id);
  for (int i = 0; i < 4; ++i)
    if (!isInner(dv, inner, DelaunayVoronoi::cellId(c->neighbor(i)))) return true;
  return false;
}

// With `inner` as given, every edge of the cell has at most one run of inner
// cells around it (a manifold boundary along it).
bool edgesStayManifold(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner, Index id) {
  const auto& dt = dv.triangulation();
  const auto c = dv.cell(id);
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      auto circ = dt.incident_cells(c, i, j);
      const auto start = circ;
      int changes = 0;
      bool previous = isInner(dv, inner, DelaunayVoronoi::cellId(start));
      do {
        ++circ;
        const bool now = isInner(dv, inner, DelaunayVoronoi::cellId(circ));
        changes += now != previous ? 1 : 0;
        previous = now;
      } while (circ != start);
      if (changes > 2) return false;
    }
  return true;
}

// The inner cells around the cell's edges that are cut off from the largest
// run of inner cells around the same edge (what makes the edge non-manifold).
void cutOffRuns(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner, Index id, std::vector<Index>& out) {
  const auto& dt = dv.triangulation();
  const auto c = dv.cell(id);
  std::vector<Index> ring;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      ring.clear();
      auto circ = dt.incident_cells(c, i, j);
      const auto start = circ;
      do ring.push_back(DelaunayVoronoi::cellId(circ));
      while (++circ != start);
      // Rotate so that the ring starts with an outer cell (the flipped one is).
      const auto firstOuter = std::find_if(ring.begin(), ring.end(), [&](Index r) { return !isInner(dv, inner, r); });
      std::rotate(ring.begin(), firstOuter, ring.end());
      std::vector<std::pair<std::size_t, std::size_t>> runs;  // [begin, end)
      for (std::size_t k = 0; k < ring.size();) {
        if (!isInner(dv, inner, ring[k])) {
          ++k;
          continue;
        }
        std::size_t e = k;
        while (e < ring.size() && isInner(dv, inner, ring[e])) ++e;
        runs.push_back({k, e});
        k = e;
      }
      if (runs.size() < 2) continue;
      const auto longest = std::max_element(runs.begin(), runs.end(), [](const auto& x, const auto& y) {
        return x.second - x.first < y.second - y.first;
      });
      for (auto r = runs.begin(); r != runs.end(); ++r)
        if (r != longest)
          for (std::size_t k = r->first; k < r->second; ++k) out.push_back(ring[k]);
    }
}

}  // namespace

std::vector<Index> boundaryCellsOfInvertedElements(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner,
                                                   const PairMesh& mesh) {
  std::vector<Index> cells;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    if (!isInverted(mesh, i)) continue;
    for (Index n : mesh.tets[i])
      if (!mesh.isBoundaryNode(n) && mesh.nodeCell[n] != kNoIndex && onBoundary(dv, inner, mesh.nodeCell[n]))
        cells.push_back(mesh.nodeCell[n]);
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  // All together: a run of cells around an edge can only go as a whole.
  std::vector<std::uint8_t> trial = inner;
  for (Index id : cells) trial[id] = 0;
  // The runs of inner cells they cut off around an edge go too (the thin tip
  // of a sliver wedge beyond them), up to a bound.
  const std::size_t limit = 4 * cells.size() + 64;
  for (std::size_t checked = 0; checked < cells.size() && cells.size() <= limit; ++checked) {
    std::vector<Index> more;
    cutOffRuns(dv, trial, cells[checked], more);
    for (Index id : more)
      if (trial[id]) {
        trial[id] = 0;
        cells.push_back(id);
      }
  }
  // Those still with a non-manifold edge go back, until none is left.
  for (std::size_t before = cells.size() + 1; cells.size() < before;) {
    before = cells.size();
    std::vector<Index> kept;
    for (Index id : cells)
      if (edgesStayManifold(dv, trial, id)) kept.push_back(id);
    for (Index id : cells) trial[id] = inner[id];
    for (Index id : kept) trial[id] = 0;
    cells = std::move(kept);
  }
  std::sort(cells.begin(), cells.end());
  return cells;
}

}  // namespace cadmedial
