// MEDIAL (seed 000, Dey & Zhao): the medial axis of a surface given only by
// sample points - scanned parts, point clouds, the vertices of a triangle
// mesh. CAD_MEDIAL (medial.hpp) extends it; both share the Delaunay/Voronoi
// diagram, the Angle [θ] / Ratio [ρ] selection and the closure into sheets.
// Only the umbrellas differ: here they come from the Voronoi diagram itself
// (poles, tangent polygons: medial_poles.hpp, medial_umbrellas.hpp).
//
//   PointMedialResult r = computeMedial(points);                       // whole axis
//   PointMedialResult r = computeMedial(points, params, meshTriangles); // inner axis
//
// Output: the closure of the Voronoi facets dual to the selected Delaunay
// edges. Without a mesh that is the whole medial axis, inner and outer; the
// unbounded facets (they reach infinity) are left out and counted. With the
// triangles of a closed, consistently oriented mesh over the points, only the
// inner axis is kept: facets whose Voronoi vertices all lie inside the mesh
// (CGAL Side_of_triangle_mesh, as in cell_sides.hpp). A mesh that is not
// closed and oriented gives the whole axis, and axisNote says why.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "cadmedial/medial.hpp"
#include "cadmedial/surface_mesh_checks.hpp"

namespace cadmedial {

enum class MedialAxisPart : unsigned char { Whole = 0, Inner = 1 };

struct PointMedialInfo {
  MedialAxisPart part = MedialAxisPart::Whole;
  std::string axisNote;            // one line: which part was output and why
  bool meshGiven = false;
  SurfaceMeshStats mesh;           // of the given triangles (when meshGiven)
  std::size_t unboundedCells = 0;  // samples on the convex hull (pole at infinity)
  std::size_t zeroPoleVectors = 0;
  std::size_t emptyUmbrellas = 0;  // tangent polygon crossed no Voronoi edge
  std::size_t umbrellaTriangles = 0;
  std::size_t unboundedFacetsDropped = 0;
  std::size_t outsideFacetsDropped = 0;  // inner axis only: a Voronoi vertex outside the mesh
  double polesSeconds = 0, tangentUmbrellaSeconds = 0, insideSeconds = 0;
};

struct PointMedialResult : MedialResult {
  PointMedialInfo cloud;
};

// A SampleSet for bare points (every sample a face sample of face 0, no
// features) and optional surface triangles; bounding box filled.
SampleSet pointCloudSamples(const std::vector<Vec3>& points, const std::vector<std::array<Index, 3>>& triangles = {});

// Throws std::invalid_argument on non-finite coordinates, bad parameters or
// triangle indices out of range. Fewer than 4 points, or points that span
// fewer than 3 dimensions, give an empty result (axisNote says so).
PointMedialResult computeMedial(const std::vector<Vec3>& points, const MedialParams& params = MedialParams::pointCloud(),
                                const std::vector<std::array<Index, 3>>& meshTriangles = {});

}  // namespace cadmedial
