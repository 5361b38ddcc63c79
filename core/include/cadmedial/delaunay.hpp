// Delaunay triangulation of the samples and its dual Voronoi diagram
// (DESIGN.md §4.1). Built once, reused by every later stage (facet selection,
// forced triangles, walk, pair-mesh).
//
// * CGAL Delaunay_triangulation_3 over Exact_predicates_inexact_constructions_kernel.
// * Vertex info = sample index (the lowest sample index at that location).
// * Cell info = cell id, dense 0..cellCount()-1 over ALL cells (infinite ones
//   included). A Voronoi vertex is identified by its cell id, never by its
//   coordinates: exactly cospherical samples give many cells with one
//   circumcenter, and they stay distinct Voronoi vertices here.
// * Circumcenter / circumradius per cell, computed once into side arrays
//   (NaN / +inf for infinite cells).
// * Duplicate input points are merged by CGAL; every sample still maps to the
//   vertex at its location (canonicalSample), and duplicateCount() says how many
//   samples were merged.
#pragma once

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <array>
#include <vector>

#include "cadmedial/sample_set.hpp"

namespace cadmedial {

class DelaunayVoronoi {
 public:
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = Kernel::Point_3;
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<Index, Kernel>;
  using Cb = CGAL::Triangulation_cell_base_with_info_3<Index, Kernel,
                                                       CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
  using Triangulation = CGAL::Delaunay_triangulation_3<Kernel, Tds>;
  using Vertex_handle = Triangulation::Vertex_handle;
  using Cell_handle = Triangulation::Cell_handle;
  using Edge = Triangulation::Edge;
  using Facet = Triangulation::Facet;

  // Builds the triangulation (points inserted as one range, spatially sorted
  // by CGAL) and the per-cell side arrays. Throws std::invalid_argument on
  // non-finite coordinates.
  explicit DelaunayVoronoi(const std::vector<Vec3>& points);

  DelaunayVoronoi(const DelaunayVoronoi&) = delete;
  DelaunayVoronoi& operator=(const DelaunayVoronoi&) = delete;

  const Triangulation& triangulation() const { return dt_; }
  int dimension() const { return dt_.dimension(); }
  std::size_t sampleCount() const { return canonical_.size(); }

  // --- cells = Voronoi vertices -------------------------------------------
  std::size_t cellCount() const { return cells_.size(); }
  std::size_t finiteCellCount() const { return finiteCells_; }
  static Index cellId(Cell_handle c) { return c->info(); }
  Cell_handle cell(Index id) const { return cells_[id]; }
  bool isInfinite(Index id) const { return infinite_[id] != 0; }
  const Vec3& circumcenter(Index id) const { return center_[id]; }
  double circumradius(Index id) const { return radius_[id]; }
  // Sample index of local vertex i of a cell, kNoIndex for the infinite vertex.
  // Read from a flat copy (16 bytes a cell, in cell-id order): the walk and
  // the ring passes read a cell's samples without touching CGAL's cell and
  // vertex records, which lie scattered in memory (two random reads less a
  // sample).
  Index cellSample(Index id, int i) const { return cellSamples_[id][i]; }
  const std::array<Index, 4>& cellSamples(Index id) const { return cellSamples_[id]; }
  // Id of the cell across local facet i (opposite vertex i), from a flat copy
  // for the same reason: rings and neighbour links are circulated over ids.
  Index cellNeighbor(Index id, int i) const { return cellNeighbors_[id][i]; }
  // The local index of a sample in a cell, -1 if absent.
  int localIndex(Index id, Index sample) const {
    const std::array<Index, 4>& s = cellSamples_[id];
    for (int i = 0; i < 4; ++i)
      if (s[i] == sample) return i;
    return -1;
  }
  bool cellHasSample(Index id, Index sample) const;
  // The finite facets (Delaunay triangles) around sample's vertex, each named
  // from the lower id of its two cells, sorted by (cell id, index). CGAL's own
  // order, and which of the two cells names a facet, changed from run to run
  // on the same input, and so did the order and orientation of fan triangles
  // in the outputs.
  void finiteIncidentFacets(Index sample, std::vector<Facet>& out) const;

  // --- samples = Delaunay vertices ----------------------------------------
  // The vertex at sample i's location (shared by duplicates).
  Vertex_handle vertex(Index sample) const { return vertex_[sample]; }
  // The sample index stored on that vertex: the lowest index among the samples
  // at that location (i itself unless i duplicates an earlier sample).
  Index canonicalSample(Index sample) const { return canonical_[sample]; }
  std::size_t duplicateCount() const { return duplicates_; }

  // Times in seconds: CGAL insertion alone, and the side arrays.
  double delaunaySeconds() const { return delaunaySeconds_; }
  double sideArraySeconds() const { return sideArraySeconds_; }

 private:
  Triangulation dt_;
  std::vector<Cell_handle> cells_;
  std::vector<std::uint8_t> infinite_;
  std::vector<std::array<Index, 4>> cellSamples_;
  std::vector<std::array<Index, 4>> cellNeighbors_;
  std::vector<Vec3> center_;
  std::vector<double> radius_;
  std::vector<Vertex_handle> vertex_;
  std::vector<Index> canonical_;
  std::size_t duplicates_ = 0;
  std::size_t finiteCells_ = 0;
  double delaunaySeconds_ = 0;
  double sideArraySeconds_ = 0;
};

}  // namespace cadmedial
