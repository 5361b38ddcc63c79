#include "pair_mesh_boundary_cells.hpp"

#include <algorithm>
#include <cmath>


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

// The angle a cell takes up around its edge (u, v).
double dihedralAngle(const DelaunayVoronoi& dv, Index id, const DelaunayVoronoi::Vertex_handle& u,
                     const DelaunayVoronoi::Vertex_handle& v) {
  const auto c = dv.cell(id);
  DelaunayVoronoi::Vertex_handle other[2];
  int k = 0;
  for (int i = 0; i < 4; ++i)
    if (c->vertex(i) != u && c->vertex(i) != v) other[k++] = c->vertex(i);
  return std::abs(CGAL::approximate_dihedral_angle(u->point(), v->point(), other[0]->point(), other[1]->point()));
}

// The inner cells around the cell's edges that are cut off from the widest
// run (by angle) of inner cells around the same edge: what makes the edge
// non-manifold once the cell is outer.
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
      // Start the ring at an outer cell (there is one: the cell itself).
      const auto firstOuter = std::find_if(ring.begin(), ring.end(), [&](Index r) { return !isInner(dv, inner, r); });
      std::rotate(ring.begin(), firstOuter, ring.end());
      struct Run {
        std::size_t begin, end;
        double angle;
      };
      std::vector<Run> runs;
      for (std::size_t k = 0; k < ring.size();) {
        if (!isInner(dv, inner, ring[k])) {
          ++k;
          continue;
        }
        Run run{k, k, 0};
        while (run.end < ring.size() && isInner(dv, inner, ring[run.end]))
          run.angle += dihedralAngle(dv, ring[run.end++], c->vertex(i), c->vertex(j));
        runs.push_back(run);
        k = run.end;
      }
      if (runs.size() < 2) continue;
      const auto widest =
          std::max_element(runs.begin(), runs.end(), [](const Run& x, const Run& y) { return x.angle < y.angle; });
      for (auto r = runs.begin(); r != runs.end(); ++r)
        if (r != widest)
          for (std::size_t k = r->begin; k < r->end; ++k) out.push_back(ring[k]);
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
  // Each candidate is the seed of a group: itself and the runs of inner
  // cells it cuts off around its edges (the thin tip of a sliver wedge beyond
  // it), grown while the total stays within the bound.
  std::vector<std::uint8_t> trial = inner;
  for (Index id : cells) trial[id] = 0;
  const std::size_t seeds = cells.size();
  std::vector<Index> group(seeds);  // per cell: the seed it was grown from
  for (std::size_t k = 0; k < seeds; ++k) group[k] = static_cast<Index>(k);
  const std::size_t limit = 4 * cells.size() + 64;
  for (std::size_t checked = 0; checked < cells.size(); ++checked) {
    std::vector<Index> more;
    cutOffRuns(dv, trial, cells[checked], more);
    for (Index id : more)
      if (trial[id] && cells.size() < limit) {
        trial[id] = 0;
        cells.push_back(id);
        group.push_back(group[checked]);
      }
  }
  // A group with a cell that still leaves a non-manifold edge goes back as a
  // whole (its cut-off cells fix nothing without it), until none is left.
  for (bool dropped = true; dropped;) {
    dropped = false;
    std::vector<std::uint8_t> dropGroup(seeds, 0);
    for (std::size_t k = 0; k < cells.size(); ++k)
      if (!edgesStayManifold(dv, trial, cells[k])) dropGroup[group[k]] = 1;
    std::vector<Index> keptCells, keptGroups;
    for (std::size_t k = 0; k < cells.size(); ++k) {
      if (dropGroup[group[k]]) {
        trial[cells[k]] = inner[cells[k]];
        dropped = true;
      } else {
        keptCells.push_back(cells[k]);
        keptGroups.push_back(group[k]);
      }
    }
    cells = std::move(keptCells);
    group = std::move(keptGroups);
  }
  std::sort(cells.begin(), cells.end());
  return cells;
}

}  // namespace cadmedial
