// Private to the pair-mesh: the elements of given inner labels on the
// Delaunay triangulation (before any repair), and the local update of a
// built mesh when a few cells change side (the last resort of the repair,
// pair_mesh_boundary_cells.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "cadmedial/delaunay.hpp"
#include "cadmedial/edge_table.hpp"
#include "cadmedial/pair_mesh.hpp"
#include "cadmedial/polygon_complex.hpp"
#include "cadmedial/sample_set.hpp"

namespace cadmedial {

class PairMeshBuilder {
 public:
  // innerAxis (optional): the CAD_MEDIAL inner complex on the same
  // triangulation, for the elements' onSheets flags.
  PairMeshBuilder(const DelaunayVoronoi& dv, const SampleSet& samples, const MedialComplex* innerAxis);

  // The pair-mesh of these labels (one per cell id; infinite cells count as
  // outer), unrepaired; Voronoi nodes within 1e-8 of the extent are welded.
  PairMesh build(const std::vector<std::uint8_t>& inner);

  // `mesh` was built (and maybe repaired) from labels under which `cells`
  // had the other side than in `after` (inner cells going outer, or outer
  // cells going inner). Only the elements that depend on those cells'
  // labels change: those of the Delaunay edges of the cells (Face-Vertex and
  // Edge-Edge) and the Vertex-Face elements of their facets; the cells going
  // outer lose their Voronoi nodes, those going inner get one at their
  // circumcenter. A split of one of those edges (by a repair) is undone, and
  // so is a split on another edge of a boundary facet that has to be
  // restored because of it. Every other element keeps what a repair did to
  // it (node positions, re-triangulated polygons, split edges), so only the
  // changed part is left to repair. Nodes keep their order; an added node
  // is appended (after any split nodes) and welded like a build would (within 1e-8 of the extent of a node of its
  // cluster of nearly coincident circumcenters). Returns false, with `mesh`
  // untouched, when a split to undo is of an edge split twice (its elements
  // could no longer be told apart): the caller rebuilds instead. Throws
  // std::invalid_argument unless exactly the listed cells change side.
  // needsRepairFlags (optional, one per element of `mesh`: its
  // elementNeedsRepair) is kept so: the removed elements' entries go, the
  // new elements get theirs (the kept ones keep their nodes' positions).
  bool relabel(PairMesh& mesh, const std::vector<std::uint8_t>& after, const std::vector<Index>& cells,
               std::vector<std::uint8_t>* needsRepairFlags = nullptr);

 private:
  using Cell_handle = DelaunayVoronoi::Cell_handle;
  using Vertex_handle = DelaunayVoronoi::Vertex_handle;

  bool isInnerIn(const std::vector<std::uint8_t>& labels, Index c) const { return !dv_.isInfinite(c) && labels[c] != 0; }
  bool isInner(Index c) const { return isInnerIn(*inner_, c); }
  Index node(Cell_handle c) const { return nodeOfCell_[DelaunayVoronoi::cellId(c)]; }
  // Element appenders: const, so that blocks of cells can run in parallel,
  // each into a PairMesh of its own.
  void add(PairMesh& out, PairElementType t, std::array<Index, 4> tet, std::array<Index, 2> medial,
           std::array<Index, 3> boundary, bool onSheets) const;
  void elements();
  void edgeElements(std::size_t begin, std::size_t end, PairMesh& out) const;
  void cellsAroundEdge(Cell_handle c, int i, int j, std::vector<Cell_handle>& ring) const;
  void orientRing(Vertex_handle va, Vertex_handle vb, std::vector<Cell_handle>& ring) const;
  // The elements of edge ab (ring: the cells around it; the build starts it
  // at the edge's owner, so Edge-Edge elements come in the same order).
  void edge(Vertex_handle va, Vertex_handle vb, std::vector<Cell_handle>& ring, PairMesh& out) const;
  void vertexFace(Index cell, int facet, PairMesh& out) const;
  void vertexFaceElements(std::size_t begin, std::size_t end, PairMesh& out) const;
  void weldNearlyCoincidentVoronoiNodes();
  Vec3 weldedPosition(const PairMesh& mesh, Index cell) const;

  const DelaunayVoronoi& dv_;
  const DelaunayVoronoi::Triangulation& dt_;
  const SampleSet& samples_;
  double weldTolerance_ = 0;  // 1e-8 of the samples' bounding-box diagonal
  PairTable sheetFacetEdges_;    // Delaunay edges {p, q} of inner CAD_MEDIAL facets
  // Per cell, bit i: the Voronoi edge to its neighbour i (dual to facet i)
  // is an edge of its polygons. Only edges between neighbours are ever
  // asked for, so a 4-bit mask per cell replaces a table of cell pairs.
  std::vector<std::uint8_t> sheetFacets_;
  std::vector<std::uint8_t> sheetCells_;
  // Per call:
  const std::vector<std::uint8_t>* inner_ = nullptr;
  std::vector<Index> nodeOfCell_;
  PairMesh* m_ = nullptr;
};

}  // namespace cadmedial
