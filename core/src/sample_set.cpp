#include "cadmedial/sample_set.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace cadmedial {

double SampleSet::bboxDiagonal() const {
  double s = 0;
  for (int k = 0; k < 3; ++k) s += (bboxMax[k] - bboxMin[k]) * (bboxMax[k] - bboxMin[k]);
  return std::sqrt(s);
}

void SampleSet::buildUmbrellas() {
  const std::size_t n = points.size();
  umbrellaOffsets.assign(n + 1, 0);
  for (const auto& t : triangles)
    for (Index v : t) ++umbrellaOffsets[v + 1];
  for (std::size_t i = 0; i < n; ++i) umbrellaOffsets[i + 1] += umbrellaOffsets[i];
  umbrellaTriangles.assign(umbrellaOffsets[n], 0);
  std::vector<Index> fill(umbrellaOffsets.begin(), umbrellaOffsets.end() - 1);
  for (Index t = 0; t < triangles.size(); ++t)
    for (Index v : triangles[t]) umbrellaTriangles[fill[v]++] = t;
}

void SampleSet::validate() const {
  const std::size_t n = points.size();
  auto fail = [](const std::string& what) { throw std::runtime_error("invalid SampleSet: " + what); };
  if (kind.size() != n || owner.size() != n || onConvexEdge.size() != n || isNonConcaveCorner.size() != n)
    fail("per-point arrays differ in size from points");
  for (const auto& p : points)
    for (double c : p)
      if (!std::isfinite(c)) fail("non-finite coordinate");
  auto checkIndex = [&](Index i, const char* what) {
    if (i != kNoIndex && i >= n) fail(std::string(what) + " index out of range");
  };
  for (const auto& t : triplets) {
    if (t.s == kNoIndex || t.sLeft == kNoIndex || t.sRight == kNoIndex) fail("incomplete triplet");
    checkIndex(t.s, "triplet");
    checkIndex(t.sLeft, "triplet");
    checkIndex(t.sRight, "triplet");
    checkIndex(t.prev, "triplet");
    checkIndex(t.next, "triplet");
  }
  for (const auto& t : triangles)
    for (Index v : t) checkIndex(v, "triangle");
  if (triangleFace.size() != triangles.size()) fail("triangleFace size");
  if (!triangleDeviation.empty() && triangleDeviation.size() != triangles.size()) fail("triangleDeviation size");
  if (!triangleOffSurface.empty() && triangleOffSurface.size() != triangles.size()) fail("triangleOffSurface size");
  if (!umbrellaOffsets.empty() && umbrellaOffsets.size() != n + 1) fail("umbrellaOffsets size");
}

}  // namespace cadmedial
