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

}  // namespace cadmedial
