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

// Total volume of the inverted elements (positive).
double invertedVolume(const PairMesh& m) {
  double volume = 0;
  for (std::size_t i = 0; i < m.size(); ++i)
    if (isInverted(m, i)) volume -= tetVolume(m, i);
  return volume;
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
    std::size_t needingRepair = 0;
    // Every element's elementNeedsRepair in `mesh` as repaired: a trial
    // starts from them (a pass over every element less per trial).
    std::vector<std::uint8_t> flags;
    std::size_t inverted = repairFlippedElements(mesh, dv, {}, &needingRepair, &flags);
    // Last resort, up to ten passes: the boundary cells whose Voronoi
    // nodes the repair could not place go outer or, failing that, the outer
    // cells across the inverted elements' boundary facets go inner; first
    // for all inverted elements at once, then element by element (the
    // cells going outer with up to three rings of boundary cells around
    // them: a fold in a wedge thinner than the sampling, the lever's blade
    // between a plane and a cylinder touching it, can need a patch of the
    // wedge to go, not one cell). Only the elements around the cells are
    // rebuilt (the whole mesh where a split edge cannot be undone; either
    // way its time counts as repair), and the mesh is repaired again
    // (without the h/200 weld: the nodes are where the first repair left
    // them). A trial is kept when no more elements need repair (flat ones
    // included) and fewer stay inverted, or as many with less than half the
    // inverted volume; while the cells relabelled hold at most 1e-3 of the
    // enclosed volume in all, and for 32 trials at most (each copies and
    // repairs the whole mesh; trials refused by the budget cost nothing and
    // do not count; CTC-01 at h = 23.3, one spacing per face, is the one
    // sweep run that reaches the cap).
    const double budget = inverted > 0 ? 1e-3 * std::abs(boundaryEnclosedVolume(mesh)) : 0;
    double changed = 0;
    // The inverted volume only decides ties on the count: it is walked
    // for when one comes up (negative: not known yet).
    double invertedVolumeNow = -1;
    // One trial: the cells change side, the mesh is rebuilt around them and
    // repaired; kept (true) when it is better. Trials over the volume budget
    // cost nothing and do not count.
    int trials = 0;
    auto tryRelabelling = [&](const std::vector<Index>& cells, bool goingInner) {
      if (cells.empty() || trials >= 32) return false;
      double volume = 0;
      for (Index c : cells) volume += std::abs(dv.triangulation().tetrahedron(dv.cell(c)).volume());
      if (changed + volume > budget) return false;
      ++trials;
      std::vector<std::uint8_t> trialInner = inner;
      for (Index c : cells) trialInner[c] = goingInner ? 1 : 0;
      PairMesh trial = mesh;
      std::vector<std::uint8_t> trialFlags = flags;
      RepairOptions again;
      again.weldCloseNodes = again.countInvertedBefore = false;
      again.flagsAreCurrent = builder.relabel(trial, trialInner, cells, &trialFlags);
      if (!again.flagsAreCurrent) {  // (then the repair flags every element)
        trial = builder.build(trialInner);
        keepRepairedPositions(mesh, trial);
      }
      trial.counts.movedNodes = trial.counts.retriangulatedPolygons = 0;
      std::size_t trialNeedingRepair = 0;
      const std::size_t trialInverted = repairFlippedElements(trial, dv, again, &trialNeedingRepair, &trialFlags);
      // Fewer inverted, or as many with less volume inverted (a fold pushed
      // to a smaller cell, which the next pass may remove): the pair (count,
      // volume) only decreases, so the passes cannot cycle.
      if (trialNeedingRepair > needingRepair || trialInverted > inverted) return false;
      double trialInvertedVolume = -1;
      if (trialInverted == inverted) {
        if (invertedVolumeNow < 0) invertedVolumeNow = invertedVolume(mesh);
        trialInvertedVolume = invertedVolume(trial);
        if (!(trialInvertedVolume < 0.5 * invertedVolumeNow)) return false;
      }
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
      flags = std::move(trialFlags);
      inner = std::move(trialInner);
      inverted = trialInverted;
      invertedVolumeNow = trialInvertedVolume;
      needingRepair = trialNeedingRepair;
      changed += volume;
      return true;
    };
    for (int pass = 0; pass < 10 && inverted > 0; ++pass) {
      // All inverted elements at once first (one rebuild and repair); when
      // that helps neither way, element by element (a change that mends one
      // element can fold another, and together they cancel out).
      const std::vector<std::size_t> elements = invertedElements(mesh);
      bool kept = tryRelabelling(boundaryCellsOfElements(dv, inner, mesh, elements), false) ||
                  tryRelabelling(outerCellsAcrossElements(dv, inner, mesh, elements), true);
      if (!kept) {
        for (std::size_t k = 0; k < elements.size() && k < 16 && !kept; ++k) {
          const std::vector<std::size_t> one{elements[k]};
          for (int rings = 0; rings < 4 && !kept; ++rings)
            kept = tryRelabelling(boundaryCellsOfElements(dv, inner, mesh, one, rings), false);
          kept = kept || tryRelabelling(outerCellsAcrossElements(dv, inner, mesh, one), true);
        }
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
