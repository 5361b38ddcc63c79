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

// One classifier per thread (TBB); cells whose centre lies outside the
// solid's bounding box or whose radius exceeds its diagonal (an empty ball
// centred inside would hold every sample) are outer without a query.
std::vector<std::uint8_t> classifyCellsBySolid(const DelaunayVoronoi& dv, const TopoDS_Shape& solid,
                                               double onTolerance = 1e-9);

}  // namespace cadmedial
