// Meshes compared as sets, free of the order the code happens to emit them in.
#pragma once

#include <algorithm>
#include <array>
#include <set>
#include <vector>

#include "cadmedial/sample_set.hpp"

namespace cadmedial::testing {

// Triangles up to rotation of their vertex order (orientation kept).
inline std::multiset<std::array<Index, 3>> orientedSet(const std::vector<std::array<Index, 3>>& tris) {
  std::multiset<std::array<Index, 3>> out;
  for (auto t : tris) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.insert(t);
  }
  return out;
}

}  // namespace cadmedial::testing
