// The distinct undirected edges among many uses of vertex pairs (polygon
// sides, triangle sides), numbered in order of first use, in linear time.
#pragma once

#include <array>
#include <vector>

#include "cadmedial/sample_set.hpp"

namespace cadmedial {

struct UniqueEdges {
  std::vector<std::array<Index, 2>> edges;  // (lower, higher) vertex, in order of first use
  std::vector<Index> useEdge;               // the edge of each use
};

// uses[u] = the two vertices (below vertexCount, any order) of use u.
// A use with equal ends is an edge of its own like any other.
UniqueEdges findUniqueEdges(std::size_t vertexCount, const std::vector<std::array<Index, 2>>& uses);

}  // namespace cadmedial
