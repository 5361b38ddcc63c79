// Why: cospherical samples have one Voronoi vertex, but the Delaunay
// triangulation splits them into several cells whose circumcenters agree
// only up to rounding (1e-13 apart), and the complex gives each cell its
// own vertex. Four cocircular samples (two mirror pairs: the legs of
// consecutive triplets, knife-edge rungs) make two such points P and Q; the
// sheet facets of the two pairs both run from P to Q, but through different
// cells' vertices, so the sheet is slit there and every slit is a cycle in
// β1 (an 8° wedge with rungs: β1 123, 8,242 coincident vertices). Welding
// vertices closer than a tolerance far below the sampling glues the slits.
// Two rules keep the weld from doing harm where the coincident vertices are
// not a slit (below): it drops no polygon that alone holds what it spans,
// and it keeps no group of welds that adds cycles.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "cadmedial/edge_table.hpp"
#include "cadmedial/polygon_complex.hpp"
#include "cadmedial/union_find.hpp"

namespace cadmedial {

namespace {

std::size_t distinctCount(std::vector<std::uint64_t>& keys) {
  std::sort(keys.begin(), keys.end());
  return static_cast<std::size_t>(std::unique(keys.begin(), keys.end()) - keys.begin());
}

// Whether `cycle` has at least three distinct corners (distinctCount >= 3
// without a copy and a sort per polygon).
bool hasThreeDistinct(const std::vector<Index>& cycle) {
  if (cycle.size() < 3) return false;
  const Index a = cycle[0];
  Index b = kNoIndex;
  for (Index v : cycle) {
    if (v == a || v == b) continue;
    if (b != kNoIndex) return true;
    b = v;
  }
  return false;
}

// A welded polygon's corners as one cycle, without a corner repeating the
// one before it (a zero-length edge) or the first.
void weldedCycle(const MedialComplex& mc, std::size_t p, const std::vector<Index>& into, std::vector<Index>& cycle) {
  cycle.clear();
  for (Index k = mc.polygonOffsets[p]; k < mc.polygonOffsets[p + 1]; ++k) {
    const Index v = into[mc.polygonVertices[k]];
    if (cycle.empty() || cycle.back() != v) cycle.push_back(v);
  }
  while (cycle.size() > 1 && cycle.back() == cycle.front()) cycle.pop_back();
}

// The same cycle whatever its first corner and direction: the smallest of
// its rotations and their reversals. Two polygons the weld makes equal span
// one surface twice, a pillow: kept both, they would enclose a void (β2)
// that is not there (box_fillet_variable: two Voronoi triangles that share
// an edge and whose third corners coincide).
std::vector<Index> canonicalCycle(const std::vector<Index>& cycle) {
  const std::size_t n = cycle.size();
  std::vector<Index> best = cycle, candidate(n);
  for (std::size_t start = 0; start < n; ++start)
    for (const bool forward : {true, false}) {
      for (std::size_t i = 0; i < n; ++i) candidate[i] = cycle[forward ? (start + i) % n : (start + n - i) % n];
      if (candidate < best) best = candidate;
    }
  return best;
}

// A polygon the weld shrinks below three distinct corners spans a point
// or a segment: a degenerate facet (the diagonal of four cocircular
// samples, whose cells share two circumcenters) goes, since the point or
// segment stays in the complex through other polygons. Where nothing
// else holds it (a facet along the torus's core circle, the only link
// there) dropping it broke loops and components (torus β1 1 -> 0,
// fillet_chamfer_block β0 1 -> 8): its clusters then stay unwelded, and
// as that can take a segment out of other polygons, until nothing changes.
// `into` maps each vertex to the vertex it is welded into; refused clusters
// map to themselves.
void refuseCollapsesNothingHolds(const MedialComplex& mc, std::vector<Index>& into) {
  const std::size_t nv = mc.vertices.size();
  std::vector<std::uint8_t> refused(nv, 0);  // per cluster's first vertex
  std::vector<std::uint8_t> collapses(mc.polygonCount(), 0);
  auto mapped = [&](Index v) { return refused[into[v]] ? v : into[v]; };
  std::vector<Index> corners;
  auto distinctCorners = [&](std::size_t p) {
    corners.clear();
    for (Index k = mc.polygonOffsets[p]; k < mc.polygonOffsets[p + 1]; ++k) corners.push_back(mapped(mc.polygonVertices[k]));
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    return corners.size();
  };
  std::vector<std::uint8_t> spanEnd(nv, 0);
  for (bool changed = true; changed;) {
    changed = false;
    // Which polygons collapse, and the ends of the segments they span: only
    // edges between two such ends are ever looked up below (a table of every
    // edge was 0.37 s of the box's weld at 347 k samples).
    std::fill(spanEnd.begin(), spanEnd.end(), 0);
    for (std::size_t p = 0; p < mc.polygonCount(); ++p) {
      collapses[p] = distinctCorners(p) < 3;
      if (collapses[p] && corners.size() == 2) spanEnd[corners[0]] = spanEnd[corners[1]] = 1;
    }
    // What the polygons that keep three corners hold: their vertices and edges.
    std::vector<std::uint8_t> held(nv, 0);
    PairTable heldEdges;
    for (std::size_t p = 0; p < mc.polygonCount(); ++p) {
      if (collapses[p]) continue;
      const Index b = mc.polygonOffsets[p], e = mc.polygonOffsets[p + 1];
      for (Index k = b; k < e; ++k) {
        const Index u = mapped(mc.polygonVertices[k]), w = mapped(mc.polygonVertices[k + 1 < e ? k + 1 : b]);
        held[u] = 1;
        if (u != w && spanEnd[u] && spanEnd[w]) heldEdges.insert(std::min(u, w), std::max(u, w), 1);
      }
    }
    for (std::size_t p = 0; p < mc.polygonCount(); ++p) {
      if (!collapses[p]) continue;
      distinctCorners(p);
      const bool spanHeld = corners.size() == 2 ? heldEdges.find(corners[0], corners[1]) != kNoIndex
                                                : corners.size() == 1 && held[corners[0]];
      if (spanHeld) continue;
      for (Index k = mc.polygonOffsets[p]; k < mc.polygonOffsets[p + 1]; ++k) {
        std::uint8_t& r = refused[into[mc.polygonVertices[k]]];
        changed = changed || r == 0;
        r = 1;
      }
    }
  }
  for (Index v = 0; v < nv; ++v) into[v] = mapped(v);
}

// Welding identifies points: where the polygons around coincident vertices
// are not glued along edges by it as well (the centre of a corner sphere,
// reached by fillet centre curves and fringe pieces through different
// cells), it pinches the complex and adds cycles (a box with filleted
// edges: β1 0 -> 9). Clusters joined through the polygons that touch them
// form groups; a group's weld is kept only when it adds no cycle: Δβ1 =
// Δβ0 − Δχ <= 0 (β2 taken as unchanged: polygons the weld makes equal
// count once, as the weld keeps one of them), with χ counted over the
// vertices, edges and polygons the weld changes and β0 over the whole
// complex. `into` maps each vertex to the vertex it is welded into;
// refused groups map to themselves. Needs refuseCollapsesNothingHolds
// first: then what a dropped polygon spans is held by a polygon of the
// same group, so no vertex or connection outside the counts is lost, and
// groups (disjoint in polygons, edges and vertices) add up.
void refuseWeldsThatAddCycles(const MedialComplex& mc, std::vector<Index>& into) {
  const std::size_t nv = mc.vertices.size(), nf = mc.polygonCount();
  std::vector<Index> members(nv, 0);
  for (Index v = 0; v < nv; ++v) ++members[into[v]];
  auto welds = [&](Index v) { return members[into[v]] > 1; };
  UnionFind groups(nv), components(nv);
  std::vector<std::uint8_t> touches(nf, 0);
  for (std::size_t p = 0; p < nf; ++p) {
    const Index b = mc.polygonOffsets[p], e = mc.polygonOffsets[p + 1];
    Index first = kNoIndex;
    for (Index k = b; k < e; ++k) {
      const Index v = mc.polygonVertices[k];
      components.unite(mc.polygonVertices[b], v);
      if (!welds(v)) continue;
      touches[p] = 1;
      if (first == kNoIndex) first = into[v];
      groups.unite(first, into[v]);
    }
  }
  // Per group (by its root): the polygons touching it.
  std::vector<std::vector<Index>> polygonsOf;
  std::vector<Index> slot(nv, kNoIndex);
  auto groupOf = [&](Index v) {
    const Index r = groups.find(into[v]);
    if (slot[r] == kNoIndex) {
      slot[r] = static_cast<Index>(polygonsOf.size());
      polygonsOf.emplace_back();
    }
    return slot[r];
  };
  for (std::size_t p = 0; p < nf; ++p) {
    if (!touches[p]) continue;
    for (Index k = mc.polygonOffsets[p]; k < mc.polygonOffsets[p + 1]; ++k)
      if (welds(mc.polygonVertices[k])) {
        polygonsOf[groupOf(mc.polygonVertices[k])].push_back(static_cast<Index>(p));
        break;
      }
  }
  std::vector<std::uint64_t> before, after, corners;
  std::vector<Index> groupVertices, cycle;
  std::vector<std::vector<Index>> keptCycles;
  for (const std::vector<Index>& polygons : polygonsOf) {
    before.clear();
    after.clear();
    groupVertices.clear();
    keptCycles.clear();
    for (Index p : polygons) {
      const Index b = mc.polygonOffsets[p], e = mc.polygonOffsets[p + 1];
      weldedCycle(mc, p, into, cycle);
      corners.assign(cycle.begin(), cycle.end());
      const bool collapses = distinctCount(corners) < 3;
      if (!collapses) keptCycles.push_back(canonicalCycle(cycle));
      for (Index k = b; k < e; ++k) {
        const Index u = mc.polygonVertices[k], w = mc.polygonVertices[k + 1 < e ? k + 1 : b];
        if (welds(u)) groupVertices.push_back(u);
        if (!welds(u) && !welds(w)) continue;
        before.push_back(PairTable::key(u, w));
        if (!collapses && into[u] != into[w]) after.push_back(PairTable::key(into[u], into[w]));
      }
    }
    std::sort(groupVertices.begin(), groupVertices.end());
    groupVertices.erase(std::unique(groupVertices.begin(), groupVertices.end()), groupVertices.end());
    long long verticesAfter = 0;
    for (Index v : groupVertices) verticesAfter += into[v] == v ? 1 : 0;
    const long long dV = verticesAfter - static_cast<long long>(groupVertices.size());
    const long long dE = static_cast<long long>(distinctCount(after)) - static_cast<long long>(distinctCount(before));
    // A polygon the weld makes equal to another goes (a pillow, above).
    std::sort(keptCycles.begin(), keptCycles.end());
    const auto keptPolygons = std::unique(keptCycles.begin(), keptCycles.end()) - keptCycles.begin();
    const long long dF = static_cast<long long>(keptPolygons) - static_cast<long long>(polygons.size());
    // Components the weld joins (on a copy of the roots involved).
    std::vector<std::pair<Index, Index>> joins;
    for (Index v : groupVertices)
      if (into[v] != v) joins.push_back({components.find(v), components.find(into[v])});
    std::vector<Index> roots;
    for (const auto& [a, c] : joins) roots.insert(roots.end(), {a, c});
    std::sort(roots.begin(), roots.end());
    roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
    UnionFind local(roots.size());
    auto localOf = [&](Index r) { return static_cast<Index>(std::lower_bound(roots.begin(), roots.end(), r) - roots.begin()); };
    long long dB0 = 0;
    for (const auto& [a, c] : joins) dB0 -= local.unite(localOf(a), localOf(c)) ? 1 : 0;
    const long long dB1 = dB0 - (dV - dE + dF);
    if (dB1 <= 0) {
      for (const auto& [a, c] : joins) components.unite(a, c);
    } else {
      for (Index v : groupVertices) into[v] = v;
    }
  }
}

}  // namespace

std::size_t weldCoincidentVertices(MedialComplex& mc, double tolerance, std::size_t* facetsDropped) {
  if (facetsDropped) *facetsDropped = 0;
  const std::size_t nv = mc.vertices.size();
  if (!(tolerance > 0) || nv == 0) return 0;
  // Voronoi vertices only (samples are distinct points), sorted by their
  // projection on a fixed direction u: a vertex's partners within the
  // tolerance follow it within the tolerance in that order, since
  // |u.(p - q)| <= |p - q|. u is skew to the axes and their diagonals: CAD
  // parts line their Voronoi vertices up along axes (a cylinder's along its
  // axis, all with one x), and sorted by x that run was one window: 27.5 M
  // pair tests and a third of the complex stage at 119 k vertices. The pairs
  // found, and so the clusters, do not depend on u.
  constexpr double ux = 0.8017837257372732, uy = 0.5345224838248488, uz = 0.2672612419124244;  // (3, 2, 1) / sqrt(14)
  struct Projected {
    double along;
    Index vertex;
    bool operator<(const Projected& o) const { return along < o.along || (along == o.along && vertex < o.vertex); }
  };
  std::vector<Projected> order;  // the key beside the index: a sort that reads no other array
  order.reserve(nv);
  for (Index v = 0; v < nv; ++v) {
    const Vec3& p = mc.vertices[v];
    // Samples are distinct points; a non-finite vertex is near nothing (and
    // would break the sort's order).
    if (mc.vertexCell[v] == kNoIndex || !std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) continue;
    order.push_back({ux * p[0] + uy * p[1] + uz * p[2], v});
  }
  // (along, vertex) is a strict order, so the parallel sort gives the one order.
  tbb::parallel_sort(order.begin(), order.end());
  // Pairs are joined as they are found: all Voronoi vertices of a sphere's
  // samples are one point, and storing their pairs (k^2 / 2) would not fit.
  UnionFind clusters(nv);
  const double limit = tolerance * tolerance;
  constexpr double kRounding = 16 * std::numeric_limits<double>::epsilon();  // of a projection, relative to |p|_1
  for (std::size_t i = 0; i < order.size(); ++i) {
    const Vec3& p = mc.vertices[order[i].vertex];
    const double window = tolerance + kRounding * (std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]) + 4 * tolerance);
    for (std::size_t j = i + 1; j < order.size() && order[j].along - order[i].along <= window; ++j) {
      const Vec3& q = mc.vertices[order[j].vertex];
      const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
      if (dx * dx + dy * dy + dz * dz <= limit) clusters.unite(order[i].vertex, order[j].vertex);
    }
  }
  std::vector<Index> into(nv, kNoIndex);  // per root, then per vertex: the smallest index of its cluster
  for (Index v = 0; v < nv; ++v) {
    Index& first = into[clusters.find(v)];
    if (first == kNoIndex) first = v;
  }
  for (Index v = 0; v < nv; ++v) into[v] = into[clusters.find(v)];
  refuseCollapsesNothingHolds(mc, into);
  refuseWeldsThatAddCycles(mc, into);
  std::size_t welded = 0;
  for (Index v = 0; v < nv; ++v) welded += into[v] != v ? 1 : 0;
  if (welded == 0) return 0;

  // The cells whose vertex goes, with the cell of the vertex kept (the
  // pair-mesh's sheet flags are per cell).
  for (Index v = 0; v < nv; ++v)
    if (into[v] != v) mc.weldedCells.push_back({mc.vertexCell[v], mc.vertexCell[into[v]]});
  // Polygons on the kept vertices: a corner repeating the one before it
  // goes (a zero-length edge), and so does a polygon left with fewer than
  // three distinct corners (one whose span other polygons hold, above; A B
  // A B counts as two), and one equal to an earlier polygon (a pillow:
  // only polygons on a welded point can become equal).
  std::vector<Index> members(nv, 0);
  for (Index v = 0; v < nv; ++v) ++members[into[v]];
  const std::size_t np = mc.polygonCount();
  std::vector<std::uint8_t> keep(np, 1);
  std::vector<Index> offsets(np + 1, 0);  // first the new corner counts, then their sums
  // Polygons in parallel blocks; per block the Voronoi facets it drops and
  // its polygons on a welded point (canonical cycle, polygon).
  struct Block {
    std::size_t facetsDropped = 0;
    std::vector<std::pair<std::vector<Index>, Index>> onWeldedPoints;
  };
  constexpr std::size_t kBlock = 16384;
  std::vector<Block> blocks((np + kBlock - 1) / kBlock);
  tbb::parallel_for(std::size_t(0), blocks.size(), [&](std::size_t b) {
    std::vector<Index> cycle;
    for (std::size_t p = b * kBlock; p < std::min(np, (b + 1) * kBlock); ++p) {
      weldedCycle(mc, p, into, cycle);
      offsets[p + 1] = static_cast<Index>(cycle.size());
      if (!hasThreeDistinct(cycle)) {
        keep[p] = 0;
        if (mc.provenance[p] == PolygonProvenance::DelaunayEdgeFacet) ++blocks[b].facetsDropped;
      } else if (std::any_of(cycle.begin(), cycle.end(), [&](Index v) { return members[v] > 1; })) {
        blocks[b].onWeldedPoints.push_back({canonicalCycle(cycle), static_cast<Index>(p)});
      }
    }
  });
  for (std::size_t p = 0; p < np; ++p) offsets[p + 1] += offsets[p];
  // Each polygon's cycle is made again here: cheaper than keeping every
  // block's corners until the sums are known.
  std::vector<Index> vertices(offsets[np]);
  tbb::parallel_for(std::size_t(0), blocks.size(), [&](std::size_t b) {
    std::vector<Index> cycle;
    for (std::size_t p = b * kBlock; p < std::min(np, (b + 1) * kBlock); ++p) {
      weldedCycle(mc, p, into, cycle);
      std::copy(cycle.begin(), cycle.end(), vertices.begin() + offsets[p]);
    }
  });
  std::vector<std::pair<std::vector<Index>, Index>> onWeldedPoints;
  for (Block& block : blocks) {
    if (facetsDropped) *facetsDropped += block.facetsDropped;
    for (auto& entry : block.onWeldedPoints) onWeldedPoints.push_back(std::move(entry));
  }
  std::sort(onWeldedPoints.begin(), onWeldedPoints.end());
  for (std::size_t i = 1; i < onWeldedPoints.size(); ++i)
    if (onWeldedPoints[i].first == onWeldedPoints[i - 1].first) {
      const Index p = onWeldedPoints[i].second;
      keep[p] = 0;
      if (facetsDropped && mc.provenance[p] == PolygonProvenance::DelaunayEdgeFacet) ++*facetsDropped;
    }
  mc.polygonVertices = std::move(vertices);
  mc.polygonOffsets = std::move(offsets);
  keepPolygons(mc, keep);  // also drops the vertices no polygon uses (the welded ones)
  return welded;
}

}  // namespace cadmedial
