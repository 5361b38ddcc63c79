#include "cadmedial/pair_mesh.hpp"
#include "pair_mesh_boundary_cells.hpp"
#include "pair_mesh_builder.hpp"
#include "pair_mesh_edit.hpp"
#include "pair_mesh_element_checks.hpp"
#include "pair_mesh_flat_cells.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <stdexcept>

#include "cadmedial/timer.hpp"

namespace cadmedial {

namespace {

// The Voronoi nodes of `rebuilt` take the positions the repair gave the
// nodes of the same cells in `repaired`: only the elements around the
// relabelled cells are left to repair.
void keepRepairedPositions(const PairMesh& repaired, PairMesh& rebuilt) {
  std::unordered_map<Index, Index> nodeOfCell;
  nodeOfCell.reserve(repaired.nodes.size());
  for (Index n = 0; n < repaired.nodes.size(); ++n)
    if (repaired.nodeCell[n] != kNoIndex) nodeOfCell.emplace(repaired.nodeCell[n], n);
  for (Index n = 0; n < rebuilt.nodes.size(); ++n) {
    if (rebuilt.nodeCell[n] == kNoIndex) continue;
    const auto it = nodeOfCell.find(rebuilt.nodeCell[n]);
    if (it != nodeOfCell.end()) rebuilt.nodes[n] = repaired.nodes[it->second];
  }
}

}  // namespace

const char* pairElementTypeName(PairElementType t) {
  switch (t) {
    case PairElementType::FaceVertex: return "face-vertex";
    case PairElementType::EdgeEdge: return "edge-edge";
    case PairElementType::VertexFace: return "vertex-face";
  }
  return "?";
}

PairMesh buildPairMesh(const DelaunayVoronoi& dv, const SampleSet& samples, const std::vector<std::uint8_t>& cellInner,
                       const MedialComplex* innerAxis, bool repair) {
  Stopwatch watch;
  if (cellInner.size() != dv.cellCount()) throw std::invalid_argument("pair-mesh: one inner label per cell needed");
  std::vector<std::uint8_t> inner = cellInner;
  const std::size_t relabelled = settleFlatCells(dv, inner);
  PairMeshBuilder builder(dv, samples, innerAxis);
  PairMesh mesh = builder.build(inner);
  mesh.counts.relabelledFlatCells = relabelled;
  mesh.seconds = watch.seconds();
  watch.restart();
  if (repair) {
    std::size_t inverted = repairFlippedElements(mesh, dv);
    // Last resort, up to three passes: the boundary cells whose Voronoi
    // nodes the repair could not place go outer or, failing that, the outer
    // cells across the inverted elements' boundary facets go inner. Only the
    // elements around the cells are rebuilt (the whole mesh where a split
    // edge cannot be undone; either way its time counts as repair), and the
    // mesh is repaired again (without the h/200 weld: the nodes are where the
    // first repair left them). A trial is kept only when fewer elements stay
    // inverted and no more need repair (flat ones included), and while the
    // cells relabelled hold at most 1e-3 of the enclosed volume in all.
    const double budget = inverted > 0 ? 1e-3 * std::abs(boundaryEnclosedVolume(mesh)) : 0;
    double changed = 0;
    std::size_t needingRepair = inverted > 0 ? countElementsNeedingRepair(mesh.nodes, mesh.tets) : 0;
    for (int pass = 0; pass < 3 && inverted > 0; ++pass) {
      bool kept = false;
      for (const bool goingInner : {false, true}) {
        const std::vector<Index> cells = goingInner ? outerCellsAcrossInvertedElements(dv, inner, mesh)
                                                    : boundaryCellsOfInvertedElements(dv, inner, mesh);
        if (cells.empty()) continue;
        double volume = 0;
        for (Index c : cells) volume += std::abs(dv.triangulation().tetrahedron(dv.cell(c)).volume());
        if (changed + volume > budget) continue;
        std::vector<std::uint8_t> trialInner = inner;
        for (Index c : cells) trialInner[c] = goingInner ? 1 : 0;
        PairMesh trial = mesh;
        if (!builder.relabel(trial, trialInner, cells)) {
          trial = builder.build(trialInner);
          keepRepairedPositions(mesh, trial);
        }
        trial.counts.movedNodes = trial.counts.retriangulatedPolygons = 0;
        const std::size_t trialInverted = repairFlippedElements(trial, dv, 12, /*weldCloseNodes=*/false);
        const std::size_t trialNeedingRepair = countElementsNeedingRepair(trial.nodes, trial.tets);
        if (trialInverted >= inverted || trialNeedingRepair > needingRepair) continue;
        // Counts of the kept mesh, except those of the whole history:
        // inverted before any repair, relabelled cells, and node moves and
        // polygon re-triangulations summed over the passes kept (split
        // edges: those the kept mesh has).
        PairMeshCounts& c = trial.counts;
        c.invertedBeforeRepair = mesh.counts.invertedBeforeRepair;
        c.relabelledFlatCells = relabelled;
        c.relabelledBoundaryCells = mesh.counts.relabelledBoundaryCells + cells.size();
        c.splitEdges = splitNodeCount(trial);
        c.movedNodes += mesh.counts.movedNodes;
        c.retriangulatedPolygons += mesh.counts.retriangulatedPolygons;
        trial.seconds = mesh.seconds;
        mesh = std::move(trial);
        inner = std::move(trialInner);
        inverted = trialInverted;
        needingRepair = trialNeedingRepair;
        changed += volume;
        kept = true;
        break;
      }
      if (!kept) break;
    }
  } else {
    const std::size_t negative = countElements(mesh.size(), [&](std::size_t i) { return isInverted(mesh, i); });
    mesh.counts.invertedBeforeRepair = mesh.counts.invertedAfterRepair = negative;
  }
  mesh.repairSeconds = watch.seconds();
  return mesh;
}

}  // namespace cadmedial
