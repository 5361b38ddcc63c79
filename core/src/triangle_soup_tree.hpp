// Private to core: the AABB tree over the reconstruction's triangles that
// cell_sides.cpp and reconstruction_sides.cpp query (distances, segments,
// ray parity).
#pragma once

#include <array>
#include <memory>
#include <utility>
#include <vector>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/internal/Side_of_triangle_mesh/Point_inside_vertical_ray_cast.h>

#include "cadmedial/delaunay.hpp"
#include "cadmedial/reconstruction_sides.hpp"
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

// The reconstruction's triangles in an AABB tree, with the axes cyclically
// permuted so that z is the shortest extent of the samples' bounding box.
// CGAL casts a vertical (+z) ray first; along the long axis of a thin-walled
// part that ray runs inside the wall past thousands of triangle boxes (the
// bottle: 3/4 of the pipeline time). Parity does not depend on the ray
// direction and a cyclic permutation is exact, so answers and distances are
// the same. Built once per pipeline run: cell_sides and reconstruction_sides
// share it (building it is ~1 s at 10^6 triangles).
struct SoupTree {
  int up = 2;  // the input axis that becomes z
  Triangles triangles;
  Tree tree;  // holds iterators into `triangles`: never copy or move a SoupTree
  std::vector<std::array<Index, 3>> corners;  // per triangle, its samples
  // Per sample, the triangles at it: sampleTriangles[firstTriangle[s] ..
  // firstTriangle[s + 1]), the SampleSet's umbrella lists.
  std::vector<Index> firstTriangle, sampleTriangles;

  explicit SoupTree(const SampleSet& samples) {
    for (int k = 0; k < 3; ++k)
      if (samples.bboxMax[k] - samples.bboxMin[k] < samples.bboxMax[up] - samples.bboxMin[up]) up = k;
    triangles.reserve(samples.triangles.size());
    for (const auto& t : samples.triangles)
      triangles.emplace_back(permuted(samples.points[t[0]]), permuted(samples.points[t[1]]),
                             permuted(samples.points[t[2]]));
    tree.insert(triangles.begin(), triangles.end());
    tree.build();
    corners = samples.triangles;
    if (samples.umbrellaOffsets.size() == samples.size() + 1) {
      firstTriangle = samples.umbrellaOffsets;
      sampleTriangles = samples.umbrellaTriangles;
    } else {  // not built yet (SampleSet::buildUmbrellas)
      SampleSet rebuilt;
      rebuilt.points = samples.points;
      rebuilt.triangles = samples.triangles;
      rebuilt.buildUmbrellas();
      firstTriangle = std::move(rebuilt.umbrellaOffsets);
      sampleTriangles = std::move(rebuilt.umbrellaTriangles);
    }
  }

  // The triangle with exactly these three samples as corners, or kNoIndex.
  Index triangleWith(Index a, Index b, Index c) const {
    if (firstTriangle.empty() || a >= firstTriangle.size() - 1) return kNoIndex;
    for (Index k = firstTriangle[a]; k < firstTriangle[a + 1]; ++k) {
      const auto& t = corners[sampleTriangles[k]];
      const bool hasB = t[0] == b || t[1] == b || t[2] == b, hasC = t[0] == c || t[1] == c || t[2] == c;
      if (hasB && hasC && b != c) return sampleTriangles[k];
    }
    return kNoIndex;
  }
  SoupTree(const SoupTree&) = delete;
  SoupTree& operator=(const SoupTree&) = delete;

  Kernel::Point_3 permuted(const Vec3& p) const { return {p[(up + 1) % 3], p[(up + 2) % 3], p[up]}; }
};

}  // namespace cadmedial::soup

namespace cadmedial {

// reconstructionSides (reconstruction_sides.hpp) on a tree built by the
// caller; with the cells' link groups when the caller has them for this
// tree and dv, else they are made here (and moved into `made` if given).
ReconstructionSides reconstructionSides(const soup::SoupTree& mesh, const DelaunayVoronoi& dv,
                                        const std::vector<double>& deviation,
                                        const std::vector<std::uint8_t>* wanted,
                                        const ReconstructionLinks* links = nullptr,
                                        ReconstructionLinks* made = nullptr);

}  // namespace cadmedial
