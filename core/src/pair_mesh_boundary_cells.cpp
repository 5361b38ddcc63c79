#include "pair_mesh_boundary_cells.hpp"
#include "pair_mesh_element_checks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

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

// The cells around the cell's edge (i, j), starting at one of the other
// side when there is one, and the runs [begin, end) of cells on side
// `innerSide` (inner cells, or outer ones: infinite cells are outer).
struct EdgeRing {
  std::vector<Index> cells;
  std::vector<std::pair<std::size_t, std::size_t>> runs;
};
EdgeRing runsAround(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner, Index id, int i, int j,
                    bool innerSide = true) {
  EdgeRing ring;
  auto circ = dv.triangulation().incident_cells(dv.cell(id), i, j);
  const auto start = circ;
  do ring.cells.push_back(DelaunayVoronoi::cellId(circ));
  while (++circ != start);
  auto onSide = [&](Index r) { return isInner(dv, inner, r) == innerSide; };
  const auto firstOther = std::find_if(ring.cells.begin(), ring.cells.end(), [&](Index r) { return !onSide(r); });
  std::rotate(ring.cells.begin(), firstOther, ring.cells.end());
  for (std::size_t k = 0; k < ring.cells.size();) {
    if (!onSide(ring.cells[k])) {
      ++k;
      continue;
    }
    std::size_t e = k;
    while (e < ring.cells.size() && onSide(ring.cells[e])) ++e;
    ring.runs.push_back({k, e});
    k = e;
  }
  return ring;
}

// With `inner` as given, every edge of the cell has at most one run of inner
// cells around it (a manifold boundary along it).
bool edgesStayManifold(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner, Index id) {
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (runsAround(dv, inner, id, i, j).runs.size() > 1) return false;
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

// The cells of side `innerSide` around the cell's edges that are cut off
// from the widest run (by angle) of that side around the same edge: what
// makes the edge non-manifold once the cell has changed side. A run with an
// infinite cell counts as the widest (it cannot change side).
void cutOffRuns(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner, Index id, bool innerSide,
                std::vector<Index>& out) {
  const auto c = dv.cell(id);
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const EdgeRing ring = runsAround(dv, inner, id, i, j, innerSide);
      if (ring.runs.size() < 2) continue;
      std::vector<double> angle(ring.runs.size(), 0);
      for (std::size_t r = 0; r < ring.runs.size(); ++r)
        for (std::size_t k = ring.runs[r].first; k < ring.runs[r].second; ++k)
          angle[r] += dv.isInfinite(ring.cells[k]) ? std::numeric_limits<double>::infinity()
                                                    : dihedralAngle(dv, ring.cells[k], c->vertex(i), c->vertex(j));
      const std::size_t widest = std::max_element(angle.begin(), angle.end()) - angle.begin();
      for (std::size_t r = 0; r < ring.runs.size(); ++r)
        if (r != widest)
          for (std::size_t k = ring.runs[r].first; k < ring.runs[r].second; ++k)
            if (!dv.isInfinite(ring.cells[k])) out.push_back(ring.cells[k]);
    }
}

// The seeds change side (to inner when goingInner) together, each with the
// runs of cells it cuts off around its edges (the thin tip of a sliver
// wedge beyond it), grown while the total stays within 4 × seeds + 64. A
// group with a cell that still leaves a non-manifold edge goes back as a
// whole (its cut-off cells fix nothing without it), until none is left.
std::vector<Index> growKeepingEdgesManifold(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner,
                                            std::vector<Index> cells, bool goingInner) {
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  const std::uint8_t to = goingInner ? 1 : 0;
  std::vector<std::uint8_t> trial = inner;
  for (Index id : cells) trial[id] = to;
  const std::size_t seeds = cells.size();
  std::vector<Index> group(seeds);  // per cell: the seed it was grown from
  for (std::size_t k = 0; k < seeds; ++k) group[k] = static_cast<Index>(k);
  const std::size_t limit = 4 * cells.size() + 64;
  for (std::size_t checked = 0; checked < cells.size(); ++checked) {
    std::vector<Index> more;
    cutOffRuns(dv, trial, cells[checked], /*innerSide=*/!goingInner, more);
    for (Index id : more)
      if (trial[id] != to && cells.size() < limit) {
        trial[id] = to;
        cells.push_back(id);
        group.push_back(group[checked]);
      }
  }
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

}  // namespace

std::vector<std::size_t> invertedElements(const PairMesh& mesh) {
  return selectElements(mesh.size(), [&](std::size_t i) { return isInverted(mesh, i); });
}

std::vector<Index> boundaryCellsOfElements(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner,
                                           const PairMesh& mesh, const std::vector<std::size_t>& elements,
                                           int rings) {
  std::vector<Index> cells;
  for (const std::size_t i : elements) {
    for (Index n : mesh.tets[i])
      if (!mesh.isBoundaryNode(n) && mesh.nodeCell[n] != kNoIndex && onBoundary(dv, inner, mesh.nodeCell[n]))
        cells.push_back(mesh.nodeCell[n]);
  }
  for (int ring = 0; ring < rings; ++ring) {
    const std::size_t size = cells.size();
    for (std::size_t k = 0; k < size; ++k) {
      const auto c = dv.cell(cells[k]);
      for (int f = 0; f < 4; ++f) {
        const Index n = DelaunayVoronoi::cellId(c->neighbor(f));
        if (isInner(dv, inner, n) && onBoundary(dv, inner, n) &&
            std::find(cells.begin(), cells.end(), n) == cells.end())
          cells.push_back(n);
      }
    }
  }
  return growKeepingEdgesManifold(dv, inner, std::move(cells), /*goingInner=*/false);
}

std::vector<Index> outerCellsAcrossElements(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner,
                                            const PairMesh& mesh, const std::vector<std::size_t>& elements) {
  const auto& dt = dv.triangulation();
  std::vector<Index> cells;
  // The outer neighbours of inner cell `id` across its facets that hold all
  // of `samples` (its boundary facets there).
  auto across = [&](Index id, const std::vector<Index>& samples) {
    const auto c = dv.cell(id);
    for (int k = 0; k < 4; ++k) {
      const Index n = DelaunayVoronoi::cellId(c->neighbor(k));
      if (isInner(dv, inner, n) || dv.isInfinite(n)) continue;
      bool holds = true;
      for (Index s : samples) holds = holds && s != c->vertex(k)->info() && dv.cellHasSample(id, s);
      if (holds) cells.push_back(n);
    }
  };
  for (const std::size_t i : elements) {
    const auto& t = mesh.tets[i];
    if (mesh.type[i] == PairElementType::VertexFace) {
      std::vector<Index> samples;
      for (int k = 1; k < 4; ++k)
        if (mesh.isSampleNode(t[k])) samples.push_back(t[k]);
      across(mesh.medialSimplex[i][0], samples);
    } else if (mesh.type[i] == PairElementType::FaceVertex) {
      for (int k = 1; k < 4; ++k)
        if (mesh.nodeCell[t[k]] != kNoIndex) across(mesh.nodeCell[t[k]], {});
    } else if (mesh.type[i] == PairElementType::EdgeEdge && mesh.isSampleNode(t[0]) && mesh.isSampleNode(t[1])) {
      DelaunayVoronoi::Cell_handle start;
      int a = 0, b = 0;
      if (!dt.is_edge(dv.vertex(t[0]), dv.vertex(t[1]), start, a, b)) continue;
      auto circ = dt.incident_cells(start, a, b);
      const auto first = circ;
      do {
        const Index id = DelaunayVoronoi::cellId(circ);
        if (isInner(dv, inner, id)) across(id, {t[0], t[1]});
      } while (++circ != first);
    }
  }
  return growKeepingEdgesManifold(dv, inner, std::move(cells), /*goingInner=*/true);
}

}  // namespace cadmedial
