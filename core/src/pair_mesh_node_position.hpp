// Private to the pair-mesh repair: the best position of one node.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "cadmedial/sample_set.hpp"

namespace cadmedial {

// The elements list the node among their four corners and are positive when
// valid. Within `reach` of the node (per coordinate), finds the position
// farthest from every plane where one of them turns flat (an LP), then
// returns the point on the way there, nearest to the node, where all are
// clearly positive. nullopt when no position makes them all positive.
std::optional<Vec3> nearestValidNodePosition(const std::vector<Vec3>& nodes, Index node,
                                     const std::vector<std::array<Index, 4>>& elements, double reach);

}  // namespace cadmedial
