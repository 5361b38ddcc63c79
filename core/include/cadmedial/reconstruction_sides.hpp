// Which side of the closed reconstruction every Voronoi vertex (cell
// circumcenter) lies on, and whether that side is certainly the exact
// solid's side too. Used by the pair-mesh labels (sampling's
// classifyCellsBySolid) to send only the uncertain cells to OCCT.
//
// Certainty: with SampleSet::triangleDeviation d_t (a bound on the distance
// between triangle t and its face patch), a point farther than d_t from every
// triangle t has the same winding number for the mesh and the exact surface,
// since the straight-line homotopy between them stays within d_t of each
// triangle. Planar faces have d_t = their B-rep tolerance, so on prismatic
// parts almost no cell is uncertain.
//
// Side: exact on the mesh, but with one ray parity test per group of cells
// instead of one per cell. Two cells whose circumcenters are joined by a
// segment that touches no reconstruction triangle (CGAL AABB tree, exact
// predicates, or farther from the samples than any triangle there reaches)
// are on the same side; the groups are the connected components
// of those links over the Delaunay adjacency. A group holding a centre
// outside the mesh's bounding box is outside; the others get one ray cast.
#pragma once

#include <cstdint>
#include <vector>

#include "cadmedial/delaunay.hpp"
#include "cadmedial/sample_set.hpp"

namespace cadmedial {

enum ReconstructionSide : std::uint8_t {
  kReconstructionOutside = 0,  // outside the mesh, and so outside the solid
  kReconstructionInside = 1,   // inside the mesh, and so inside the solid
  kReconstructionNear = 2,     // within some triangle's deviation: ask the exact classifier
  kReconstructionSkipped = 3,  // not wanted (or infinite cell): no answer
};

struct ReconstructionSides {
  std::vector<std::uint8_t> side;  // per cell id, a ReconstructionSide
  std::size_t nearCells = 0;
  // Circumcenter-to-circumcenter segments tested against a triangle or the
  // tree (not those the triangles' reach clears, reconstruction_sides.cpp).
  std::size_t segmentTests = 0;
  std::size_t rayCasts = 0;      // one per group without a centre outside the mesh's box
  std::size_t groups = 0;
  // Seconds: tree and near test, segment links, ray casts and answers.
  double nearSeconds = 0, linkSeconds = 0, raySeconds = 0;
};

// The groups of cells above, for one Delaunay and one closed
// reconstruction. They do not depend on the deviations, so one set serves
// every side question on that Delaunay (CellSideInputs::keepLinks: the
// CAD_MEDIAL cell sides and the pair-mesh labels).
struct ReconstructionLinks {
  std::vector<Index> group;  // per cell id: its group's root cell
  std::size_t segmentTests = 0;
  double seconds = 0;
};

// samples.triangles must form a closed manifold (checkSurfaceMesh); the
// caller checks. dv is meant to be the Delaunay of samples.points: its
// short cuts (reconstruction_sides.cpp) rely on the triangles' corners
// being its vertices, and are not taken when the sample counts differ. deviation: per triangle (samples.triangleDeviation, or a
// uniform band when that is empty). wanted (per cell id, optional): cells to
// answer; the others are still used to link groups.
ReconstructionSides reconstructionSides(const DelaunayVoronoi& dv, const SampleSet& samples,
                                        const std::vector<double>& deviation,
                                        const std::vector<std::uint8_t>* wanted = nullptr);

}  // namespace cadmedial
