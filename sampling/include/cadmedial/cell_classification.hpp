// Inner / outer label of every Delaunay cell for the pair-mesh (DESIGN.md §5):
// a cell is inner iff its Voronoi vertex (circumcenter) lies inside the solid,
// decided by OCCT's exact classifier (BRepClass3d_SolidClassifier). Points on
// the boundary (within `onTolerance`) count as outer.
#pragma once

// CGAL (delaunay.hpp) before OCCT: OCCT's Handle macro breaks CGAL.
#include "cadmedial/delaunay.hpp"

#include <cstdint>
#include <vector>

#include <TopoDS_Shape.hxx>

namespace cadmedial {

struct CellClassification {
  std::vector<std::uint8_t> inner;  // per cell id
  std::size_t exactQueries = 0;     // cells sent to the OCCT classifier
  std::size_t decidedByMesh = 0;    // cells decided by the reconstruction
};

// One classifier per thread (TBB); cells whose centre lies outside the
// solid's bounding box or whose radius exceeds its diagonal (an empty ball
// centred inside would hold every sample) are outer without a query.
//
// With `samples` (the SampleSet the triangulation was built on) and a closed
// manifold reconstruction: centres farther than `band` from the reconstructed
// surface take its side (CGAL point-in-mesh, exact on the mesh); only those
// within `band` go to the OCCT classifier. The reconstruction's triangles
// have their vertices on the exact surface and deviate from it by their
// chord error, well below band = h / 2 for the sampling's spacing h.
CellClassification classifyCellsBySolid(const DelaunayVoronoi& dv, const TopoDS_Shape& solid,
                                        const SampleSet* samples = nullptr, double band = 0,
                                        double onTolerance = 1e-9);

}  // namespace cadmedial
