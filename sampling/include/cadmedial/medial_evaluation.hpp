// Measuring a medial axis against the exact B-rep (DESIGN.md §6): inside,
// medialness, coverage, attachment and topology, each with a pass/fail
// threshold. Works on a plain polygon complex (MedialMesh), so it does not
// depend on how the axis was computed. Distances and the inside test come
// from ExactOracle (exact OCCT geometry); tol = toleranceFraction × the
// bounding-box diagonal. Vertices used by no polygon are ignored everywhere.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>

namespace cadmedial {

// Where a medial polygon came from (the `provenance` PLY property).
enum class MedialProvenance : std::uint8_t {
  VoronoiFacet = 0,        // Voronoi facet dual to a Delaunay edge
  ConvexEdgeTriangle = 1,  // s v1 v2 of ProcConvexEdges
  ConvexEdgeFill = 2,      // s s' v1 / s s'' v2 of ProcConvexEdges
  CornerTriangle = 3,      // p v1 v2 of ProcNonconcaveCorners
  HoleFill = 4,            // a short hole in a sheet, closed (fillShortHoles)
};

// An indexed polygon complex with a medial radius per vertex.
struct MedialMesh {
  std::vector<std::array<double, 3>> vertices;
  std::vector<double> radius;  // per vertex, >= 0 (0 on edges and corners of the B-rep)
  // Polygon i = polygonVertices[polygonOffsets[i] .. polygonOffsets[i+1]).
  std::vector<std::uint32_t> polygonOffsets{0};
  std::vector<std::uint32_t> polygonVertices;
  std::vector<std::int32_t> sheet;                 // per polygon
  std::vector<MedialProvenance> provenance;        // per polygon

  std::size_t polygonCount() const { return polygonOffsets.size() - 1; }
  std::uint32_t addVertex(const std::array<double, 3>& p, double r);
  void addPolygon(const std::vector<std::uint32_t>& corners, std::int32_t sheetId,
                  MedialProvenance origin = MedialProvenance::VoronoiFacet);
  // Throws std::invalid_argument naming the first inconsistency.
  void validate() const;
};

// Pass/fail limits. Lengths are in units of the tolerance tol.
struct EvaluationThresholds {
  double minInsideShare = 0.999;
  double maxMedialnessMedianTol = 1.0;  // median |dist - r| <= 1 tol
  double maxMedialnessP90Tol = 2.0;     // 90th percentile <= 2 tol
  double minTwoContactShare = 0.9;
  double minCoverage = 0.99;
  double minEdgeAttachment = 0.99;
  double minCornerAttachment = 1.0;
};

struct EvaluationParams {
  double toleranceFraction = 0.005;  // tol = this × bounding-box diagonal
  // Inside test: points this close to the boundary count as inside (the axis
  // touches convex edges and corners), × diagonal.
  double onBoundaryFraction = 1e-6;
  std::size_t boundaryPoints = 20000;   // area-uniform boundary points for coverage
  double contactAngleDeg = 10.0;        // "two distinct closest points": angle they subtend at v
  std::size_t topologyCoreLimit = 50000;  // β2 rank computation skipped above this many core polygons
  double smoothAngleDeg = 1.0;          // edge classification, as in sampling
  double thetaDeg = 5.0;                // the run's Angle threshold: creases turning < 2θ are shallow
  unsigned seed = 1;
  bool parallel = true;                 // TBB over vertices / triangles / boundary points
  EvaluationThresholds thresholds;
};

// Polygons are fan-triangulated; each triangle is tested at its three
// degree-2 Gauss points (barycentric 2/3, 1/6, 1/6), each standing for a third
// of its area. Points within onBoundaryFraction × diagonal of the boundary
// count as inside (the axis touches convex edges and corners).
struct InsideMetric {
  double share = 0;        // inside area / total area (1 if the axis has no area)
  double area = 0, outsideArea = 0;
  std::size_t triangles = 0, points = 0, outsidePoints = 0;
  // Largest distance of an outside test point from the boundary / diagonal
  // (for a fan triangle wholly outside: an upper bound, its centroid's distance + its reach).
  double maxOutsideDepth = 0;
};

// Over used vertices with r > 0: |dist(v, B-rep) − r(v)| / diagonal.
// Two contacts: among the boundary points ExactOracle::nearPoints(v, tol)
// returns - stationary points of the distance from v on each face (all
// extrema, from several starts, so a degenerate minimum such as a torus'
// tube circle gives several), minima on sharp edges and at vertices that
// are minima over the whole boundary, all within dist(v) + tol - two
// subtend an angle >= contactAngleDeg at v.
struct MedialnessMetric {
  std::size_t vertices = 0;  // used vertices with r > 0
  double median = 0, p90 = 0, max = 0;  // |dist(v, B-rep) - r(v)| / diagonal
  std::size_t twoContacts = 0;
  double twoContactShare = 0;
};

// boundaryPoints area-uniform points b on the exact faces; b is covered when
// min over used vertices of (|b − v| − r(v)) <= tol (branch and bound over a
// bounding-volume tree of the balls).
struct CoverageMetric {
  std::size_t points = 0, covered = 0;
  double share = 0;
  double maxGap = 0;  // max over uncovered points of min_v(|b - v| - r(v)) / diagonal (0 if all covered)
};

// Convex edges (exact classification of the unsplit solid, as
// classifyFeatures counts them) sampled every tol of arc length; a point is
// attached when within tol of a fan triangle (exact point-triangle distance,
// CGAL AABB tree). Non-concave corners likewise.
// Shallow creases: where the two faces' outward normals differ by less than
// 2θ, the Angle condition cannot select the Voronoi facet that bisects the
// crease (seed 002 §4: "if the dihedral angle at the convex edge e is more
// than π − 2θ, the Angle condition ... cannot capture" it), so the θ-filtered
// axis ends short of such length by design. It is measured apart and left out
// of edgeShare; so is a corner that only shallow convex edges reach.
struct AttachmentMetric {
  int convexEdges = 0;
  double convexLength = 0;
  double steepLength = 0, attachedLength = 0, edgeShare = 1;   // crease turn >= 2θ
  double shallowLength = 0, shallowAttachedLength = 0;         // crease turn < 2θ (not in edgeShare)
  int corners = 0, attachedCorners = 0;  // non-concave corners reached by a steep convex edge
  int shallowCorners = 0, shallowAttachedCorners = 0;  // reached by shallow ones only (not in cornerShare)
  double cornerShare = 1;
};

struct TopologyMetric {
  // Medial complex (vertices used by polygons, distinct polygon edges, polygons).
  std::size_t vertices = 0, edges = 0, polygons = 0, corePolygons = 0;
  long long euler = 0, beta0 = 0, beta1 = -1, beta2 = -1;  // -1: not computed (core too big)
  // Solid: β0 = 1, β1 = sum of shell genera, β2 = shells - 1.
  int shells = 0;
  long long solidBeta0 = 1, solidBeta1 = 0, solidBeta2 = 0;
  bool matches = false;  // β0, β1 (and β2 when known) equal
};

// Every threshold of EvaluationThresholds; an axis without vertices of
// positive radius fails medialness and contacts.
struct EvaluationVerdict {
  bool inside = false, medialness = false, twoContacts = false, coverage = false, edges = false, corners = false,
       topology = false;
  bool all() const { return inside && medialness && twoContacts && coverage && edges && corners && topology; }
};

struct EvaluationReport {
  double diagonal = 0, tolerance = 0;
  std::size_t vertices = 0, unusedVertices = 0, polygons = 0, sheets = 0;
  InsideMetric inside;
  MedialnessMetric medialness;
  CoverageMetric coverage;
  AttachmentMetric attachment;
  TopologyMetric topology;
  EvaluationVerdict pass;
  EvaluationParams params;
  double secondsSetup = 0, secondsInside = 0, secondsMedialness = 0, secondsCoverage = 0, secondsAttachment = 0,
         secondsTopology = 0;
};

// Prepares everything that depends only on the solid (exact oracle, boundary
// points, convex-edge points, corners, the solid's Betti numbers), so several
// axes of one solid can be evaluated without redoing it. evaluate() may run
// concurrently on one evaluator (it copies the oracle per thread).
class MedialEvaluator {
 public:
  explicit MedialEvaluator(const TopoDS_Shape& solid, const EvaluationParams& params = {});
  ~MedialEvaluator();
  EvaluationReport evaluate(const MedialMesh& mesh) const;
  double diagonal() const;
  double tolerance() const;

 private:
  struct Prepared;
  std::unique_ptr<Prepared> prepared_;
};

EvaluationReport evaluateMedial(const TopoDS_Shape& solid, const MedialMesh& mesh, const EvaluationParams& params = {});

// Betti numbers of a polygon complex over Z2 (only the topology fields of
// the medial complex are filled). β0 by union-find over the polygon edges;
// β2 = dim of the Z2 cycle space of the 2-core left after collapsing every
// polygon with a free edge (-1 if that core has more than coreLimit
// polygons); β1 = β0 + β2 − χ with χ = V − E + F.
TopologyMetric medialComplexTopology(const MedialMesh& mesh, std::size_t coreLimit);

// Betti numbers of a solid from its closed boundary shells: β0 = 1,
// β1 = Σ genus, β2 = shells − 1. A shell's genus is (2 − χ)/2 with
// χ = V − E + F − Σ(wires − 1) (seams counted as edges, degenerated edges
// not): every face cut along its seams is taken as a disc with one hole per
// inner wire, which holds for faces of analytic and B-spline surfaces as
// OCCT builds them. beta1 = -1 if some shell's χ is odd or above 2.
struct SolidBetti {
  int shells = 0;
  long long beta0 = 1, beta1 = 0, beta2 = 0;
};
SolidBetti solidBettiNumbers(const TopoDS_Shape& solid);

}  // namespace cadmedial
