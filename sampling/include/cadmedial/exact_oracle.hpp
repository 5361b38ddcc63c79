// Exact distance to a B-rep solid and exact inside test: the reference that
// evaluation (DESIGN.md §6) measures medial axes against.
//
// A fine BRepMesh triangulation in a bounding-volume tree only *selects*
// candidate faces (those whose mesh distance is within a few mesh deflections
// of the best); the distance itself is computed on the exact OCCT geometry of
// those faces: a Newton projection started from the mesh foot point
// (catches the degenerate cases where the analytic solver gives up, e.g. a
// point on a torus' core circle), all extrema on the surface
// (Extrema_ExtPS) on analytic faces and where Newton finds nothing (on
// B-spline faces first Newton from the face's other triangles near p: the
// global search costs milliseconds there), each kept if its UV lies in the
// face (FaceUVClassifier: FClass2d, split per hole), and the minima on the
// face's edges and vertices for feet on the face boundary.
#pragma once

#include <memory>
#include <vector>

#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>

namespace cadmedial {

// A point of the boundary seen from a query point.
struct BoundaryPoint {
  gp_Pnt point;
  double distance = 0;
  int face = -1;  // face id (TopExp::MapShapes order of solid()), -1 for edge/vertex points
  int edge = -1;  // edge id when the point was found as a minimum on an edge
  int vertex = -1;
};

struct ExactOracleParams {
  double meshDeflectionFraction = 1e-3;  // BRepMesh linear deflection, × bounding-box diagonal
  double meshAngle = 0.25;               // BRepMesh angular deflection (radians)
  // Faces whose mesh distance is within this many deflections of the best
  // mesh distance are checked exactly (the mesh is within ~1 deflection of
  // the surface, so 2 would suffice; 4 leaves room for BRepMesh's estimate).
  double candidateDeflections = 4.0;
};

// Not thread-safe: queries reuse OCCT solver objects held by the oracle.
// Use one copy per thread; copies share the (immutable) mesh and AABB tree and
// build their own solver objects lazily, so copying is cheap.
class ExactOracle {
 public:
  explicit ExactOracle(const TopoDS_Shape& solid, const ExactOracleParams& params = {});
  ExactOracle(const ExactOracle& other);
  ExactOracle& operator=(const ExactOracle&) = delete;
  ~ExactOracle();

  // Inside the solid or within onTolerance of its boundary. Decided by the
  // outward normal at the closest point when the surface is smooth there
  // (inside a face, a seam or a tangent edge), by the side of a sharp edge
  // the closest point is inside of, otherwise by BRepClass3d_SolidClassifier.
  // If `distance` is given, the exact distance to the boundary (computed on
  // the way) is stored there.
  bool inside(const gp_Pnt& p, double onTolerance = 0, double* distance = nullptr);
  // The side of p known from the oracle's mesh alone: -1 inside, +1
  // outside, 0 when the mesh cannot tell. It tells when every face is meshed
  // and the mesh is closed and wound outward (checked once), p is more than
  // `margins` × (2 mesh deflections) and 4 B-rep tolerances from the mesh,
  // so the exact surface cannot pass between p and the mesh (the bound the
  // distance queries already trust to pick candidate faces), and the
  // triangles at p's nearest mesh point lie along the exact surface, on
  // faces meshed to their exact area: then the angle-weighted pseudo-normal
  // there gives the side. Microseconds against the tens to hundreds of
  // inside(): the run's check of the walk asks it first.
  int meshSide(const gp_Pnt& p, double margins = 4.0);
  // How many inside() calls of this copy went to the classifier.
  std::size_t classifierQueries() const;

  // Exact unsigned distance from p to the boundary, and a closest point.
  double distance(const gp_Pnt& p);
  BoundaryPoint closestPoint(const gp_Pnt& p);

  // Local minima (and other extrema) of the distance from p on faces, edges
  // and vertices that are within distance(p) + slack, closest first. Faces
  // are searched from several starts (the mesh triangles near p), so a
  // degenerate minimum - from a point on a torus' core circle, a whole tube
  // circle - shows up as several points. Empty only without faces.
  std::vector<BoundaryPoint> nearPoints(const gp_Pnt& p, double slack);

  double diagonal() const;                   // of the solid's bounding box
  gp_Pnt boxMin() const;
  gp_Pnt boxMax() const;
  double meshDeflection() const;             // largest deflection BRepMesh reported
  std::size_t meshTriangles() const;
  int faceCount() const;
  int unmeshedFaces() const;                 // checked on every query (no mesh to select them)
  // The solid the oracle works on: a copy of the input (closed faces are
  // not split, so every edge keeps its exact curve), carrying the mesh.
  const TopoDS_Shape& solid() const;

  // Area-uniform points on the boundary: mesh triangles picked by area, a
  // uniform point in the triangle mapped through its UV onto the exact
  // surface. Deterministic for a given seed.
  std::vector<gp_Pnt> sampleBoundary(std::size_t count, unsigned seed) const;

 private:
  struct Shared;
  struct Workspace;
  std::vector<BoundaryPoint> query(const gp_Pnt& p, double slack, bool nearOnly);
  std::shared_ptr<const Shared> shared_;
  std::unique_ptr<Workspace> work_;
};

}  // namespace cadmedial
