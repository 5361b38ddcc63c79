#include "cadmedial/facet_selection.hpp"

#include <tbb/parallel_for.h>

#include <cmath>

#include "cadmedial/timer.hpp"

namespace cadmedial {

namespace {

constexpr const int* kEdgeI = SelectedFacets::kEdgeI;
constexpr const int* kEdgeJ = SelectedFacets::kEdgeJ;

}  // namespace

SelectedFacets selectFacetsByAngleAndRatio(const DelaunayVoronoi& dv, const UmbrellaData& umbrellas,
                                           const MedialParams& params) {
  Stopwatch watch;
  SelectedFacets out;
  if (dv.dimension() < 3) return out;
  const auto& dt = dv.triangulation();
  const double sinTheta = std::sin(params.thetaDeg * M_PI / 180.0);
  const double rho = params.rho;
  const std::size_t cells = dv.cellCount();

  // Phase 1 (parallel): per cell, a 6-bit mask of its edges that pass the
  // test (an edge is tested from each cell around it: O(1) each, no
  // allocation). Phase 2 (sequential, deterministic): each selected edge is
  // circulated once, from the lowest cell id that has it, recording its ring
  // and marking it done in every cell of the ring.
  std::vector<std::uint8_t> selectedMask(cells, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells, 4096), [&](const tbb::blocked_range<std::size_t>& range) {
    for (std::size_t id = range.begin(); id != range.end(); ++id) {
      if (dv.isInfinite(static_cast<Index>(id))) continue;  // every finite edge has a finite cell
      const auto c = dv.cell(static_cast<Index>(id));
      std::uint8_t mask = 0;
      for (int e = 0; e < 6; ++e) {
        const auto vp = c->vertex(kEdgeI[e]);
        const auto vq = c->vertex(kEdgeJ[e]);
        const auto& P = vp->point();
        const auto& Q = vq->point();
        double dir[3] = {Q.x() - P.x(), Q.y() - P.y(), Q.z() - P.z()};
        const double len = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        bool selected = satisfiesAngleOrRatio(umbrellas, vp->info(), dir, len, sinTheta, rho);
        if (!selected) {
          const double back[3] = {-dir[0], -dir[1], -dir[2]};
          selected = satisfiesAngleOrRatio(umbrellas, vq->info(), back, len, sinTheta, rho);
        }
        if (selected) mask |= static_cast<std::uint8_t>(1u << e);
      }
      selectedMask[id] = mask;
    }
  });

  out.cellEdgeMask = selectedMask;  // phase 2 clears the bits it has done
  out.testSeconds = watch.seconds();
  // Finite edges by Euler's relation on S³ (V − E + F − C = 0 with the
  // infinite vertex, F = 2C) minus the hull vertices (2 + H/2 for H hull
  // triangles = infinite cells): CGAL's number_of_finite_edges() walks all edges.
  const std::size_t hull = cells - dv.finiteCellCount();
  out.finiteEdges = dt.number_of_vertices() + 1 + cells - (2 + hull / 2);
  out.lookup.reserve(out.finiteEdges / 2 + 16);
  for (std::size_t id = 0; id < cells; ++id) {
    const std::uint8_t mask = selectedMask[id];
    if (mask == 0) continue;
    const auto c = dv.cell(static_cast<Index>(id));
    for (int e = 0; e < 6; ++e) {
      if (!(mask & (1u << e))) continue;
      const auto vp = c->vertex(kEdgeI[e]);
      const auto vq = c->vertex(kEdgeJ[e]);
      Index p = vp->info(), q = vq->info();
      if (p > q) std::swap(p, q);
      out.lookup.insert(p, q, static_cast<Index>(out.edge.size()));
      out.edge.push_back({p, q});
      bool unbounded = false;
      auto circ = dt.incident_cells(c, kEdgeI[e], kEdgeJ[e]);
      const auto start = circ;
      do {
        const Index cid = DelaunayVoronoi::cellId(circ);
        unbounded = unbounded || dv.isInfinite(cid);
        out.ringCells.push_back(cid);
        const int a = circ->index(vp), b = circ->index(vq);
        selectedMask[cid] &= static_cast<std::uint8_t>(~(1u << SelectedFacets::cellEdgeBit(a, b)));
        ++circ;
      } while (circ != start);
      out.ringOffsets.push_back(static_cast<Index>(out.ringCells.size()));
      out.unbounded.push_back(unbounded ? 1 : 0);
      out.unboundedCount += unbounded ? 1 : 0;
    }
  }
  out.seconds = watch.seconds();
  return out;
}

}  // namespace cadmedial
