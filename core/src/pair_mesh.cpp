#include "cadmedial/pair_mesh.hpp"
#include "pair_mesh_boundary_cells.hpp"
#include "pair_mesh_element_checks.hpp"
#include "pair_mesh_flat_cells.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <stdexcept>

#include "cadmedial/edge_table.hpp"
#include "cadmedial/timer.hpp"

namespace cadmedial {

namespace {

using Kernel = DelaunayVoronoi::Kernel;
using Cell_handle = DelaunayVoronoi::Cell_handle;
using Vertex_handle = DelaunayVoronoi::Vertex_handle;

// Local vertex pairs of the six edges of a cell, and the edge of a pair.
constexpr int kEdgeI[6] = {0, 0, 0, 1, 1, 2};
constexpr int kEdgeJ[6] = {1, 2, 3, 2, 3, 3};
constexpr int kEdgeOf[4][4] = {{-1, 0, 1, 2}, {0, -1, 3, 4}, {1, 3, -1, 5}, {2, 4, 5, -1}};

// What of the inner CAD_MEDIAL axis each kind of medial simplex can belong to.
struct SheetMembership {
  PairTable facetEdges;    // Delaunay edges {p, q} of inner facets
  PairTable voronoiEdges;  // cell pairs that are polygon edges
  std::vector<std::uint8_t> cells;
};

SheetMembership sheetMembership(const MedialComplex* axis, std::size_t cellCount) {
  SheetMembership m;
  m.cells.assign(cellCount, 0);
  if (!axis) return m;
  m.facetEdges.reserve(axis->polygonCount());
  m.voronoiEdges.reserve(axis->polygonVertices.size());
  for (std::size_t p = 0; p < axis->polygonCount(); ++p) {
    if (axis->provenance[p] == PolygonProvenance::DelaunayEdgeFacet)
      m.facetEdges.insert(axis->provenanceSamples[p][0], axis->provenanceSamples[p][1], 1);
    const Index b = axis->polygonOffsets[p], e = axis->polygonOffsets[p + 1];
    for (Index k = b; k < e; ++k) {
      const Index c = axis->vertexCell[axis->polygonVertices[k]];
      const Index d = axis->vertexCell[axis->polygonVertices[k + 1 < e ? k + 1 : b]];
      if (c != kNoIndex && c < cellCount) m.cells[c] = 1;
      if (c != kNoIndex && d != kNoIndex) m.voronoiEdges.insert(c, d, 1);
    }
  }
  return m;
}

class Builder {
 public:
  Builder(const DelaunayVoronoi& dv, const SampleSet& samples, const std::vector<std::uint8_t>& cellInner,
          const MedialComplex* axis)
      : dv_(dv), dt_(dv.triangulation()), inner_(cellInner), spacing_(samples.spacing), sheets_(sheetMembership(axis, dv.cellCount())) {
    if (cellInner.size() != dv.cellCount()) throw std::invalid_argument("pair-mesh: one inner label per cell needed");
    m_.nodes = samples.points;
    m_.sampleNodes = samples.points.size();
    m_.spacing = samples.spacing;
    m_.nodeCell.assign(m_.sampleNodes, kNoIndex);
    m_.boundaryNode.assign(m_.sampleNodes, 1);
    nodeOfCell_.assign(dv.cellCount(), kNoIndex);
    for (Index c = 0; c < dv.cellCount(); ++c)
      if (isInner(c)) {
        nodeOfCell_[c] = static_cast<Index>(m_.nodes.size());
        m_.nodes.push_back(dv.circumcenter(c));
        m_.nodeCell.push_back(c);
        m_.boundaryNode.push_back(0);
        ++m_.counts.innerCells;
      }
  }

  PairMesh build() {
    weldNearlyCoincidentVoronoiNodes();
    if (dv_.dimension() == 3) {
      edgeElements();
      vertexFaceElements();
    }
    return std::move(m_);
  }

 private:
  bool isInner(Index c) const { return !dv_.isInfinite(c) && inner_[c] != 0; }

  void add(PairElementType t, std::array<Index, 4> tet, std::array<Index, 2> medial, std::array<Index, 3> boundary,
           bool onSheets) {
    m_.tets.push_back(tet);
    m_.type.push_back(t);
    m_.medialSimplex.push_back(medial);
    m_.boundarySimplex.push_back(boundary);
    m_.onSheets.push_back(onSheets ? 1 : 0);
  }

  // Face-Vertex (interior edge) or Edge-Edge (boundary edge) elements of every
  // finite Delaunay edge, each edge visited once (a bit per local edge).
  void edgeElements() {
    std::vector<std::uint8_t> done(dv_.cellCount(), 0);
    std::vector<Cell_handle> ring;
    for (Index id = 0; id < dv_.cellCount(); ++id) {
      if (dv_.isInfinite(id)) continue;
      const Cell_handle c = dv_.cell(id);
      for (int e = 0; e < 6; ++e) {
        if (done[id] & (1u << e)) continue;
        const Vertex_handle va = c->vertex(kEdgeI[e]), vb = c->vertex(kEdgeJ[e]);
        ring.clear();
        auto circ = dt_.incident_cells(c, kEdgeI[e], kEdgeJ[e]);
        const auto start = circ;
        do {
          ring.push_back(circ);
          const Index cid = DelaunayVoronoi::cellId(circ);
          done[cid] |= static_cast<std::uint8_t>(1u << kEdgeOf[circ->index(va)][circ->index(vb)]);
          ++circ;
        } while (circ != start);
        edge(va, vb, ring);
      }
    }
  }

  // Turns `ring` (cells around ab) so that it goes positively about a -> b:
  // for an inner (hence finite) cell c of it, the next cell shares c's facet
  // opposite w, and (a, b, w, w') must be positively oriented.
  void orientRing(Vertex_handle va, Vertex_handle vb, std::vector<Cell_handle>& ring) const {
    std::size_t k = 0;
    while (!isInner(DelaunayVoronoi::cellId(ring[k]))) ++k;
    const Cell_handle c = ring[k], next = ring[(k + 1) % ring.size()];
    Vertex_handle w, w2;
    for (int i = 0; i < 4; ++i) {
      const Vertex_handle u = c->vertex(i);
      if (u == va || u == vb) continue;
      if (c->neighbor(i) == next) w = u;
      else w2 = u;
    }
    if (CGAL::orientation(va->point(), vb->point(), w->point(), w2->point()) == CGAL::NEGATIVE)
      std::reverse(ring.begin(), ring.end());
  }

  void edge(Vertex_handle va, Vertex_handle vb, std::vector<Cell_handle>& ring) {
    std::size_t innerCount = 0;
    for (const Cell_handle& r : ring) innerCount += isInner(DelaunayVoronoi::cellId(r)) ? 1 : 0;
    if (innerCount == 0) return;
    orientRing(va, vb, ring);
    const Index a = va->info(), b = vb->info();
    const std::size_t k = ring.size();
    if (innerCount == k) {  // interior edge: two Face-Vertex pyramids
      const bool linked = sheets_.facetEdges.find(a, b) != kNoIndex;
      const std::array<Index, 2> facet{std::min(a, b), std::max(a, b)};
      const Index n0 = node(ring[0]);
      for (std::size_t i = 1; i + 1 < k; ++i) {
        const Index ni = node(ring[i]), nj = node(ring[i + 1]);
        add(PairElementType::FaceVertex, {a, n0, ni, nj}, facet, {a, kNoIndex, kNoIndex}, linked);
        add(PairElementType::FaceVertex, {b, n0, nj, ni}, facet, {b, kNoIndex, kNoIndex}, linked);
        m_.counts.faceVertex += 2;
      }
      return;
    }
    for (std::size_t i = 0; i < k; ++i) {  // boundary edge: Edge-Edge per inner Voronoi edge
      const Index ci = DelaunayVoronoi::cellId(ring[i]), cj = DelaunayVoronoi::cellId(ring[(i + 1) % k]);
      if (!isInner(ci) || !isInner(cj)) continue;
      const bool linked = sheets_.voronoiEdges.find(ci, cj) != kNoIndex;
      add(PairElementType::EdgeEdge, {a, b, nodeOfCell_[ci], nodeOfCell_[cj]}, {ci, cj}, {a, b, kNoIndex}, linked);
      ++m_.counts.edgeEdge;
    }
  }

  // Nearly cospherical samples (grids on planar faces, parameter grids on
  // tori) give Voronoi vertices that coincide in exact arithmetic but differ
  // by rounding; the elements between them are slivers of either sign, and
  // their iso-surface cuts cross. Such nodes get one position (the first
  // seen), within 1e-8 of the samples' extent, which makes those elements
  // exactly flat instead.
  void weldNearlyCoincidentVoronoiNodes() {
    if (m_.nodes.size() <= m_.sampleNodes) return;
    Vec3 lo = m_.nodes[0], hi = m_.nodes[0];
    for (std::size_t i = 0; i < m_.sampleNodes; ++i)
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], m_.nodes[i][k]), hi[k] = std::max(hi[k], m_.nodes[i][k]);
    const double extent = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                    (hi[2] - lo[2]) * (hi[2] - lo[2]));
    const double tolerance = 1e-8 * extent;
    if (!(tolerance > 0)) return;
    auto cellOf = [&](const Vec3& p, int k) { return static_cast<std::int64_t>(std::floor(p[k] / tolerance)); };
    auto key = [](std::int64_t x, std::int64_t y, std::int64_t z) {
      return (static_cast<std::uint64_t>(x) * 73856093u) ^ (static_cast<std::uint64_t>(y) * 19349663u) ^
             (static_cast<std::uint64_t>(z) * 83492791u);
    };
    std::unordered_multimap<std::uint64_t, Index> grid;
    grid.reserve(m_.nodes.size() - m_.sampleNodes);
    for (Index n = static_cast<Index>(m_.sampleNodes); n < m_.nodes.size(); ++n) {
      Vec3& p = m_.nodes[n];
      const std::int64_t cx = cellOf(p, 0), cy = cellOf(p, 1), cz = cellOf(p, 2);
      bool welded = false;
      for (int dx = -1; dx <= 1 && !welded; ++dx)
        for (int dy = -1; dy <= 1 && !welded; ++dy)
          for (int dz = -1; dz <= 1 && !welded; ++dz) {
            const auto range = grid.equal_range(key(cx + dx, cy + dy, cz + dz));
            for (auto it = range.first; it != range.second; ++it) {
              const Vec3& q = m_.nodes[it->second];
              if (std::abs(q[0] - p[0]) <= tolerance && std::abs(q[1] - p[1]) <= tolerance &&
                  std::abs(q[2] - p[2]) <= tolerance) {
                if (q != p) ++m_.counts.weldedNodes;
                p = q;
                welded = true;
                break;
              }
            }
          }
      if (!welded) grid.emplace(key(cx, cy, cz), n);
    }
  }

  Index node(Cell_handle c) const { return nodeOfCell_[DelaunayVoronoi::cellId(c)]; }

  // Vertex-Face: every facet of an inner cell whose neighbour is outer.
  void vertexFaceElements() {
    for (Index id = 0; id < dv_.cellCount(); ++id) {
      if (!isInner(id)) continue;
      const Cell_handle c = dv_.cell(id);
      for (int i = 0; i < 4; ++i) {
        if (isInner(DelaunayVoronoi::cellId(c->neighbor(i)))) continue;
        Vertex_handle x = c->vertex((i + 1) & 3), y = c->vertex((i + 2) & 3), z = c->vertex((i + 3) & 3);
        // Outward: the cell's own vertex i on the negative side.
        if (CGAL::orientation(x->point(), y->point(), z->point(), c->vertex(i)->point()) == CGAL::POSITIVE)
          std::swap(y, z);
        const std::array<Index, 3> tri{x->info(), y->info(), z->info()};
        m_.boundaryTriangles.push_back(tri);
        add(PairElementType::VertexFace, {nodeOfCell_[id], tri[0], tri[1], tri[2]}, {id, kNoIndex}, tri,
            sheets_.cells[id] != 0);
        ++m_.counts.vertexFace;
      }
    }
    m_.counts.boundaryTriangles = m_.boundaryTriangles.size();
  }

  const DelaunayVoronoi& dv_;
  const DelaunayVoronoi::Triangulation& dt_;
  const std::vector<std::uint8_t>& inner_;
  double spacing_;
  SheetMembership sheets_;
  std::vector<Index> nodeOfCell_;
  PairMesh m_;
};

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
  PairMesh mesh = Builder(dv, samples, inner, innerAxis).build();
  mesh.counts.relabelledFlatCells = relabelled;
  mesh.seconds = watch.seconds();
  watch.restart();
  if (repair) {
    std::size_t inverted = repairFlippedElements(mesh, dv);
    // Last resort, up to three times: the boundary cells whose Voronoi nodes
    // the repair could not place go outer, and the mesh is rebuilt (nodes
    // where the repair left them; its build time counts as repair) and
    // repaired. Kept only when fewer elements stay inverted and no more need
    // repair (flat ones included), and when the cells taken out hold at most
    // 1e-3 of the enclosed volume.
    const double budget = inverted > 0 ? 1e-3 * std::abs(checkPairMesh(mesh).enclosedVolume) : 0;
    double removed = 0;
    for (int pass = 0; pass < 3 && inverted > 0; ++pass) {
      const std::vector<Index> cells = boundaryCellsOfInvertedElements(dv, inner, mesh);
      if (cells.empty()) break;
      double volume = 0;
      for (Index c : cells) volume += std::abs(dv.triangulation().tetrahedron(dv.cell(c)).volume());
      if (removed + volume > budget) break;
      std::vector<std::uint8_t> trialInner = inner;
      for (Index c : cells) trialInner[c] = 0;
      PairMesh trial = Builder(dv, samples, trialInner, innerAxis).build();
      keepRepairedPositions(mesh, trial);
      const std::size_t trialInverted = repairFlippedElements(trial, dv);
      if (trialInverted >= inverted ||
          countElementsNeedingRepair(trial.nodes, trial.tets) > countElementsNeedingRepair(mesh.nodes, mesh.tets))
        break;
      // Counts of the kept mesh, except those of the whole history: inverted
      // before any repair, relabelled cells, and node moves and polygon
      // re-triangulations summed over the passes kept.
      PairMeshCounts& c = trial.counts;
      c.invertedBeforeRepair = mesh.counts.invertedBeforeRepair;
      c.relabelledFlatCells = relabelled;
      c.relabelledBoundaryCells = mesh.counts.relabelledBoundaryCells + cells.size();
      c.movedNodes += mesh.counts.movedNodes;
      c.retriangulatedPolygons += mesh.counts.retriangulatedPolygons;
      trial.seconds = mesh.seconds;
      mesh = std::move(trial);
      inner = std::move(trialInner);
      inverted = trialInverted;
      removed += volume;
    }
  } else {
    std::size_t negative = 0;
    for (std::size_t i = 0; i < mesh.size(); ++i) negative += isInverted(mesh, i) ? 1 : 0;
    mesh.counts.invertedBeforeRepair = mesh.counts.invertedAfterRepair = negative;
  }
  mesh.repairSeconds = watch.seconds();
  return mesh;
}

}  // namespace cadmedial
