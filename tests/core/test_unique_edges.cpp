// findUniqueEdges against a std::map of first uses: the same edges, in order
// of first use, and every use mapped to its edge.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <utility>

#include "cadmedial/unique_edges.hpp"

namespace cadmedial {
namespace {

void expectSameAsMap(std::size_t vertexCount, const std::vector<std::array<Index, 2>>& uses) {
  std::map<std::pair<Index, Index>, Index> id;
  std::vector<std::array<Index, 2>> edges;
  std::vector<Index> useEdge;
  for (const auto& u : uses) {
    const std::pair<Index, Index> key{std::min(u[0], u[1]), std::max(u[0], u[1])};
    const auto [it, added] = id.emplace(key, static_cast<Index>(edges.size()));
    if (added) edges.push_back({key.first, key.second});
    useEdge.push_back(it->second);
  }
  const UniqueEdges got = findUniqueEdges(vertexCount, uses);
  EXPECT_EQ(got.edges, edges);
  EXPECT_EQ(got.useEdge, useEdge);
}

TEST(UniqueEdges, MatchesAMapOfFirstUses) {
  std::mt19937 random(7);
  // Few vertices, many uses: buckets far above the pairwise-compare size
  // (the sorted path), both orientations, and loops (equal ends).
  for (const std::size_t vertices : {1u, 5u, 40u, 3000u}) {
    std::uniform_int_distribution<Index> pick(0, static_cast<Index>(vertices - 1));
    std::vector<std::array<Index, 2>> uses(20000);
    for (auto& u : uses) u = {pick(random), pick(random)};
    SCOPED_TRACE(vertices);
    expectSameAsMap(vertices, uses);
  }
}

TEST(UniqueEdges, PolygonSidesSharedBetweenNeighbours) {
  // A strip of quads: inner sides are used twice, in opposite directions.
  std::vector<std::array<Index, 2>> uses;
  for (Index q = 0; q < 100; ++q) {
    const Index a = 2 * q, b = 2 * q + 1, c = 2 * q + 3, d = 2 * q + 2;
    for (const auto& side : {std::array<Index, 2>{a, b}, {b, c}, {c, d}, {d, a}}) uses.push_back(side);
  }
  const UniqueEdges got = findUniqueEdges(202, uses);
  EXPECT_EQ(got.edges.size(), 100u * 3 + 1);  // 2 per quad + the shared rungs (101)
  expectSameAsMap(202, uses);
}

TEST(UniqueEdges, NoUses) {
  const UniqueEdges got = findUniqueEdges(10, {});
  EXPECT_TRUE(got.edges.empty());
  EXPECT_TRUE(got.useEdge.empty());
}

}  // namespace
}  // namespace cadmedial
