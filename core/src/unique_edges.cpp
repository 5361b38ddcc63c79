#include "cadmedial/unique_edges.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace cadmedial {

// Why not a hash table: at 10^6 samples there are ~1.3e7 polygon sides, and
// a table of that size makes every insert a cache miss (~2.9 s of the sheets
// stage). Here the uses are bucketed by their lower vertex (a counting sort:
// vertices are numbered in the order the polygons meet them, so the buckets
// are filled nearly in order), duplicates are found within each small bucket
// in parallel, and one last pass numbers the edges in order of first use,
// the same numbering a hash table fed in use order gives.
UniqueEdges findUniqueEdges(std::size_t vertexCount, const std::vector<std::array<Index, 2>>& uses) {
  const std::size_t n = uses.size();
  if (n >= kNoIndex) throw std::length_error("too many edge uses for 32-bit indices");
  auto low = [&](std::size_t u) { return std::min(uses[u][0], uses[u][1]); };
  auto high = [&](std::size_t u) { return std::max(uses[u][0], uses[u][1]); };

  std::vector<std::size_t> start(vertexCount + 1, 0);
  for (std::size_t u = 0; u < n; ++u) ++start[low(u) + 1];
  for (std::size_t v = 0; v < vertexCount; ++v) start[v + 1] += start[v];
  std::vector<Index> byLow(n);  // use ids grouped by lower vertex, ascending within a group
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t u = 0; u < n; ++u) byLow[fill[low(u)]++] = static_cast<Index>(u);
  }

  // firstUse[u]: the earliest use of u's edge.
  std::vector<Index> firstUse(n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertexCount, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
    std::vector<std::pair<Index, Index>> sorted;  // (higher vertex, use) of a large bucket
    for (std::size_t v = r.begin(); v != r.end(); ++v) {
      const std::size_t b = start[v], e = start[v + 1];
      if (e - b <= 32) {  // the usual bucket: a few uses, compare pairwise
        for (std::size_t x = b; x < e; ++x) {
          const Index u = byLow[x];
          Index first = u;
          for (std::size_t y = b; y < x; ++y)
            if (high(byLow[y]) == high(u)) {
              first = byLow[y];
              break;
            }
          firstUse[u] = first;
        }
        continue;
      }
      sorted.clear();  // a fan apex or a big polygon's vertex: sort instead
      for (std::size_t x = b; x < e; ++x) sorted.emplace_back(high(byLow[x]), byLow[x]);
      std::sort(sorted.begin(), sorted.end());
      for (std::size_t x = 0; x < sorted.size(); ++x)
        firstUse[sorted[x].second] =
            x > 0 && sorted[x - 1].first == sorted[x].first ? firstUse[sorted[x - 1].second] : sorted[x].second;
    }
  });

  UniqueEdges result;
  result.useEdge.resize(n);
  for (std::size_t u = 0; u < n; ++u) {
    if (firstUse[u] == u) {
      result.useEdge[u] = static_cast<Index>(result.edges.size());
      result.edges.push_back({low(u), high(u)});
    } else {
      result.useEdge[u] = result.useEdge[firstUse[u]];
    }
  }
  return result;
}

}  // namespace cadmedial
