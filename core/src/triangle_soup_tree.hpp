// Private to core: the AABB tree over the reconstruction's triangles that
// cell_sides.cpp and reconstruction_sides.cpp query (distances, segments,
// ray parity).
#pragma once

#include <vector>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/internal/Side_of_triangle_mesh/Point_inside_vertical_ray_cast.h>

#include "cadmedial/delaunay.hpp"
#include "cadmedial/sample_set.hpp"

namespace cadmedial::soup {

using Kernel = DelaunayVoronoi::Kernel;
// Triangles stored in the tree's primitives (contiguous, no face -> vertex ->
// point indirection per ray-box-triangle test).
using Triangles = std::vector<Kernel::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator, CGAL::Tag_true>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
// What CGAL::Side_of_triangle_mesh does after its bounding-box test (that
// class insists on building its tree from a face graph).
using RayCast = CGAL::internal::Point_inside_vertical_ray_cast<Kernel, Tree>;

}  // namespace cadmedial::soup
