#include "pair_mesh_builder.hpp"
#include "pair_mesh_edit.hpp"
#include "pair_mesh_element_checks.hpp"
#include "point_box.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <unordered_map>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

namespace cadmedial {

namespace {

// Local vertex pairs of the six edges of a cell, and the edge of a pair.
constexpr int kEdgeI[6] = {0, 0, 0, 1, 1, 2};
constexpr int kEdgeJ[6] = {1, 2, 3, 2, 3, 3};
constexpr int kEdgeOf[4][4] = {{-1, 0, 1, 2}, {0, -1, 3, 4}, {1, 3, -1, 5}, {2, 4, 5, -1}};

// The samples of a cell's facet opposite its local vertex `opposite`, sorted.
std::array<Index, 3> facetSamples(const DelaunayVoronoi::Cell_handle& c, int opposite) {
  std::array<Index, 3> corners{};
  for (int u = 0, k = 0; u < 4; ++u)
    if (u != opposite) corners[k++] = c->vertex(u)->info();
  std::sort(corners.begin(), corners.end());
  return corners;
}

}  // namespace

PairMeshBuilder::PairMeshBuilder(const DelaunayVoronoi& dv, const SampleSet& samples, const MedialComplex* axis)
    : dv_(dv), dt_(dv.triangulation()), samples_(samples) {
  weldTolerance_ = 1e-8 * boxOf(samples.points.data(), samples.points.data() + samples.points.size()).diagonal();
  sheetCells_.assign(dv.cellCount(), 0);
  sheetFacets_.assign(dv.cellCount(), 0);
  if (!axis) return;
  // A vertex the axis welded stands for several cells (coincident
  // circumcenters): each of them is on the sheets, and so is a Voronoi edge
  // between any of the cells of two consecutive corners, or of one corner
  // (the zero-length edges the weld dropped).
  // Per kept cell, the cells welded into it: a run of `welded` (sorted by
  // the kept cell) that firstWelded points at, so that a polygon corner's
  // lookup is an array read.
  std::vector<std::array<Index, 2>> welded = axis->weldedCells;  // {welded, kept}
  std::sort(welded.begin(), welded.end(),
            [](const std::array<Index, 2>& a, const std::array<Index, 2>& b) { return a[1] < b[1]; });
  std::vector<Index> firstWelded(dv.cellCount(), kNoIndex);
  for (std::size_t k = welded.size(); k-- > 0;)
    if (welded[k][1] < firstWelded.size()) firstWelded[welded[k][1]] = static_cast<Index>(k);
  auto forEachCell = [&](Index c, auto&& f) {
    if (c >= dv.cellCount()) return;  // (kNoIndex: a sample vertex)
    f(c);
    for (Index k = firstWelded[c]; k != kNoIndex && k < welded.size() && welded[k][1] == c; ++k)
      if (welded[k][0] < dv.cellCount()) f(welded[k][0]);
  };
  // Polygons are marked in parallel: bits are set with atomic ORs, so the
  // masks do not depend on the order (GCC/Clang builtins on the plain bytes:
  // C++17 has no atomic_ref, and the plain reads come after the join).
  auto markVoronoiEdge = [&](Index x, Index y) {
    if (x == y || x >= dv.cellCount() || y >= dv.cellCount()) return;
    for (int i = 0; i < 4; ++i) {
      if (dv.cellNeighbor(x, i) == y)
        __atomic_fetch_or(&sheetFacets_[x], static_cast<std::uint8_t>(1u << i), __ATOMIC_RELAXED);
      if (dv.cellNeighbor(y, i) == x)
        __atomic_fetch_or(&sheetFacets_[y], static_cast<std::uint8_t>(1u << i), __ATOMIC_RELAXED);
    }
  };
  for (std::size_t k = 0; k < welded.size();) {
    std::vector<Index> cells;
    const Index kept = welded[k][1];
    for (; k < welded.size() && welded[k][1] == kept; ++k) cells.push_back(welded[k][0]);
    cells.push_back(kept);
    for (std::size_t i = 0; i < cells.size(); ++i)
      for (std::size_t j = i + 1; j < cells.size(); ++j) markVoronoiEdge(cells[i], cells[j]);
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, axis->polygonCount()), [&](const auto& range) {
    for (std::size_t p = range.begin(); p != range.end(); ++p) {
      const Index b = axis->polygonOffsets[p], e = axis->polygonOffsets[p + 1];
      for (Index k = b; k < e; ++k) {
        const Index c = axis->vertexCell[axis->polygonVertices[k]];
        const Index d = axis->vertexCell[axis->polygonVertices[k + 1 < e ? k + 1 : b]];
        forEachCell(c, [&](Index x) {
          __atomic_store_n(&sheetCells_[x], std::uint8_t{1}, __ATOMIC_RELAXED);
          forEachCell(d, [&](Index y) { markVoronoiEdge(x, y); });
        });
      }
    }
  });
  sheetFacetEdges_.reserve(axis->polygonCount());
  for (std::size_t p = 0; p < axis->polygonCount(); ++p)
    if (axis->provenance[p] == PolygonProvenance::DelaunayEdgeFacet)
      sheetFacetEdges_.insert(axis->provenanceSamples[p][0], axis->provenanceSamples[p][1], 1);
}

PairMesh PairMeshBuilder::build(const std::vector<std::uint8_t>& inner) {
  if (inner.size() != dv_.cellCount()) throw std::invalid_argument("pair-mesh: one inner label per cell needed");
  PairMesh m;
  inner_ = &inner;
  m_ = &m;
  m.nodes = samples_.points;
  m.sampleNodes = samples_.points.size();
  m.spacing = samples_.spacing;
  m.nodeCell.assign(m.sampleNodes, kNoIndex);
  m.boundaryNode.assign(m.sampleNodes, 1);
  nodeOfCell_.assign(dv_.cellCount(), kNoIndex);
  for (Index c = 0; c < dv_.cellCount(); ++c)
    if (isInner(c)) {
      nodeOfCell_[c] = static_cast<Index>(m.nodes.size());
      m.nodes.push_back(dv_.circumcenter(c));
      m.nodeCell.push_back(c);
      m.boundaryNode.push_back(0);
      ++m.counts.innerCells;
    }
  weldNearlyCoincidentVoronoiNodes();
  if (dv_.dimension() == 3) elements();
  m_ = nullptr;
  inner_ = nullptr;
  return m;
}

bool PairMeshBuilder::relabel(PairMesh& mesh, const std::vector<std::uint8_t>& after, const std::vector<Index>& cells,
                              std::vector<std::uint8_t>* needsRepairFlags) {
  if (after.size() != dv_.cellCount()) throw std::invalid_argument("pair-mesh: one inner label per cell needed");
  if (needsRepairFlags && needsRepairFlags->size() != mesh.size())
    throw std::invalid_argument("pair-mesh: one repair flag per element needed");
  if (cells.empty() || dv_.dimension() != 3) return true;
  // Inner before: the cells with a Voronoi node in the mesh.
  std::vector<Index> nodeBefore(dv_.cellCount(), kNoIndex);
  for (Index n = 0; n < mesh.nodes.size(); ++n)
    if (mesh.nodeCell[n] != kNoIndex) nodeBefore[mesh.nodeCell[n]] = n;
  auto innerBefore = [&](Index c) { return nodeBefore[c] != kNoIndex; };
  std::vector<std::uint8_t> gone(dv_.cellCount(), 0), added(dv_.cellCount(), 0);
  for (Index c : cells) {
    if (c >= dv_.cellCount() || dv_.isInfinite(c) || innerBefore(c) == isInnerIn(after, c) || gone[c] || added[c])
      throw std::invalid_argument("pair-mesh: relabelled cells must be finite, listed once, and change side");
    (innerBefore(c) ? gone : added)[c] = 1;
  }
  for (Index c = 0; c < dv_.cellCount(); ++c)
    if (!gone[c] && !added[c] && innerBefore(c) != isInnerIn(after, c))
      throw std::invalid_argument("pair-mesh: only the relabelled cells may change side");
  // The Delaunay edges of the cells (sample pairs), each once, with a cell
  // and local edge to circulate from.
  PairTable edges;
  edges.reserve(6 * cells.size());
  std::vector<std::pair<Index, int>> edgeStarts;
  for (Index c : cells)
    for (int e = 0; e < 6; ++e) {
      const Index a = dv_.cell(c)->vertex(kEdgeI[e])->info(), b = dv_.cell(c)->vertex(kEdgeJ[e])->info();
      const Index id = static_cast<Index>(edgeStarts.size());
      if (edges.insert(a, b, id) == id) edgeStarts.push_back({c, e});
    }
  // A split edge (a -> m -> b, by a repair) among them is undone: its
  // Edge-Edge halves and the Vertex-Face polygons through m go, the boundary
  // facets on ab of cells that stay inner get their one Vertex-Face element
  // back, and so does ab its Edge-Edge elements. A restored facet with a
  // split on another of its edges has that split undone too (the repair may
  // split them again). The sample edge of a split node: the samples reached
  // through the ends of its Edge-Edge halves; an edge split twice cannot be
  // undone here, and then the mesh is left alone for the caller to rebuild.
  std::unordered_map<Index, std::vector<Index>> splitEnds;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    if (mesh.type[i] != PairElementType::EdgeEdge) continue;
    const Index p = mesh.tets[i][0], q = mesh.tets[i][1];
    if (!mesh.isSampleNode(p)) splitEnds[p].push_back(q);
    if (!mesh.isSampleNode(q)) splitEnds[q].push_back(p);
  }
  struct Split {
    std::array<Index, 2> edge;  // samples
    bool once;                  // not split again
  };
  std::unordered_map<Index, Split> splits;
  PairTable splitNodeOfEdge;
  splitNodeOfEdge.reserve(splitEnds.size());
  std::vector<Index> toUndo;
  for (const auto& [split, ends] : splitEnds) {
    std::vector<Index> stack{split}, seen{split}, samples;
    while (!stack.empty()) {
      const Index s = stack.back();
      stack.pop_back();
      const auto it = splitEnds.find(s);
      if (it == splitEnds.end()) return false;
      for (Index u : it->second) {
        if (std::find(seen.begin(), seen.end(), u) != seen.end()) continue;
        seen.push_back(u);
        if (mesh.isSampleNode(u)) samples.push_back(u);
        else stack.push_back(u);
      }
    }
    if (samples.size() != 2) return false;
    splits[split] = {{samples[0], samples[1]}, seen.size() == 3};
    splitNodeOfEdge.insert(samples[0], samples[1], split);
    if (edges.find(samples[0], samples[1]) != kNoIndex) toUndo.push_back(split);
  }
  std::vector<std::uint8_t> undoneNode(mesh.nodes.size(), 0);
  std::vector<std::pair<Index, int>> restoredFacets;  // (cell, local vertex opposite)
  // Per cell that stays inner: the boundary facets whose Vertex-Face
  // elements go (restored ones, and those an added cell now covers).
  std::unordered_map<Index, std::vector<std::array<Index, 3>>> replacedFacets;
  std::vector<std::tuple<Cell_handle, int, int>> restoredEdges;  // undone edges that are not the cells' own
  std::vector<Cell_handle> ring;
  for (std::size_t next = 0; next < toUndo.size(); ++next) {
    const Index split = toUndo[next];
    if (undoneNode[split]) continue;
    const Split& info = splits.at(split);
    if (!info.once) return false;
    undoneNode[split] = 1;
    Cell_handle start;
    int i = 0, j = 0;
    if (!dt_.is_edge(dv_.vertex(info.edge[0]), dv_.vertex(info.edge[1]), start, i, j)) return false;
    if (edges.find(info.edge[0], info.edge[1]) == kNoIndex) restoredEdges.emplace_back(start, i, j);
    cellsAroundEdge(start, i, j, ring);
    for (const Cell_handle& c : ring) {
      const Index id = DelaunayVoronoi::cellId(c);
      if (!isInnerIn(after, id) || added[id]) continue;  // (an added cell's facets are all new)
      for (int w = 0; w < 4; ++w) {  // the facets on ab: opposite the two other vertices
        const Index sample = c->vertex(w)->info(), across = DelaunayVoronoi::cellId(c->neighbor(w));
        if (sample == info.edge[0] || sample == info.edge[1] || innerBefore(across) || isInnerIn(after, across))
          continue;
        if (std::find(restoredFacets.begin(), restoredFacets.end(), std::make_pair(id, w)) != restoredFacets.end())
          continue;
        const std::array<Index, 3> corners = facetSamples(c, w);
        for (int e = 0; e < 3; ++e)  // splits on the facet's other edges
          if (const Index other = splitNodeOfEdge.find(corners[e], corners[(e + 1) % 3]); other != kNoIndex)
            toUndo.push_back(other);
        restoredFacets.push_back({id, w});
        replacedFacets[id].push_back(corners);
      }
    }
  }
  for (Index c : cells) {
    if (!added[c]) continue;
    for (int i = 0; i < 4; ++i) {
      const Index n = DelaunayVoronoi::cellId(dv_.cell(c)->neighbor(i));
      if (innerBefore(n) && !gone[n]) replacedFacets[n].push_back(facetSamples(dv_.cell(c), i));
    }
  }

  // Out: the elements of those edges and split nodes, the cells'
  // Vertex-Face elements and those of the restored facets.
  std::vector<std::uint8_t> dropElement(mesh.size(), 0);
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const auto& t = mesh.tets[i];
    bool drop = false;
    for (Index v : t) drop = drop || undoneNode[v] != 0;
    switch (mesh.type[i]) {
      case PairElementType::FaceVertex:
        drop = drop || edges.find(mesh.medialSimplex[i][0], mesh.medialSimplex[i][1]) != kNoIndex;
        break;
      case PairElementType::EdgeEdge:
        drop = drop || (mesh.isSampleNode(t[0]) && mesh.isSampleNode(t[1]) && edges.find(t[0], t[1]) != kNoIndex);
        break;
      case PairElementType::VertexFace: {
        const Index c = mesh.medialSimplex[i][0];
        drop = drop || gone[c] != 0;
        const auto it = replacedFacets.find(c);
        if (!drop && it != replacedFacets.end()) {
          std::array<Index, 3> corners{t[1], t[2], t[3]};
          std::sort(corners.begin(), corners.end());
          drop = std::find(it->second.begin(), it->second.end(), corners) != it->second.end();
        }
        break;
      }
    }
    dropElement[i] = drop ? 1 : 0;
  }
  removeElements(mesh, dropElement, needsRepairFlags);
  const std::size_t keptElements = mesh.size();

  // In: the same edges' elements and the new boundary facets' Vertex-Face
  // elements under the new labels, on the nodes where they are; an added
  // cell's node starts at its circumcenter.
  inner_ = &after;
  m_ = &mesh;
  nodeOfCell_ = nodeBefore;
  for (Index c : cells)
    if (added[c]) {
      nodeOfCell_[c] = static_cast<Index>(mesh.nodes.size());
      mesh.nodes.push_back(weldedPosition(mesh, c));
      mesh.nodeCell.push_back(c);
      mesh.boundaryNode.push_back(0);
    }
  for (const auto& [c, e] : edgeStarts) {
    const Cell_handle cell = dv_.cell(c);
    cellsAroundEdge(cell, kEdgeI[e], kEdgeJ[e], ring);
    edge(cell->vertex(kEdgeI[e]), cell->vertex(kEdgeJ[e]), ring, mesh);
  }
  for (const auto& [cell, i, j] : restoredEdges) {
    cellsAroundEdge(cell, i, j, ring);
    edge(cell->vertex(i), cell->vertex(j), ring, mesh);
  }
  for (Index c : cells)
    for (int i = 0; i < 4; ++i) {
      const Cell_handle n = dv_.cell(c)->neighbor(i);
      const Index id = DelaunayVoronoi::cellId(n);
      if (gone[c] && isInner(id) && !added[id]) vertexFace(id, n->index(dv_.cell(c)), mesh);  // newly exposed
      if (added[c] && !isInner(id)) vertexFace(c, i, mesh);                                  // the added cell's own
    }
  for (const auto& [c, w] : restoredFacets) vertexFace(c, w, mesh);
  m_ = nullptr;
  inner_ = nullptr;

  undoneNode.resize(mesh.nodes.size(), 0);
  std::vector<std::uint8_t> dropNode(mesh.nodes.size(), 0);
  for (Index n = 0; n < mesh.nodes.size(); ++n)
    dropNode[n] = undoneNode[n] || (mesh.nodeCell[n] != kNoIndex && gone[mesh.nodeCell[n]]);
  // (Added nodes stay after the split nodes: the repair that follows visits
  // nodes in index order, and its result depends on it. NIST CTC-01 ends
  // with 0 inverted elements so, 1 with them sorted among the Voronoi nodes
  // by cell id.)
  removeNodes(mesh, dropNode);
  recountElements(mesh);
  if (needsRepairFlags) flagElementsNeedingRepair(mesh.nodes, mesh.tets, *needsRepairFlags, keptElements);
  PairMeshCounts& k = mesh.counts;
  k.splitEdges = splitNodeCount(mesh);
  for (Index c : cells) gone[c] ? --k.innerCells : ++k.innerCells;
  return true;
}

void PairMeshBuilder::add(PairMesh& out, PairElementType t, std::array<Index, 4> tet, std::array<Index, 2> medial,
                          std::array<Index, 3> boundary, bool onSheets) const {
  out.tets.push_back(tet);
  out.type.push_back(t);
  out.medialSimplex.push_back(medial);
  out.boundarySimplex.push_back(boundary);
  out.onSheets.push_back(onSheets ? 1 : 0);
}

void PairMeshBuilder::cellsAroundEdge(Cell_handle c, int i, int j, std::vector<Cell_handle>& ring) const {
  ring.clear();
  auto circ = dt_.incident_cells(c, i, j);
  const auto start = circ;
  do {
    ring.push_back(circ);
    ++circ;
  } while (circ != start);
}

// Every element of the labels, in the order of one pass over the cells by
// id: first the edges' elements (edgeElements), then the boundary facets'
// (vertexFaceElements). Blocks of cells run in parallel, each into buffers
// of its own, appended in block order: the same elements in the same order
// as one pass.
void PairMeshBuilder::elements() {
  const std::size_t cells = dv_.cellCount();
  constexpr std::size_t kBlock = 8192;
  const std::size_t blocks = (cells + kBlock - 1) / kBlock;
  std::vector<PairMesh> edgeParts(blocks), faceParts(blocks);
  tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) {
    const std::size_t begin = b * kBlock, end = std::min(cells, begin + kBlock);
    edgeElements(begin, end, edgeParts[b]);
    vertexFaceElements(begin, end, faceParts[b]);
  });
  PairMesh& m = *m_;
  std::size_t total = m.size(), triangles = m.boundaryTriangles.size();
  for (std::size_t b = 0; b < blocks; ++b) {
    total += edgeParts[b].size() + faceParts[b].size();
    triangles += faceParts[b].boundaryTriangles.size();
  }
  // Room for the elements the first repair's edge splits add (a few per
  // split), so that they do not move the whole mesh to grow it (on the
  // lever, moving 418 k elements to fresh pages was most of its 8 splits'
  // time; a relabelling trial's copy has no such room).
  const std::size_t room = total + total / 128 + 1024;
  m.tets.reserve(room);
  m.type.reserve(room);
  m.medialSimplex.reserve(room);
  m.boundarySimplex.reserve(room);
  m.onSheets.reserve(room);
  m.boundaryTriangles.reserve(triangles);
  // Each array is appended in a task of its own: the copies and the page
  // faults of fresh memory were a third of the box's build on one core.
  auto appendAll = [&](auto member) {
    auto& to = m.*member;
    for (const auto* parts : {&edgeParts, &faceParts})
      for (const PairMesh& part : *parts) to.insert(to.end(), (part.*member).begin(), (part.*member).end());
  };
  tbb::parallel_invoke([&] { appendAll(&PairMesh::tets); }, [&] { appendAll(&PairMesh::type); },
                       [&] { appendAll(&PairMesh::medialSimplex); }, [&] { appendAll(&PairMesh::boundarySimplex); },
                       [&] { appendAll(&PairMesh::onSheets); }, [&] { appendAll(&PairMesh::boundaryTriangles); });
  for (const auto* parts : {&edgeParts, &faceParts})
    for (const PairMesh& part : *parts) {
      m.counts.faceVertex += part.counts.faceVertex;
      m.counts.edgeEdge += part.counts.edgeEdge;
      m.counts.vertexFace += part.counts.vertexFace;
    }
  m.counts.boundaryTriangles = m.boundaryTriangles.size();
}

// Face-Vertex (interior edge) or Edge-Edge (boundary edge) elements of the
// Delaunay edges owned by cells [begin, end): an edge's owner is the inner
// cell of lowest id around it; in the order of the owners' ids and local
// edges. A circulated edge is marked on the range's cells around it (a bit
// per local edge), so they skip it; an edge whose owner is below `begin`
// is circulated by the range's first cell that has it, which sees the lower
// inner id and leaves it.
void PairMeshBuilder::edgeElements(std::size_t begin, std::size_t end, PairMesh& out) const {
  std::vector<std::uint8_t> done(end - begin, 0);
  std::vector<Cell_handle> ring;
  for (std::size_t id = begin; id < end; ++id) {
    if (!isInner(static_cast<Index>(id))) continue;
    const Cell_handle c = dv_.cell(static_cast<Index>(id));
    for (int e = 0; e < 6; ++e) {
      if (done[id - begin] & (1u << e)) continue;
      const Vertex_handle va = c->vertex(kEdgeI[e]), vb = c->vertex(kEdgeJ[e]);
      cellsAroundEdge(c, kEdgeI[e], kEdgeJ[e], ring);
      bool owner = true;
      for (const Cell_handle& r : ring) {
        const std::size_t rid = DelaunayVoronoi::cellId(r);
        if (rid >= begin && rid < end)
          done[rid - begin] |= static_cast<std::uint8_t>(1u << kEdgeOf[r->index(va)][r->index(vb)]);
        if (rid < id && isInner(static_cast<Index>(rid))) owner = false;
      }
      if (owner) edge(va, vb, ring, out);
    }
  }
}

// Turns `ring` (cells around ab) so that it goes positively about a -> b:
// for an inner (hence finite) cell c of it, the next cell shares c's facet
// opposite w, and (a, b, w, w') must be positively oriented.
void PairMeshBuilder::orientRing(Vertex_handle va, Vertex_handle vb, std::vector<Cell_handle>& ring) const {
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

void PairMeshBuilder::edge(Vertex_handle va, Vertex_handle vb, std::vector<Cell_handle>& ring, PairMesh& out) const {
  std::size_t innerCount = 0;
  for (const Cell_handle& r : ring) innerCount += isInner(DelaunayVoronoi::cellId(r)) ? 1 : 0;
  if (innerCount == 0) return;
  orientRing(va, vb, ring);
  const Index a = va->info(), b = vb->info();
  const std::size_t k = ring.size();
  if (innerCount == k) {  // interior edge: two Face-Vertex pyramids
    // The fan starts at the cell of lowest id, whichever cell the edge was
    // reached from: a rebuild and a local relabel give the same elements.
    std::rotate(ring.begin(),
                std::min_element(ring.begin(), ring.end(),
                                 [](const Cell_handle& x, const Cell_handle& y) {
                                   return DelaunayVoronoi::cellId(x) < DelaunayVoronoi::cellId(y);
                                 }),
                ring.end());
    const bool linked = sheetFacetEdges_.find(a, b) != kNoIndex;
    const std::array<Index, 2> facet{std::min(a, b), std::max(a, b)};
    const Index n0 = node(ring[0]);
    for (std::size_t i = 1; i + 1 < k; ++i) {
      const Index ni = node(ring[i]), nj = node(ring[i + 1]);
      add(out, PairElementType::FaceVertex, {a, n0, ni, nj}, facet, {a, kNoIndex, kNoIndex}, linked);
      add(out, PairElementType::FaceVertex, {b, n0, nj, ni}, facet, {b, kNoIndex, kNoIndex}, linked);
      out.counts.faceVertex += 2;
    }
    return;
  }
  for (std::size_t i = 0; i < k; ++i) {  // boundary edge: Edge-Edge per inner Voronoi edge
    const Index ci = DelaunayVoronoi::cellId(ring[i]), cj = DelaunayVoronoi::cellId(ring[(i + 1) % k]);
    if (!isInner(ci) || !isInner(cj)) continue;
    const bool linked = ((sheetFacets_[ci] >> ring[i]->index(ring[(i + 1) % k])) & 1) != 0;
    add(out, PairElementType::EdgeEdge, {a, b, nodeOfCell_[ci], nodeOfCell_[cj]}, {ci, cj}, {a, b, kNoIndex}, linked);
    ++out.counts.edgeEdge;
  }
}

// The Vertex-Face element of inner cell `id` on its facet opposite local
// vertex i (a boundary facet: the neighbour there is outer).
void PairMeshBuilder::vertexFace(Index id, int i, PairMesh& out) const {
  const Cell_handle c = dv_.cell(id);
  Vertex_handle x = c->vertex((i + 1) & 3), y = c->vertex((i + 2) & 3), z = c->vertex((i + 3) & 3);
  // Outward: the cell's own vertex i on the negative side.
  if (CGAL::orientation(x->point(), y->point(), z->point(), c->vertex(i)->point()) == CGAL::POSITIVE) std::swap(y, z);
  const std::array<Index, 3> tri{x->info(), y->info(), z->info()};
  out.boundaryTriangles.push_back(tri);
  add(out, PairElementType::VertexFace, {nodeOfCell_[id], tri[0], tri[1], tri[2]}, {id, kNoIndex}, tri,
      sheetCells_[id] != 0);
  ++out.counts.vertexFace;
}

// Vertex-Face: every facet of an inner cell in [begin, end) whose neighbour
// is outer.
void PairMeshBuilder::vertexFaceElements(std::size_t begin, std::size_t end, PairMesh& out) const {
  for (std::size_t id = begin; id < end; ++id) {
    if (!isInner(static_cast<Index>(id))) continue;
    for (int i = 0; i < 4; ++i)
      if (!isInner(DelaunayVoronoi::cellId(dv_.cell(static_cast<Index>(id))->neighbor(i))))
        vertexFace(static_cast<Index>(id), i, out);
  }
}

// Where an added cell's circumcenter is within the weld tolerance of a
// Voronoi node already in the mesh (reached through neighbours whose
// circumcenters are that close too: one cluster of nearly cospherical
// samples), the node takes that node's position, as a build would have
// welded it; otherwise its circumcenter.
Vec3 PairMeshBuilder::weldedPosition(const PairMesh& mesh, Index cell) const {
  const Vec3& p = dv_.circumcenter(cell);
  auto close = [&](const Vec3& q) {
    return std::abs(q[0] - p[0]) <= weldTolerance_ && std::abs(q[1] - p[1]) <= weldTolerance_ &&
           std::abs(q[2] - p[2]) <= weldTolerance_;
  };
  std::vector<Index> cluster{cell};
  for (std::size_t k = 0; k < cluster.size() && cluster.size() < 64; ++k)
    for (int i = 0; i < 4; ++i) {
      const Index n = DelaunayVoronoi::cellId(dv_.cell(cluster[k])->neighbor(i));
      if (dv_.isInfinite(n) || std::find(cluster.begin(), cluster.end(), n) != cluster.end() ||
          !close(dv_.circumcenter(n)))
        continue;
      if (nodeOfCell_[n] != kNoIndex && nodeOfCell_[n] < mesh.nodes.size() && close(mesh.nodes[nodeOfCell_[n]]))
        return mesh.nodes[nodeOfCell_[n]];
      cluster.push_back(n);
    }
  return p;
}

// Nearly cospherical samples (grids on planar faces, parameter grids on
// tori) give Voronoi vertices that coincide in exact arithmetic but differ
// by rounding; the elements between them are slivers of either sign, and
// their iso-surface cuts cross. Such nodes get one position (the first
// seen), within 1e-8 of the samples' extent, which makes those elements
// exactly flat instead.
void PairMeshBuilder::weldNearlyCoincidentVoronoiNodes() {
  PairMesh& m = *m_;
  if (m.nodes.size() <= m.sampleNodes) return;
  const double tolerance = weldTolerance_;
  if (!(tolerance > 0)) return;
  // Grid cells of the tolerance's size: two nodes in one cell are within
  // the tolerance, so a cell holds at most one node that is not welded; a
  // node's candidates are those of the 27 cells around it, first found
  // first. Open addressing, and a bit per hash value of 8 times as many
  // that says whether any cell with it holds a node: most of the 27 cells
  // are empty, and the bits stay in cache where the table does not
  // (std::unordered_multimap's lookups were 1/3 of the build). A cell's key
  // is linear in its coordinates, so a neighbour's key, and its bit (the
  // key's top bits), is the node's plus a constant: the 27 filter tests
  // cost no hashing, which took two thirds of the weld (10 ms of the
  // torus's build). The table's slot mixes the key further.
  using Cell = std::array<std::int64_t, 3>;
  auto cellOf = [&](const Vec3& p) {
    return Cell{static_cast<std::int64_t>(std::floor(p[0] / tolerance)),
                static_cast<std::int64_t>(std::floor(p[1] / tolerance)),
                static_cast<std::int64_t>(std::floor(p[2] / tolerance))};
  };
  constexpr std::uint64_t kx = 0x9e3779b97f4a7c15ULL, ky = 0xc2b2ae3d27d4eb4fULL, kz = 0x165667b19e3779f9ULL;
  auto keyOf = [](const Cell& c) {  // (unsigned: wraps around, the same for a cell however it is reached)
    return static_cast<std::uint64_t>(c[0]) * kx + static_cast<std::uint64_t>(c[1]) * ky +
           static_cast<std::uint64_t>(c[2]) * kz;
  };
  std::array<std::uint64_t, 27> neighbourOffset;
  std::array<Cell, 27> neighbourStep;
  for (int dx = -1, k = 0; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dz = -1; dz <= 1; ++dz, ++k) {
        neighbourStep[k] = Cell{dx, dy, dz};
        neighbourOffset[k] = keyOf(neighbourStep[k]);
      }
  auto slotHash = [](std::uint64_t key) {
    key ^= key >> 31;
    key *= 0xbf58476d1ce4e5b9ULL;
    return key ^ (key >> 29);
  };
  std::size_t capacity = 16;
  int capacityBits = 4;
  while (capacity < 2 * (m.nodes.size() - m.sampleNodes)) {
    capacity <<= 1;
    ++capacityBits;
  }
  const std::size_t mask = capacity - 1;
  std::vector<Cell> cells(capacity);
  std::vector<Index> nodeIn(capacity, kNoIndex);
  const int bitShift = 64 - (capacityBits + 3);  // 8 * capacity bits
  std::vector<std::uint64_t> bits(capacity / 8 + 1, 0);
  auto bit = [&](std::uint64_t key) { return key >> bitShift; };
  auto find = [&](const Cell& c, std::uint64_t key) {
    for (std::size_t slot = slotHash(key) & mask;; slot = (slot + 1) & mask)
      if (nodeIn[slot] == kNoIndex || cells[slot] == c) return slot;
  };
  // A node too far out for the grid's integer cells (|p| >= 2^52 tolerances,
  // or not finite: the centre of a nearly flat cell relabelled inner) is
  // left as it is: its coordinates' rounding is as large as the tolerance
  // there, and the cast to integers and the steps to the neighbours would
  // overflow.
  auto onGrid = [tolerance](const Vec3& p) {
    constexpr double limit = 4503599627370496.0;  // 2^52
    return std::abs(p[0]) / tolerance < limit && std::abs(p[1]) / tolerance < limit &&
           std::abs(p[2]) / tolerance < limit;
  };
  for (Index n = static_cast<Index>(m.sampleNodes); n < m.nodes.size(); ++n) {
    Vec3& p = m.nodes[n];
    if (!onGrid(p)) continue;
    const Cell c = cellOf(p);
    const std::uint64_t key = keyOf(c);
    bool welded = false;
    for (int k = 0; k < 27 && !welded; ++k) {
      const std::uint64_t aroundKey = key + neighbourOffset[k];
      const std::uint64_t b = bit(aroundKey);
      if (!(bits[b >> 6] >> (b & 63) & 1)) continue;
      const Cell around{c[0] + neighbourStep[k][0], c[1] + neighbourStep[k][1], c[2] + neighbourStep[k][2]};
      const Index other = nodeIn[find(around, aroundKey)];
      if (other == kNoIndex) continue;
      const Vec3& q = m.nodes[other];
      if (std::abs(q[0] - p[0]) <= tolerance && std::abs(q[1] - p[1]) <= tolerance &&
          std::abs(q[2] - p[2]) <= tolerance) {
        if (q != p) ++m.counts.weldedNodes;
        p = q;
        welded = true;
      }
    }
    if (welded) continue;
    const std::size_t slot = find(c, key);
    if (nodeIn[slot] == kNoIndex) {  // (else a node within the tolerance holds it, and p welded to it)
      cells[slot] = c;
      nodeIn[slot] = n;
      const std::uint64_t b = bit(key);
      bits[b >> 6] |= std::uint64_t(1) << (b & 63);
    }
  }
}

}  // namespace cadmedial
