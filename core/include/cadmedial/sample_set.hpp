// SampleSet: the boundary samples of one solid, handed from sampling/ (OCCT)
// to core/ (no OCCT). Plain arrays only, so core can be driven by synthetic
// samples and point clouds as well. See DESIGN.md §3.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace cadmedial {

using Vec3 = std::array<double, 3>;
using Index = std::uint32_t;
constexpr Index kNoIndex = std::numeric_limits<Index>::max();

// Where a sample lies on the B-rep.
enum class SampleKind : std::uint8_t {
  Face = 0,    // interior of a face (owner = face id)
  Edge = 1,    // on an edge, not at a corner (owner = edge id)
  Corner = 2,  // at a B-rep vertex (owner = vertex id); vertices[owner].isCorner
               // tells whether it is a sharp corner or a smooth / pass-through vertex
};

// Classification of an edge shared by two faces, from the outward normals.
enum class EdgeKind : std::uint8_t {
  Smooth = 0,   // tangent-continuous (fillet border, split seam): not a feature
  Convex = 1,   // interior dihedral angle < 180° - tol
  Concave = 2,  // interior dihedral angle > 180° + tol
};

// A convex-edge triplet (seed 002 §4.2.1): s on the edge, sLeft and sRight on
// the two incident faces, with s-sLeft and s-sRight perpendicular to the edge
// at s and of equal length. prev / next are the neighbouring samples s', s''
// along the same edge, including the vertex sample at an edge end; core's
// convex-edge fill triangles need them (kNoIndex loses the fills there).
struct Triplet {
  Index s = kNoIndex;
  Index sLeft = kNoIndex;
  Index sRight = kNoIndex;
  Index prev = kNoIndex;
  Index next = kNoIndex;
  std::int32_t edge = -1;  // owner edge id
};

// One edge of the (split) B-rep and its samples in order along the edge,
// including the samples at its two end vertices (corner samples, or the shared
// samples of a pass-through vertex).
struct EdgeInfo {
  EdgeKind kind = EdgeKind::Smooth;
  std::int32_t faceLeft = -1;   // the two incident face ids
  std::int32_t faceRight = -1;
  double length = 0.0;
  double maxDihedralDeviationDeg = 0.0;  // max |180° - dihedral| seen along it
  std::vector<Index> samples;            // ordered along the edge
};

// A vertex of the (split) B-rep (every vertex has one sample).
struct CornerInfo {
  Index sample = kNoIndex;    // the sample at the vertex
  bool isCorner = false;      // a true corner (not a tangent pass-through of one sharp edge chain)
  bool nonConcave = false;    // no ball inside the solid touches it (DESIGN.md §3)
  double ballRadius = 0.0;    // corner ball radius (0 if not a corner)
};

struct SampleSet {
  // --- samples --------------------------------------------------------------
  std::vector<Vec3> points;
  std::vector<SampleKind> kind;      // per point
  std::vector<std::int32_t> owner;   // per point: face / edge / vertex id by kind
  std::vector<std::uint8_t> onConvexEdge;        // per point: 1 if on a convex edge (incl. its end vertices)
  // per point: 1 where the inner axis must attach at a vertex sample: a
  // non-concave corner, or a vertex inside a convex edge chain (pass-through).
  std::vector<std::uint8_t> isNonConcaveCorner;

  std::vector<Triplet> triplets;

  // --- features ---------------------------------------------------------------
  std::vector<EdgeInfo> edges;        // indexed by edge id
  std::vector<CornerInfo> vertices;   // indexed by vertex id

  // --- boundary reconstruction ----------------------------------------------
  // Stitched closed triangle surface over `points` (face-by-face constrained
  // Delaunay, consistently oriented with outward normals).
  std::vector<std::array<Index, 3>> triangles;
  std::vector<std::int32_t> triangleFace;  // per triangle: owning face id
  // Per triangle (optional, empty when unknown, e.g. point clouds): a bound on
  // how far the triangle lies from the face patch it stands for, i.e. on
  // |S(u,v) - T(u,v)| over its UV triangle, S the face's surface and T the
  // affine map onto the triangle (chord error, plus the B-rep tolerances).
  // A point farther than this from every triangle is on the same side of
  // the reconstruction as of the exact surface (the straight-line homotopy
  // from surface to mesh never passes through it): the pair-mesh labels use
  // it to skip the exact classifier (sampling/cell_classification.hpp).
  std::vector<double> triangleDeviation;
  // Per triangle (optional, empty when unknown): 1 if the triangle stands
  // more than 45° off the exact surface normal (a UV triangle at a pole of a
  // degenerate edge that no flip could mend). It stays in the surface, which
  // must be closed, but its normal is no tangent plane: umbrellas skip it.
  std::vector<std::uint8_t> triangleOffSurface;
  // Umbrella of sample i = triangles umbrellaTriangles[umbrellaOffsets[i] .. umbrellaOffsets[i+1]).
  std::vector<Index> umbrellaOffsets;
  std::vector<Index> umbrellaTriangles;

  // --- context ------------------------------------------------------------------
  double spacing = 0.0;          // target spacing h used
  Vec3 bboxMin{0, 0, 0};
  Vec3 bboxMax{0, 0, 0};
  int faceCount = 0;

  std::size_t size() const { return points.size(); }
  double bboxDiagonal() const;
  // Build umbrellaOffsets/umbrellaTriangles from `triangles`.
  void buildUmbrellas();
  // Throws std::runtime_error naming the first inconsistency (sizes, indices).
  void validate() const;
};

}  // namespace cadmedial
