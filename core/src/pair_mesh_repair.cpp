// Seed 003 §4.1: flipped Vertex-Face and Edge-Edge elements come from Voronoi
// vertices that lie outside the boundary surface (near it, where the solid's
// surface bulges past the Delaunay triangles). Moving such a vertex toward
// the inside of its own Delaunay cell turns its Vertex-Face elements positive
// (the centroid of the cell is on the inner side of each of its facets), and
// the step is kept as small as the neighbouring elements allow.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "cadmedial/pair_mesh.hpp"
#include "cadmedial/union_find.hpp"
#include "pair_mesh_element_checks.hpp"
#include "pair_mesh_facet_triangulation.hpp"
#include "pair_mesh_incidence.hpp"
#include "pair_mesh_node_position.hpp"
#include "point_box.hpp"

namespace cadmedial {

namespace {


double squaredLength(const Vec3& a, const Vec3& b) {
  const double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
  return x * x + y * y + z * z;
}

}  // namespace

double tetVolume(const PairMesh& m, std::size_t i) {
  const auto& t = m.tets[i];
  return signedTetVolume(m.nodes[t[0]], m.nodes[t[1]], m.nodes[t[2]], m.nodes[t[3]]);
}

bool isInverted(const PairMesh& m, std::size_t i) {
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  const auto& t = m.tets[i];
  if (hasCoincidentCorners(m.nodes, t)) return false;
  auto point = [&](Index n) { return Point(m.nodes[n][0], m.nodes[n][1], m.nodes[n][2]); };
  return CGAL::orientation(point(t[0]), point(t[1]), point(t[2]), point(t[3])) == CGAL::NEGATIVE;
}

namespace {

bool needsRepair(const PairMesh& m, std::size_t i) { return elementNeedsRepair(m.nodes, m.tets[i]); }

}  // namespace

double negligibleVolume(const PairMesh& m, std::size_t i) {
  const auto& t = m.tets[i];
  double longest = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) longest = std::max(longest, squaredLength(m.nodes[t[a]], m.nodes[t[b]]));
  return 1e-12 * longest * std::sqrt(longest);
}

namespace {

// Rounds of Voronoi node moves (first case of §4.1); marks moved nodes.
// Returns the number of elements left needing repair (negative or flat),
// and flags them in badFlag (per element).
// With flagsCurrent, badFlag already says which elements need repair.
std::size_t moveVoronoiNodes(PairMesh& m, const DelaunayVoronoi& dv, int rounds, std::vector<std::uint8_t>& moved,
                             std::vector<std::uint8_t>& badFlag, bool flagsCurrent) {
  const std::size_t n = m.nodes.size();
  moved.resize(n, 0);
  // Per element: needs repair. Kept current as nodes move (only the
  // elements around a moved node change, and the polygons re-triangulated
  // update theirs), so that no round has to test all elements again.
  // The elements flagged, so that a round looks at those only (a few
  // hundred among 10^5-10^6): every flagged element is listed; elements
  // flagged no more, and repeats, until the next count.
  std::vector<std::size_t> flagged;
  auto countFlagged = [&]() {
    std::sort(flagged.begin(), flagged.end());
    flagged.erase(std::unique(flagged.begin(), flagged.end()), flagged.end());
    flagged.erase(std::remove_if(flagged.begin(), flagged.end(), [&](std::size_t i) { return badFlag[i] == 0; }),
                  flagged.end());
    return flagged.size();
  };
  // Flags every element (unless the caller's flags are current) and lists
  // the flagged ones.
  auto flagAndListAll = [&]() {
    if (!flagsCurrent) flagElementsNeedingRepair(m.nodes, m.tets, badFlag);
    flagged.clear();
    for (std::size_t i = 0; i < m.tets.size(); ++i)
      if (badFlag[i]) flagged.push_back(i);
    return flagged.size();
  };
  auto negative = [&badFlag](std::size_t i) { return badFlag[i] != 0; };
  // Node -> incident tetrahedra, kept through the re-triangulations. Only
  // Voronoi nodes move, and only near the flagged elements (a few hundred
  // of 10^5-10^6; a relabelling trial's repair often starts from one or
  // two), so it is built for the Voronoi nodes within two rings of those,
  // and built again around them and the node asked for when a node outside
  // is asked for. A node's list is the same as in an incidence of all nodes,
  // so are the repair's choices. (The whole incidence was the costliest
  // step of the lever's trials: 11 ms a build.)
  NodeIncidence incidence;
  auto voronoiNode = [&m](Index v) { return !m.isBoundaryNode(v); };
  std::vector<std::uint8_t> inRegion;
  auto inRegionNode = [&inRegion](Index v) { return inRegion[v] != 0; };
  auto buildIncidenceAround = [&](const std::vector<Index>& alsoNodes) {
    inRegion.assign(m.nodes.size(), 0);
    for (std::size_t i : flagged)
      for (Index v : m.tets[i])
        if (voronoiNode(v)) inRegion[v] = 1;
    for (Index v : alsoNodes) inRegion[v] = 1;
    // (Each ring's Voronoi nodes gathered in parallel, marked after.)
    for (int ring = 0; ring < 2; ++ring) {
      tbb::enumerable_thread_specific<std::vector<Index>> reached;
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, m.tets.size()), [&](const auto& r) {
        auto& local = reached.local();
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          const auto& t = m.tets[i];
          if (inRegion[t[0]] || inRegion[t[1]] || inRegion[t[2]] || inRegion[t[3]])
            for (Index v : t)
              if (voronoiNode(v) && !inRegion[v]) local.push_back(v);
        }
      });
      for (const auto& local : reached)
        for (Index v : local) inRegion[v] = 1;
    }
    incidence.build(m, inRegionNode);
  };
  // Before asking for the elements of these nodes.
  auto ensureIncidence = [&](const std::vector<Index>& nodes) {
    if (!std::all_of(nodes.begin(), nodes.end(), inRegionNode)) buildIncidenceAround(nodes);
  };
  // Elements needing repair around v (and their volume short of zero in
  // *deficit); once there are more than `most`, the rest are not tested.
  auto negativeAround = [&](Index v, double* deficit, std::size_t most = std::numeric_limits<std::size_t>::max()) {
    std::size_t count = 0;
    incidence.forEach(m, v, [&](Index i) {
      if (count > most) return;
      if (needsRepair(m, i)) {
        ++count;
        if (deficit) *deficit -= tetVolume(m, i);
      }
    });
    return count;
  };

  auto flagAround = [&](Index v) {
    incidence.forEach(m, v, [&](Index i) {
      badFlag[i] = needsRepair(m, i) ? 1 : 0;
      if (badFlag[i]) flagged.push_back(i);
    });
  };
  // The polygons the re-triangulations met, with their element slots (no
  // element changes its slot in here).
  PolygonSlots polygonSlots;

  // Negative elements around a set of nodes, each element counted once.
  std::vector<std::uint32_t> seen(m.tets.size(), 0);
  std::uint32_t stamp = 0;
  auto negativeAroundSet = [&](const std::vector<Index>& set, double* deficit) {
    ++stamp;
    std::size_t count = 0;
    for (Index v : set)
      incidence.forEach(m, v, [&](Index i) {
        if (seen[i] == stamp) return;
        seen[i] = stamp;
        if (needsRepair(m, i)) {
          ++count;
          *deficit -= tetVolume(m, i);
        }
      });
    return count;
  };
  // Nearly cospherical samples (the symmetric triplets along a convex edge)
  // have Voronoi vertices that should coincide; rounding of the samples
  // spreads them by ~1 % of the spacing in an arbitrary order, which folds
  // the short Voronoi edges between them. Moving a whole cluster of such
  // nodes (reachable through elements, within 5 % of the element size of
  // the seed) to one point makes the elements between them flat.
  auto collapseNodeClusters = [&]() {
    bool collapsed = false;
    for (std::size_t i = 0; i < m.tets.size(); ++i) {
      if (!negative(i)) continue;
      const double size = std::cbrt(negligibleVolume(m, i) * 1e12);  // longest edge
      std::vector<Index> cluster;
      for (Index v : m.tets[i])
        if (!m.isBoundaryNode(v) &&
            (cluster.empty() || squaredLength(m.nodes[v], m.nodes[cluster[0]]) < 0.0025 * size * size))
          cluster.push_back(v);
      if (cluster.empty()) continue;
      const Vec3 seed = m.nodes[cluster[0]];
      for (std::size_t q = 0; q < cluster.size() && cluster.size() < 32; ++q) {
        ensureIncidence({cluster[q]});
        incidence.forEach(m, cluster[q], [&](Index i) {
          for (Index u : m.tets[i])
            if (!m.isBoundaryNode(u) && std::find(cluster.begin(), cluster.end(), u) == cluster.end() &&
                squaredLength(m.nodes[u], seed) < 0.0025 * size * size)
              cluster.push_back(u);
        });
      }
      ensureIncidence(cluster);
      std::vector<Vec3> start;
      Vec3 centroid{0, 0, 0};
      for (Index v : cluster) {
        start.push_back(m.nodes[v]);
        for (int k = 0; k < 3; ++k) centroid[k] += m.nodes[v][k] / static_cast<double>(cluster.size());
      }
      double deficit0 = 0;
      const std::size_t before = negativeAroundSet(cluster, &deficit0);
      std::vector<Vec3> targets{centroid};
      targets.insert(targets.end(), start.begin(), start.end());
      std::size_t bestCount = before;
      double bestDeficit = deficit0;
      const Vec3* best = nullptr;
      for (const Vec3& target : targets) {
        for (Index v : cluster) m.nodes[v] = target;
        double deficit = 0;
        const std::size_t count = negativeAroundSet(cluster, &deficit);
        if (count < bestCount || (count == bestCount && deficit < bestDeficit)) {
          best = &target;
          bestCount = count;
          bestDeficit = deficit;
        }
      }
      for (std::size_t k = 0; k < cluster.size(); ++k) {
        m.nodes[cluster[k]] = best && bestCount < before ? *best : start[k];
        if (best && bestCount < before) moved[cluster[k]] = 1;
      }
      collapsed = collapsed || (best && bestCount < before);
      for (Index v : cluster) flagAround(v);
    }
    return collapsed;
  };

  static constexpr double kSteps[] = {0.03125, 0.0625, 0.125, 0.25, 0.5, 0.75, 1.0};
  // The LP is for nodes among elements of the part's size. A node whose
  // elements reach 100 × the samples' extent (the circumcenter of a nearly
  // flat cell, 1e16 away: the exact LP over such coordinates ran for minutes
  // without an answer) is left to the simpler candidates.
  const double extent = boxOf(m.nodes.data(), m.nodes.data() + m.sampleNodes).diagonal();
  auto bestPosition = [&](Index v) -> std::optional<Vec3> {
    std::vector<std::array<Index, 4>> elements;
    double far = 0;
    incidence.forEach(m, v, [&](Index i) {
      elements.push_back(m.tets[i]);
      for (Index u : m.tets[i]) far = std::max(far, squaredLength(m.nodes[v], m.nodes[u]));
    });
    if (!(std::sqrt(far) <= 100 * extent)) return std::nullopt;
    return nearestValidNodePosition(m.nodes, v, elements, 0.5 * std::sqrt(far));
  };

  std::size_t bad = flagAndListAll();
  if (bad == 0) return 0;  // before the incidence: on CTC-01 a 0.05 s pass
  buildIncidenceAround({});
  for (int round = 0; round < rounds && bad > 0; ++round) {
    // A round is a function of the mesh (and of which half of the rounds it
    // is in): after a round that changed nothing, the rest of its half would
    // change nothing either.
    bool changedMesh = false;
    // Moves fold Voronoi polygons that another triangulation keeps positive.
    std::vector<std::uint64_t> rewritten;
    if (const std::size_t changed = retriangulateFaceVertexPolygons(m, &badFlag, &flagged, &polygonSlots, &rewritten)) {
      changedMesh = true;
      m.counts.retriangulatedPolygons += changed;
      for (std::uint64_t key : rewritten) incidence.polygonRewritten(m, polygonSlots.at(key));
    }
    bad = countFlagged();  // also compacts the list the candidates come from
    if (bad == 0) break;
    std::vector<Index> candidates;
    for (std::size_t i : flagged)
      for (Index v : m.tets[i])
        if (!m.isBoundaryNode(v)) candidates.push_back(v);
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    ensureIncidence(candidates);
    for (Index v : candidates) {
      double deficit0 = 0;
      const std::size_t before = negativeAround(v, &deficit0);
      if (before == 0) continue;
      const Index cell = m.nodeCell[v];
      Vec3 centroid{0, 0, 0};
      for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 3; ++k) centroid[k] += 0.25 * m.nodes[dv.cellSample(cell, i)][k];
      const Vec3 start = m.nodes[v];
      // Candidates: steps toward the centroid, then the positions of the
      // Voronoi nodes it shares elements with. The latter fix nearly flat
      // cells (four cocircular samples, e.g. triplet legs around a convex
      // edge): their circumcenter is any point of the circle's axis, and the
      // one picked can fall outside the span of the neighbours' vertices on
      // that axis, folding the Voronoi polygons; a neighbour's position
      // unfolds them (the elements between the two become flat).
      // First the nearest position where all its elements are positive (an
      // LP, when there is one), then steps toward the centroid and the
      // neighbours' positions, keeping the one with the fewest negative.
      std::vector<Vec3> targets;
      if (const auto p = bestPosition(v)) targets.push_back(*p);
      for (double s : kSteps)
        targets.push_back({(1 - s) * start[0] + s * centroid[0], (1 - s) * start[1] + s * centroid[1],
                           (1 - s) * start[2] + s * centroid[2]});
      // Each neighbour once (it is in several of the node's elements; a
      // repeated target could never win, as only a strictly better one does).
      std::vector<Index> neighbours;
      incidence.forEach(m, v, [&](Index i) {
        for (Index u : m.tets[i])
          if (u != v && !m.isBoundaryNode(u) && std::find(neighbours.begin(), neighbours.end(), u) == neighbours.end()) {
            neighbours.push_back(u);
            const Vec3& q = m.nodes[u];
            targets.push_back(q);
            targets.push_back({(start[0] + q[0]) / 2, (start[1] + q[1]) / 2, (start[2] + q[2]) / 2});
          }
      });
      Vec3 best = start;
      std::size_t bestCount = before;
      double bestDeficit = deficit0;
      for (const Vec3& target : targets) {
        m.nodes[v] = target;
        double deficit = 0;
        // (A target with more than the best so far cannot win: counting
        // stops there.)
        const std::size_t count = negativeAround(v, &deficit, bestCount);
        if (count < bestCount || (count == bestCount && deficit < bestDeficit)) {
          best = target;
          bestCount = count;
          bestDeficit = deficit;
        }
        if (count == 0) break;
      }
      m.nodes[v] = best;
      flagAround(v);
      if (best != start) moved[v] = changedMesh = true;
    }
    // Only when single moves have stalled (round past half): collapsing
    // clusters trades elements and is the rougher tool.
    if (2 * round >= rounds && collapseNodeClusters()) changedMesh = true;
    bad = countFlagged();
    if (!changedMesh) {
      if (2 * round >= rounds) break;
      round = (rounds + 1) / 2 - 1;  // on to the first round that collapses clusters
    }
  }
  if (bad > 0) {
    if (const std::size_t changed = retriangulateFaceVertexPolygons(m, &badFlag, &flagged, &polygonSlots)) {
      m.counts.retriangulatedPolygons += changed;
      bad = countFlagged();
    }
  }
  return bad;
}

// Voronoi nodes closer than h/200 are, on planar parts, one vertex of
// nearly cospherical samples (the symmetric triplets along convex edges)
// spread by the samples' rounding; the slivers between them cut into
// iso-surface triangles whose rounded corners cross. Each cluster of such
// nodes (joined through elements) goes to one member's position when that
// leaves no more elements needing repair around it than before (on curved
// parts close nodes are often genuinely distinct, and then the move is
// refused). Returns the number of nodes moved.
// `needsRepairFlags`, when given, holds every element's needsRepair on entry
// and is kept so: the count before a move is read from it, and the pass
// that accepts a move (which has tested every element of the cluster)
// writes its results (on the lever and torus, testing the moved clusters'
// elements again afterwards was a fifth of the weld).
std::size_t weldCloseVoronoiNodes(PairMesh& m, double tolerance, std::vector<std::uint8_t>* needsRepairFlags) {
  if (!(tolerance > 0)) return 0;
  const std::size_t n = m.nodes.size();
  // Clusters: nodes joined through elements by pairs closer than tolerance.
  // Most nodes join none; only those that do are gathered, and only theirs
  // is the incidence below (on the lever, 58 k lone nodes took half the
  // weld's time).
  // The close pairs: every element's six, tested in parallel (few are close;
  // a serial pass was a fifth of the lever's first repair).
  const double limit = tolerance * tolerance;
  tbb::enumerable_thread_specific<std::vector<std::array<Index, 2>>> closePairs;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, m.tets.size()), [&](const auto& r) {
    auto& found = closePairs.local();
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      const auto& t = m.tets[i];
      for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b)
          if (!m.isBoundaryNode(t[a]) && !m.isBoundaryNode(t[b]) && squaredLength(m.nodes[t[a]], m.nodes[t[b]]) <= limit)
            found.push_back({t[a], t[b]});
    }
  });
  // Clusters and their members' order do not depend on the order of the unions.
  UnionFind joined(n);
  std::vector<std::uint8_t> inPair(n, 0);
  for (const auto& found : closePairs)
    for (const auto& [a, b] : found) {
      joined.unite(a, b);
      inPair[a] = inPair[b] = 1;
    }
  std::vector<std::vector<Index>> clusters;
  {
    std::vector<Index> slot(n, kNoIndex);
    for (Index v = 0; v < n; ++v) {
      if (!inPair[v]) continue;
      const Index r = joined.find(v);
      if (slot[r] == kNoIndex) {
        slot[r] = static_cast<Index>(clusters.size());
        clusters.emplace_back();
      }
      clusters[slot[r]].push_back(v);
    }
  }
  // Node -> incident elements, for the clustered nodes only.
  NodeIncidence incidence;
  incidence.build(m, [&inPair](Index v) { return inPair[v] != 0; });
  // The clusters that may move (a cluster moves its own nodes only, so this
  // holds until it is decided), each with its elements once.
  std::vector<Index> active;
  std::vector<std::size_t> elementOffsets{0};
  std::vector<Index> elements;
  std::vector<std::uint8_t> listed(m.tets.size(), 0);
  for (Index c = 0; c < clusters.size(); ++c) {
    const std::vector<Index>& cluster = clusters[c];
    if (cluster.size() < 2) continue;
    std::vector<Vec3> start;
    for (Index v : cluster) start.push_back(m.nodes[v]);
    if (std::all_of(start.begin(), start.end(), [&](const Vec3& p) { return p == start[0]; })) continue;
    // A target must be within 2 × tolerance of every member, so none is
    // when the cluster spans more than 4 × tolerance along an axis. Checked
    // first: chains of close pairs can hold thousands of nodes (the apex of
    // a cone), and the member-by-member test below is quadratic.
    if (boxOf(start.data(), start.data() + start.size()).widestSide() > 4 * tolerance) continue;
    // (Each once, marked while listed: their order does not matter below,
    // and sorting them was a sixth of the torus's weld.)
    const std::size_t first = elements.size();
    for (Index v : cluster)
      incidence.forEach(m, v, [&](Index i) {
        if (listed[i]) return;
        listed[i] = 1;
        elements.push_back(i);
      });
    for (std::size_t k = first; k < elements.size(); ++k) listed[elements[k]] = 0;
    active.push_back(c);
    elementOffsets.push_back(elements.size());
  }
  // Moves a cluster onto one member's position, or leaves it; returns the
  // number of members moved. It reads the positions of its elements' nodes
  // (and writes their flags, when kept).
  auto decide = [&](std::size_t a) -> std::size_t {
    const std::vector<Index>& cluster = clusters[active[a]];
    const std::size_t firstElement = elementOffsets[a], elementCount = elementOffsets[a + 1] - firstElement;
    std::vector<Vec3> start;
    for (Index v : cluster) start.push_back(m.nodes[v]);
    // Elements needing repair, counted up to `most` + 1 (a move is refused
    // as soon as it has more than before: on the torus three moves in four
    // are, and counting them out was most of the weld); each one's answer
    // goes to `tested` (complete when the count is at most `most`).
    std::vector<std::uint8_t> tested(elementCount);
    auto badUpTo = [&](std::size_t most) {
      std::size_t count = 0;
      for (std::size_t k = 0; k < elementCount && count <= most; ++k)
        count += tested[k] = needsRepair(m, elements[firstElement + k]) ? 1 : 0;
      return count;
    };
    std::size_t before = 0;
    if (needsRepairFlags)
      for (std::size_t k = 0; k < elementCount; ++k) before += (*needsRepairFlags)[elements[firstElement + k]];
    else
      before = badUpTo(std::numeric_limits<std::size_t>::max());
    for (std::size_t k = 0; k < cluster.size(); ++k) {  // onto each member's position in turn
      // Chains of close pairs can span far: every member must be near the target.
      bool compact = true;
      for (const Vec3& p : start) compact = compact && squaredLength(p, start[k]) <= 4 * limit;
      if (!compact) continue;
      for (Index v : cluster) m.nodes[v] = start[k];
      if (badUpTo(before) <= before) {
        if (needsRepairFlags)
          for (std::size_t e = 0; e < elementCount; ++e) (*needsRepairFlags)[elements[firstElement + e]] = tested[e];
        return static_cast<std::size_t>(
            std::count_if(start.begin(), start.end(), [&](const Vec3& p) { return p != start[k]; }));
      }
    }
    for (std::size_t k = 0; k < cluster.size(); ++k) m.nodes[cluster[k]] = start[k];
    return 0;
  };
  // Decided as in one pass in order, in waves: a cluster goes in the wave
  // after the last one holding an earlier cluster it shares an element
  // with, so that no two of a wave share one (nor write one's flag) and
  // each sees every earlier neighbour decided; a wave's clusters are
  // decided in parallel.
  std::vector<int> waveOfElement(m.tets.size(), -1);
  std::vector<std::vector<std::size_t>> waves;
  for (std::size_t a = 0; a < active.size(); ++a) {
    int wave = 0;
    for (std::size_t k = elementOffsets[a]; k < elementOffsets[a + 1]; ++k)
      wave = std::max(wave, waveOfElement[elements[k]] + 1);
    for (std::size_t k = elementOffsets[a]; k < elementOffsets[a + 1]; ++k) waveOfElement[elements[k]] = wave;
    if (static_cast<std::size_t>(wave) >= waves.size()) waves.resize(wave + 1);
    waves[wave].push_back(a);
  }
  std::size_t welded = 0;
  for (const std::vector<std::size_t>& wave : waves)
    welded += tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, wave.size()), std::size_t(0),
        [&](const tbb::blocked_range<std::size_t>& r, std::size_t sum) {
          for (std::size_t k = r.begin(); k != r.end(); ++k) sum += decide(wave[k]);
          return sum;
        },
        std::plus<>());
  return welded;
}

}  // namespace

std::size_t repairFlippedElements(PairMesh& m, const DelaunayVoronoi& dv, const RepairOptions& options,
                                  std::size_t* needingRepairLeft, std::vector<std::uint8_t>* needsRepairFlags) {
  std::vector<std::uint8_t> moved, ownFlags;
  std::vector<std::uint8_t>& needsRepairFlag = needsRepairFlags ? *needsRepairFlags : ownFlags;
  // The count before repair comes from the pass that flags the elements
  // needing repair (inverted ones are among them), unless the caller's
  // flags are current; the weld keeps the flags current, so the first
  // round need not test all.
  if (options.flagsAreCurrent && needsRepairFlag.size() != m.tets.size())
    throw std::invalid_argument("pair-mesh repair: current flags must hold one entry per element");
  bool flagsCurrent = options.flagsAreCurrent;
  if (options.countInvertedBefore && !flagsCurrent) {
    flagElementsNeedingRepair(m.nodes, m.tets, needsRepairFlag);
    flagsCurrent = true;
  }
  if (options.countInvertedBefore)
    m.counts.invertedBeforeRepair =
        countElements(m.tets.size(), [&](std::size_t i) { return needsRepairFlag[i] != 0 && isInverted(m, i); });
  if (options.weldCloseNodes)
    m.counts.weldedNodes += weldCloseVoronoiNodes(m, m.spacing / 200, flagsCurrent ? &needsRepairFlag : nullptr);
  std::size_t needingRepair = moveVoronoiNodes(m, dv, options.rounds, moved, needsRepairFlag, flagsCurrent);
  if (needingRepair > 0) {
    std::vector<std::size_t> flagged;  // the negative elements are among them
    for (std::size_t i = 0; i < m.tets.size(); ++i)
      if (needsRepairFlag[i]) flagged.push_back(i);
    // (None kept: the mesh and its flags as they were; the flags follow
    // the splits, a pass over every element less: 6 ms of the lever's.)
    m.counts.splitEdges = splitBoundaryEdges(m, &flagged, &needsRepairFlag);
    if (m.counts.splitEdges > 0) needingRepair = moveVoronoiNodes(m, dv, options.rounds, moved, needsRepairFlag, true);
  }
  // Inverted elements are among those flagged as needing repair: only they are tested.
  std::size_t bad = 0;
  if (needingRepair > 0)
    for (std::size_t i = 0; i < m.tets.size(); ++i) bad += needsRepairFlag[i] && isInverted(m, i) ? 1 : 0;
  if (needingRepairLeft) *needingRepairLeft = needingRepair;
  m.counts.movedNodes = static_cast<std::size_t>(std::count(moved.begin(), moved.end(), 1));
  m.counts.invertedAfterRepair = bad;
  return bad;
}

}  // namespace cadmedial
