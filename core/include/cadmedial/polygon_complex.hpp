// Closure of the inner medial axis into an indexed polygon complex, its
// segmentation into sheets, and its Betti numbers (DESIGN.md §4.6).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "cadmedial/delaunay.hpp"
#include "cadmedial/facet_selection.hpp"
#include "cadmedial/forced_triangles.hpp"
#include "cadmedial/inner_outer.hpp"

namespace cadmedial {

struct MedialComplex {
  // Shared vertices: one per Voronoi vertex (= Delaunay cell) used, plus one
  // per sample used by a forced triangle.
  std::vector<Vec3> vertices;
  std::vector<double> radius;        // medial radius: circumradius of the cell; 0 at samples
  std::vector<Index> vertexCell;     // cell id, or kNoIndex for a sample vertex
  std::vector<Index> vertexSample;   // sample id, or kNoIndex for a Voronoi vertex
  // Polygon i = vertices polygonVertices[polygonOffsets[i] .. polygonOffsets[i+1]).
  std::vector<Index> polygonOffsets{0};
  std::vector<Index> polygonVertices;
  std::vector<PolygonProvenance> provenance;
  // DelaunayEdgeFacet: (p, q); ConvexEdgeTriangle: (s, -); fill: (s, s'); corner: (p, -);
  // HoleFill: (-, -).
  std::vector<std::array<Index, 2>> provenanceSamples;
  // Sheet id per polygon (0 .. sheetCount-1), filled by segmentSheets().
  std::vector<Index> sheet;
  std::size_t sheetCount = 0;
  // Cells whose Voronoi vertex weldCoincidentVertices joined to another
  // cell's: (cell welded, cell of the vertex kept).
  std::vector<std::array<Index, 2>> weldedCells;

  std::size_t polygonCount() const { return provenance.size(); }
  Index polygonSize(std::size_t i) const { return polygonOffsets[i + 1] - polygonOffsets[i]; }
};

// The 1-skeleton of a complex: distinct undirected polygon edges.
struct ComplexEdges {
  std::vector<std::array<Index, 2>> vertices;  // per edge
  std::vector<Index> polygonCount;             // polygons incident to the edge
  std::vector<Index> firstPolygon, secondPolygon;
  // Edge of polygon slot k (from polygonVertices[k] to the next vertex of its polygon).
  std::vector<Index> slotEdge;
  std::size_t borderEdges = 0;    // in 1 polygon
  std::size_t manifoldEdges = 0;  // in 2
  std::size_t junctionEdges = 0;  // in 3 or more
};

struct ComplexTopology {
  std::size_t vertices = 0, edges = 0, polygons = 0;
  long long euler = 0;     // χ = V − E + F
  long long beta0 = 0;     // connected components
  long long beta1 = -1;    // β0 + β2 − χ (Z2 coefficients); -1 if β2 unknown
  long long beta2 = -1;    // enclosed voids; -1 if the 2-core exceeded the limit
  std::size_t coreSize = 0;  // polygons left after free-face collapses
};

// Inner facets (bounded, not reached by the walk) and inner forced triangles.
MedialComplex buildInnerComplex(const DelaunayVoronoi& dv, const SampleSet& samples, const SelectedFacets& selected,
                                const ForcedTriangles& forced, const InnerOuterLabels& labels);

// Adds every unselected Voronoi facet whose vertices and edges all lie on
// the complex already (a one-facet hole in the inner axis, see
// facet_holes.cpp); returns how many. Call before buildComplexEdges.
std::size_t fillSingleFacetHoles(const DelaunayVoronoi& dv, const SelectedFacets& selected, MedialComplex& complex);

// The connected components of a complex's vertices (joined through
// polygons), numbered 0 .. count-1, and the one with the most polygons,
// which the island rules below never drop.
struct VertexComponents {
  std::vector<Index> ofVertex;
  Index count = 0;
  Index largest = 0;
  Index ofPolygon(const MedialComplex& complex, std::size_t p) const {
    return ofVertex[complex.polygonVertices[complex.polygonOffsets[p]]];
  }
};
VertexComponents vertexComponents(const MedialComplex& complex);

// The island rules below: each finds the complex's components unless
// `shared` holds them already, and leaves them there, so consecutive rules
// on one complex find them once; a rule that removes polygons empties it.

// Removes every connected component whose largest medial radius is below
// minRadius and which has no forced triangle, except the component with the
// most polygons, and drops the vertices no polygon uses any more (see
// small_islands.cpp).
// Returns the number of components removed; *polygonsRemoved their polygons.
std::size_t dropSubResolutionIslands(MedialComplex& complex, double minRadius, std::size_t* polygonsRemoved,
                                     std::optional<VertexComponents>* shared = nullptr);

// Removes every connected component, except the one with the most polygons,
// whose vertices all lie in a box no wider than `tolerance` (zero-size
// polygons at the common centre of cospherical samples, see
// small_islands.cpp), and the vertices no polygon uses any more.
// Returns the number of components removed; *polygonsRemoved their polygons.
std::size_t dropPointIslands(MedialComplex& complex, double tolerance, std::size_t* polygonsRemoved,
                             std::optional<VertexComponents>* shared = nullptr);

// Removes every connected component, except the one with the most polygons,
// that has no Voronoi facet (forced triangles only: a feature's completion
// whose sheet the filter pruned, see small_islands.cpp), and the vertices no
// polygon uses any more. Returns the number of components removed;
// *polygonsRemoved their polygons.
std::size_t dropForcedOnlyIslands(MedialComplex& complex, std::size_t* polygonsRemoved,
                                  std::optional<VertexComponents>* shared = nullptr);

// Removes every connected component, except the one with the most polygons,
// that has no forced triangle and whose every vertex v is dominated by a
// vertex u of that one: r_u - r_v + slack >= cosBeta |u - v| (its balls
// nearly nest in the main axis's, see small_islands.cpp), and the vertices no polygon
// uses any more. Returns the number of components removed; *polygonsRemoved
// their polygons.
std::size_t dropNestedIslands(MedialComplex& complex, double cosBeta, double slack, std::size_t* polygonsRemoved,
                              std::optional<VertexComponents>* shared = nullptr);

// Joins Voronoi vertices closer than `tolerance` (cospherical samples: one
// vertex, several cells, circumcenters apart by rounding) into the first of
// them; drops zero-length polygon edges and polygons left with fewer than
// three corners (only where other polygons hold what they span) and
// polygons made equal to an earlier one (a pillow), keeps a group of welds
// only when it adds no cycle (β1 from χ and β0), and records the cells
// joined in weldedCells. Returns the number of vertices welded;
// *facetsDropped the Voronoi facets (not forced triangles) dropped: a
// segment or a point once welded, or equal to another polygon. See
// coincident_vertices.cpp. Call before
// buildComplexEdges.
std::size_t weldCoincidentVertices(MedialComplex& complex, double tolerance, std::size_t* facetsDropped = nullptr);

// Keeps the polygons with keep[i] != 0 (in order) and the vertices they use
// (renumbered); sheets are reset.
void keepPolygons(MedialComplex& complex, const std::vector<std::uint8_t>& keep);

struct FringeThinningParams {
  double cosBeta = 0.94;  // u dominates v if r_u - r_v >= cosBeta |u - v| (β ≈ 20°)
  double slack = 0;       // ... up to slack: r_u - r_v + slack >= cosBeta |u - v|
  double minReach = 0;    // ... and |u - v| >= minReach (u any other vertex); must be > 0
};

// Removes, by homotopy-preserving collapses from the complex's free edges,
// the Voronoi facets of chords on one smooth surface whose vanishing
// vertices, and one end of each free edge, have their ball inside another
// vertex's ball: the fringe the Angle condition keeps around 1-D parts of
// the axis (fringe_thinning.cpp). Returns how many polygons were removed;
// throws std::invalid_argument on parameters out of range. Call before
// buildComplexEdges.
std::size_t thinFringe(MedialComplex& complex, const SampleSet& samples, const FringeThinningParams& params);

ComplexEdges buildComplexEdges(const MedialComplex& complex);

// Closes every hole of the complex whose rim is a simple cycle of border
// edges shorter than the median medial radius on it, with one HoleFill
// polygon through the rim's vertices (short_holes.cpp: such a loop bounds a
// disk inside a medial ball, so it is no loop of the true axis), unless it
// closes a pocket (the fill stays in the 2-core: the rim bounded a disk
// already, and a void would be made). `edges` is buildComplexEdges(complex)
// and is kept up to date. Returns the number of holes closed; sheets are
// reset (sheet ids kNoIndex, sheetCount 0).
std::size_t fillShortHoles(MedialComplex& complex, ComplexEdges& edges);

// Sheets = maximal sets of polygons connected across edges shared by exactly
// two polygons (border edges and non-manifold junction edges separate them).
void segmentSheets(MedialComplex& complex, const ComplexEdges& edges);

// β0 by union-find over the edges. β2 by elementary collapses (repeatedly
// remove a polygon with a free edge: homotopy-preserving) followed by the Z2
// rank of the boundary matrix of the remaining 2-core (skipped above
// coreLimit polygons). β1 from the Euler characteristic: β1 = β0 + β2 − χ.
ComplexTopology computeTopology(const MedialComplex& complex, const ComplexEdges& edges, std::size_t coreLimit);

// The elementary collapses above. core() is, per polygon, 1 if it is left
// (the 2-core: polygons on closed pockets, and what hangs between them). A
// polygon of the core can be taken out and the collapses go on from the
// edges it frees (fillShortHoles takes its fills out one at a time). The
// complex and the edges must outlive it and stay unchanged.
class FreeFaceCollapse {
 public:
  FreeFaceCollapse(const MedialComplex& complex, const ComplexEdges& edges);
  bool inCore(Index polygon) const { return alive_[polygon] != 0; }
  const std::vector<std::uint8_t>& core() const { return alive_; }
  void removeFromCore(Index polygon);

 private:
  void takeOut(Index polygon);
  void collapse();
  const MedialComplex& mc_;
  const ComplexEdges& edges_;
  std::vector<Index> offsets_, incident_, count_, queue_;
  std::vector<std::uint8_t> alive_;
};

}  // namespace cadmedial
