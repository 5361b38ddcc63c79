// Per-sample umbrella data for the Angle and Ratio conditions (DESIGN.md §4.2),
// computed once so the edge test is a tight loop.
#pragma once

#include <array>
#include <cstdint>
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

  // One-sided umbrellas (concave-edge samples of a B-rep, see
  // addConcaveEdgeWedges): sideStart[i] is kNoIndex for an ordinary sample;
  // otherwise normals[offsets[i] + k] has the corner wedge at sample i of its
  // triangle in wedges[sideStart[i] + k] (unit rays toward its two other
  // vertices). A face of such a sample lies on one side of the edge only, so
  // its triangles judge only the edges that head over them.
  std::vector<Index> sideStart;
  std::vector<std::array<std::array<double, 3>, 2>> wedges;
};

// Uses samples.triangles and samples.umbrellaOffsets/umbrellaTriangles (built
// with SampleSet::buildUmbrellas() when empty). Samples inside concave B-rep
// edges (samples.kind / owner / edges) get one-sided umbrellas. Triangles
// flagged in samples.triangleOffSurface are left out.
UmbrellaData computeUmbrellaData(const SampleSet& samples);

// 1 for each sample inside a concave B-rep edge (not at its end vertices).
std::vector<std::uint8_t> concaveEdgeSamples(const SampleSet& samples);

// The same from explicit umbrellas: sample i's umbrella is
// triangles[members[offsets[i] .. offsets[i+1])] (offsets.size() = samples + 1).
// Used by CAD_MEDIAL (reconstruction triangles) and by MEDIAL (Delaunay
// triangles cut by the tangent polygon, medial_umbrellas.hpp).
// oneSided (optional, per sample): which samples get one-sided umbrellas.
// offSurface (optional, per triangle): triangles to leave out, as if
// degenerate (SampleSet::triangleOffSurface).
UmbrellaData umbrellaDataFromTriangles(const std::vector<Vec3>& points, const std::vector<std::array<Index, 3>>& triangles,
                                       const std::vector<Index>& offsets, const std::vector<Index>& members,
                                       const std::vector<std::uint8_t>* oneSided = nullptr,
                                       const std::vector<std::uint8_t>* offSurface = nullptr);

// The Angle condition's question for one umbrella triangle of sample p: is
// the Delaunay edge direction `dir` (not normalised) within the triangle's
// corner wedge at p, widened by `slackCos` (cosine of the widening angle),
// once projected onto the triangle's plane?
bool headsOverWedge(const std::array<std::array<double, 3>, 2>& wedge, const std::array<double, 3>& normal,
                    const double dir[3], double slackCos);

}  // namespace cadmedial
