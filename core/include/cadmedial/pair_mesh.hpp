// Pair-mesh (seed 003 §4, DESIGN.md §5): a tetrahedral complex that links the
// inner part of the Voronoi diagram of the samples to the boundary surface
// made of Delaunay triangles, on the same Delaunay triangulation as CAD_MEDIAL.
//
//   inner cells   Delaunay cells whose Voronoi vertex (circumcenter) is inside
//                 the solid; decided by the caller (exact classifier), so core
//                 stays free of OCCT. Infinite cells are outer.
//   boundary      Delaunay triangles between an inner and an outer cell,
//                 oriented outward: closed by construction.
//   elements      Face-Vertex pyramids: a Voronoi facet whose Delaunay edge ab
//                 has only inner cells around it, coned to a and to b
//                 (fan-split into tetrahedra);
//                 Edge-Edge: at a boundary edge ab, each Voronoi edge between
//                 two consecutive inner cells, joined to ab;
//                 Vertex-Face: a boundary triangle joined to the Voronoi
//                 vertex of its inner cell.
//
// Every tetrahedron is stored with a positive orientation when valid:
//   FaceVertex (a, c0, ci, ci+1)  a the apex sample, c the facet's Voronoi
//                                 vertices turning positively about a -> b
//   EdgeEdge   (a, b, ci, ci+1)   ci, ci+1 turning positively about a -> b
//   VertexFace (c, x, y, z)       (x, y, z) the outward boundary triangle
// Whatever the node positions, the signed volumes add up to the volume
// enclosed by the boundary (a chain identity), so the complex is a valid
// partition of that volume exactly when no element has a negative volume.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "cadmedial/delaunay.hpp"
#include "cadmedial/polygon_complex.hpp"
#include "cadmedial/sample_set.hpp"

namespace cadmedial {

enum class PairElementType : std::uint8_t { FaceVertex = 0, EdgeEdge = 1, VertexFace = 2 };
const char* pairElementTypeName(PairElementType t);

struct PairMeshCounts {
  std::size_t innerCells = 0;
  std::size_t weldedNodes = 0;  // Voronoi nodes put on a nearly coincident one (< 1e-8 extent, or < h/200 when safe)
  std::size_t boundaryTriangles = 0;
  std::size_t faceVertex = 0, edgeEdge = 0, vertexFace = 0;  // tetrahedra of each type
  // Repair (seed 003 §4.1): Voronoi nodes moved toward the inside of their
  // Delaunay cell, and elements negative before / after it.
  std::size_t invertedBeforeRepair = 0;
  std::size_t movedNodes = 0;
  // Boundary edges split at a point of their Voronoi cut face (seed 003
  // §4.1, second case): each adds one boundary node.
  std::size_t splitEdges = 0;
  // Voronoi polygons of Face-Vertex pyramids given another triangulation
  // than the fan, where node moves had folded it.
  std::size_t retriangulatedPolygons = 0;
  // Flat Delaunay cells (coplanar samples, no meaningful circumcenter) given
  // their neighbours' side where that removes a fold of the boundary.
  std::size_t relabelledFlatCells = 0;
  // Last resort: cells that changed side around elements the repair left
  // inverted, when the updated, repaired mesh has fewer inverted elements:
  // inner cells on the boundary whose Voronoi node was a corner of such an
  // element, relabelled outer, or outer cells next to such an element,
  // relabelled inner (the boundary then runs over their other facets).
  // movedNodes and retriangulatedPolygons are then summed over the repairs
  // of the meshes kept; splitEdges and the other counts are those of the
  // final mesh (invertedBeforeRepair: of the first).
  std::size_t relabelledBoundaryCells = 0;
  std::size_t invertedAfterRepair = 0;
};

struct PairMesh {
  // Nodes: node i < sampleNodes is sample i (boundary vertex); then the
  // Voronoi vertices, one per inner cell (the circumcenter, unless the repair
  // moved it), by cell id; then the boundary nodes the repair put on split
  // edges, and the Voronoi vertices of cells the last resort made inner
  // (nodeCell and boundaryNode tell each node's kind).
  std::vector<Vec3> nodes;
  std::size_t sampleNodes = 0;
  std::vector<Index> nodeCell;        // per node: its Delaunay cell, kNoIndex for boundary nodes
  std::vector<std::uint8_t> boundaryNode;  // per node: 1 sample or split point, 0 Voronoi node
  double spacing = 0;  // the samples' spacing h (0 if unknown)
  std::vector<std::array<Index, 4>> tets;
  std::vector<PairElementType> type;
  // Dual data per tetrahedron (kNoIndex where unused):
  //   medialSimplex: FaceVertex -> the Delaunay edge {p, q} (samples) of its
  //   Voronoi facet; EdgeEdge -> the two cells of its Voronoi edge;
  //   VertexFace -> {cell, -}.
  //   boundarySimplex: FaceVertex -> {apex sample}; EdgeEdge -> {a, b};
  //   VertexFace -> {x, y, z}.
  std::vector<std::array<Index, 2>> medialSimplex;
  std::vector<std::array<Index, 3>> boundarySimplex;
  // 1 if the medial simplex belongs to the CAD_MEDIAL inner sheets (the
  // facet, one of their edges, one of their vertices).
  std::vector<std::uint8_t> onSheets;
  std::vector<std::array<Index, 3>> boundaryTriangles;  // outward, sample ids
  PairMeshCounts counts;
  double seconds = 0;        // construction
  double repairSeconds = 0;

  std::size_t size() const { return tets.size(); }
  bool isSampleNode(Index n) const { return n < sampleNodes; }
  bool isBoundaryNode(Index n) const { return boundaryNode[n] != 0; }
};

// Builds the pair-mesh from the triangulation and per-cell inner labels
// (cellInner[id] != 0: inner; size dv.cellCount()). innerAxis (optional): the
// CAD_MEDIAL inner complex built on the same triangulation, for onSheets.
// Runs the repair unless repair is false; what it leaves inverted gets the
// last resort, cells next to it relabelled (counts.relabelledBoundaryCells).
PairMesh buildPairMesh(const DelaunayVoronoi& dv, const SampleSet& samples, const std::vector<std::uint8_t>& cellInner,
                       const MedialComplex* innerAxis = nullptr, bool repair = true);

// Seed 003 §4.1, first case: a Voronoi node of a negative element is moved
// toward the centroid of its Delaunay cell (inside the cell: its Vertex-Face
// elements turn positive) by the smallest step that leaves all its elements
// non-negative, or failing that by the step that leaves the fewest negative.
// Then every boundary edge with a negative Edge-Edge element that node moves
// could not fix is split (splitBoundaryEdges) and the nodes are moved again.
// Updates the counts; returns the number of negative elements left, and
// in *needingRepair (when given) the number of elements left negative or
// flat (elementNeedsRepair). needsRepairFlags (optional): on entry, with
// options.flagsAreCurrent, every element's elementNeedsRepair (one entry
// per element); on return, those of the repaired mesh (the relabelling
// trials start from them).
struct RepairOptions {
  int rounds = 12;  // of node moves
  // First put clusters of Voronoi nodes closer than h/200 on one position
  // where that leaves no more elements to repair around them.
  bool weldCloseNodes = true;
  // Set counts.invertedBeforeRepair (a pass over every element); off where
  // the caller keeps that count itself (the relabelling trials).
  bool countInvertedBefore = true;
  // The needsRepairFlags passed in hold every element's elementNeedsRepair
  // for the mesh as it is (then no pass over every element is made for
  // them). Off, they are computed, whatever they hold.
  bool flagsAreCurrent = false;
};
std::size_t repairFlippedElements(PairMesh& mesh, const DelaunayVoronoi& dv, const RepairOptions& options = {},
                                  std::size_t* needingRepair = nullptr,
                                  std::vector<std::uint8_t>* needsRepairFlags = nullptr);

// Seed 003 §4.1, second case: a boundary edge ab that misses its Voronoi cut
// face (the chain of inner Voronoi nodes around it) folds some of its
// Edge-Edge elements. It is replaced by a -> m -> b, m a new boundary node
// near the cut face; each Edge-Edge element becomes two, and the two boundary
// triangles on ab become polygons, re-triangulated (every triangulation of
// the polygon is tried) into Vertex-Face elements on the same Voronoi node.
// A split is kept only when it leaves fewer negative elements. Returns the
// number of edges split. candidates (optional): elements among which are
// all the negative ones (the repair's flagged elements), so that the search
// need not test every element. needsRepairFlags (optional): every element's
// elementNeedsRepair, kept so (the replaced elements' entries go with them,
// the new elements get theirs), so that the repair after the splits need
// not test every element again.
std::size_t splitBoundaryEdges(PairMesh& mesh, const std::vector<std::size_t>* candidates = nullptr,
                               std::vector<std::uint8_t>* needsRepairFlags = nullptr);

// Signed volume of tetrahedron i (positive = valid orientation).
double tetVolume(const PairMesh& mesh, std::size_t i);
// Inverted: negative orientation by CGAL's exact predicate, however small
// (the iso-surfaces are checked with exact predicates too, so a sliver of
// rounding size with the wrong sign would show there as a crossing).
bool isInverted(const PairMesh& mesh, std::size_t i);
// 1e-12 × (longest edge)³: below it a volume is reported as degenerate.
double negligibleVolume(const PairMesh& mesh, std::size_t i);

// DESIGN.md §6 pair-mesh validity.
struct PairMeshValidity {
  std::size_t elements = 0;
  std::size_t inverted = 0;     // negative orientation (exact)
  std::size_t degenerate = 0;   // not inverted, |volume| <= negligible
  double sumVolume = 0;         // Σ vol
  double sumAbsVolume = 0;      // Σ |vol|
  double enclosedVolume = 0;    // enclosed by the boundary triangles (divergence theorem)
  double overlapError = 0;      // (Σ|vol| - |Σ vol|) / enclosed: 0 iff nothing folds over
  double gapError = 0;          // |Σ vol - enclosed| / enclosed
  std::size_t boundaryTriangles = 0;
  std::size_t boundaryTrianglesNotInOneVertexFace = 0;  // must be 0
  std::size_t boundaryEdgesNotShared = 0;  // edges in an odd number of boundary triangles (must be 0: closed)

  bool valid(double relativeTolerance = 1e-9) const {
    return inverted == 0 && overlapError <= relativeTolerance && gapError <= relativeTolerance &&
           boundaryTrianglesNotInOneVertexFace == 0 && boundaryEdgesNotShared == 0 && enclosedVolume > 0;
  }
};
PairMeshValidity checkPairMesh(const PairMesh& mesh);

// The volume its boundary triangles enclose (checkPairMesh(mesh).enclosedVolume
// without the element checks).
double boundaryEnclosedVolume(const PairMesh& mesh);

// Iso-parametric surface at t in [0, 1] (seed 003 §4.2): one node per interim
// edge (sample s, Voronoi node v) at (1 - t) v + t s; per element its cut:
// Face-Vertex -> a polygon (fan-split like the pyramid), Edge-Edge -> a
// quadrilateral (2 triangles), Vertex-Face -> a triangle; oriented from the
// medial side toward the boundary. At t = 1 (t = 0) the nodes of a sample
// (of a Voronoi node) coincide and are merged, and faces that collapse are
// dropped: at t = 1 this leaves exactly the boundary triangles.
struct IsoSurface {
  std::vector<Vec3> points;
  std::vector<std::array<Index, 3>> triangles;
  std::vector<Index> element;  // per triangle: the pair-mesh element it cuts
  // Per point: its interim edge {boundary node, Voronoi node} (kNoIndex for
  // the side merged away at t = 1 or t = 0), and the parameter.
  std::vector<std::array<Index, 2>> pointNodes;
  double t = 0.5;
};
IsoSurface isoSurface(const PairMesh& mesh, double t);

// CGAL's self-intersection test on an iso-surface: pairs of triangles that
// meet other than along the edges and vertices they share (0 for a valid
// pair-mesh at any t in (0, 1)). Cuts of flat elements (cospherical samples
// make Voronoi nodes coincide) are counted apart, not as intersections:
// triangles that collapse once equal positions are welded, and pairs of
// opposite copies of one triangle.
struct IsoSurfaceIntersections {
  std::size_t intersectingPairs = 0;
  std::size_t degenerateTriangles = 0;
  std::vector<std::array<Index, 2>> elementPairs;  // the elements of (up to 100) crossing pairs
  std::size_t roundedCrossings = 0;  // crossing pairs of the triangles at their rounded (written) points
};
IsoSurfaceIntersections isoSurfaceSelfIntersections(const IsoSurface& iso);
// The same, decided on the exact iso-surface of `mesh` (its points built
// with exact arithmetic from the nodes, CGAL's Epeck kernel) around the
// crossings the rounded points show (the triangles within a crossing
// triangle's size of one; all of them past 256 crossing triangles): what the
// pair-mesh defines, free of the rounding of the written coordinates, which
// near sliver elements alone can make cuts cross (those are counted in
// roundedCrossings). Elsewhere the rounded points decide, as everywhere when
// they show no crossing; degenerateTriangles is the rounded count.
IsoSurfaceIntersections isoSurfaceSelfIntersections(const IsoSurface& iso, const PairMesh& mesh);

}  // namespace cadmedial
