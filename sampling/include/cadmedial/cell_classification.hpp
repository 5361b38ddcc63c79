// Inner / outer label of every Delaunay cell for the pair-mesh (DESIGN.md §5):
// a cell is inner iff its Voronoi vertex (circumcenter) lies inside the solid,
// decided by the exact classifier (SolidPointClassifier: the answers of
// OCCT's BRepClass3d_SolidClassifier, faster on many faces). Points on the
// boundary (within `onTolerance`) count as outer.
#pragma once

// CGAL (delaunay.hpp) before OCCT: OCCT's Handle macro breaks CGAL.
#include "cadmedial/cell_sides.hpp"
#include "cadmedial/delaunay.hpp"

#include <cstdint>
#include <vector>

#include <TopoDS_Shape.hxx>

namespace cadmedial {

struct CellClassification {
  std::vector<std::uint8_t> inner;  // per cell id
  std::size_t exactQueries = 0;     // cells sent to the exact classifier
  std::size_t decidedByMesh = 0;    // cells decided by the reconstruction
  std::size_t rayCasts = 0;         // ray parity tests on the reconstruction (one per group of cells)
  std::size_t segmentTests = 0;     // centre-to-centre segments tested against the reconstruction
  // Seconds of the reconstruction's part: near test, segment links, ray casts.
  double nearSeconds = 0, linkSeconds = 0, raySeconds = 0;
};

// One classifier per thread (TBB); cells whose centre lies outside the
// solid's bounding box or whose radius exceeds its diagonal (an empty ball
// centred inside would hold every sample) are outer without a query.
//
// With `samples` (the SampleSet the triangulation was built on) and a closed
// manifold reconstruction: a centre farther from every triangle t than t's
// deviation from its face patch (SampleSet::triangleDeviation, measured at
// sampling; planar faces: their tolerance) is on the same side of the
// reconstruction as of the solid, and takes the reconstruction's side
// (core/reconstruction_sides.hpp: groups of cells linked by centre-to-centre
// segments that cross no triangle, one exact ray parity test per group).
// Only the others go to the exact classifier. Without triangleDeviation a
// uniform `band` stands for it (0: every cell goes to the exact classifier).
// `prepared`: the CellSideInputs built from the same samples for the
// CAD_MEDIAL run on dv, if there is one; its surface check, tree and link
// groups are used instead of new ones (same answers).
CellClassification classifyCellsBySolid(const DelaunayVoronoi& dv, const TopoDS_Shape& solid,
                                        const SampleSet* samples = nullptr, double band = 0,
                                        double onTolerance = 1e-9, const CellSideInputs* prepared = nullptr);

}  // namespace cadmedial
