// Axis-aligned bounding box of a run of points.
#pragma once

#include <algorithm>
#include <cmath>

#include "cadmedial/sample_set.hpp"

namespace cadmedial {

struct PointBox {
  Vec3 lo{0, 0, 0}, hi{0, 0, 0};
  double side(int k) const { return hi[k] - lo[k]; }
  double widestSide() const { return std::max({side(0), side(1), side(2)}); }
  double diagonal() const { return std::sqrt(side(0) * side(0) + side(1) * side(1) + side(2) * side(2)); }
};

// The box of [begin, end); a zero box at the origin when the run is empty.
inline PointBox boxOf(const Vec3* begin, const Vec3* end) {
  PointBox b;
  if (begin == end) return b;
  b.lo = b.hi = *begin;
  for (const Vec3* p = begin; p != end; ++p)
    for (int k = 0; k < 3; ++k) b.lo[k] = std::min(b.lo[k], (*p)[k]), b.hi[k] = std::max(b.hi[k], (*p)[k]);
  return b;
}

// b grown by d on every side.
inline PointBox grown(PointBox b, double d) {
  for (int k = 0; k < 3; ++k) b.lo[k] -= d, b.hi[k] += d;
  return b;
}

// Do the boxes meet (touching counts)?
inline bool boxesMeet(const PointBox& a, const PointBox& b) {
  for (int k = 0; k < 3; ++k)
    if (b.hi[k] < a.lo[k] || a.hi[k] < b.lo[k]) return false;
  return true;
}

}  // namespace cadmedial
