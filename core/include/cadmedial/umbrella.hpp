// Per-sample umbrella data for the Angle and Ratio conditions (DESIGN.md §4.2),
// computed once so the edge test is a tight loop.
#pragma once

#include <array>
#include <vector>

#include "cadmedial/sample_set.hpp"

namespace cadmedial {

struct UmbrellaData {
  // Unit normals of the non-degenerate umbrella triangles of sample i:
  // normals[offsets[i] .. offsets[i+1]). Orientation is irrelevant (the
  // conditions use the acute angle between lines).
  std::vector<Index> offsets;
  std::vector<std::array<double, 3>> normals;
  // Largest circumradius over the umbrella of sample i (0 if the umbrella is empty).
  std::vector<double> maxCircumradius;
  // Umbrella triangles skipped because they have (numerically) zero area.
  std::size_t degenerateTriangles = 0;
  // Samples with no usable umbrella triangle: they can never satisfy a condition
  // themselves (an edge pq can still be selected through q).
  std::size_t samplesWithoutUmbrella = 0;
};

// Uses samples.triangles and samples.umbrellaOffsets/umbrellaTriangles (built
// with SampleSet::buildUmbrellas() when empty).
UmbrellaData computeUmbrellaData(const SampleSet& samples);

// The same from explicit umbrellas: sample i's umbrella is
// triangles[members[offsets[i] .. offsets[i+1])] (offsets.size() = samples + 1).
// Used by CAD_MEDIAL (reconstruction triangles) and by MEDIAL (Delaunay
// triangles cut by the tangent polygon, medial_umbrellas.hpp).
UmbrellaData umbrellaDataFromTriangles(const std::vector<Vec3>& points, const std::vector<std::array<Index, 3>>& triangles,
                                       const std::vector<Index>& offsets, const std::vector<Index>& members);

}  // namespace cadmedial
