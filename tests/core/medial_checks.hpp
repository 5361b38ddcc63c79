// Measurements of a MedialResult against exact geometry, shared by the tests.
#pragma once

#include <functional>
#include <vector>

#include "cadmedial/medial.hpp"

namespace cadmedial::testing {

struct Stats {
  std::size_t count = 0;
  double median = 0, p99 = 0, max = 0;
};
Stats statsOf(std::vector<double> v);

// Box [0,a]x[0,b]x[0,c]: over the Voronoi vertices (radius > 0) of the complex,
// |d1 - d2| (d1 <= d2 the two smallest distances to the six face planes) and
// |r - d1|; `outside` counts vertices not strictly inside the box.
struct BoxMedialness {
  Stats tie, radius;
  std::size_t outside = 0;
};
BoxMedialness boxMedialness(const MedialResult& r, const Vec3& size);

// Share of samples of `ids` that are vertices of the complex.
double attachedShare(const MedialResult& r, const std::vector<Index>& ids);

std::string summary(const MedialResult& r);

}  // namespace cadmedial::testing
