// ClearanceTrees (the per-cell trees of SampleBuilder) against a brute-force
// scan: pruning by box distance and largest exclusion must never change an
// answer, with graded radii, coincident samples and radii changed after
// insertion.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "clearance_tree.hpp"

namespace cadmedial {
namespace {

bool bruteForceBlocks(const std::vector<ClearanceEntry>& all, double x, double y, double z, double radius,
                      Index ignore, bool honour) {
  for (const ClearanceEntry& q : all) {
    if (q.id == ignore) continue;
    const double dx = q.x - x, dy = q.y - y, dz = q.z - z;
    const double limit = honour ? std::max(radius, q.exclusion) : radius;
    if (dx * dx + dy * dy + dz * dz < limit * limit) return true;
  }
  return false;
}

// One cell crowded the way a graded part crowds it: a dense cluster of fine
// samples (radii 0.002-0.004 in a 0.05 cube, as on a small fillet), a few
// coarse ones (radius 0.3) and 200 samples on one spot.
TEST(ClearanceTrees, AnswerLikeABruteForceScanInACrowdedCell) {
  ClearanceTrees trees;
  const Index root = trees.newTree();
  const Index other = trees.newTree();  // a second tree must not see the first's samples
  std::vector<ClearanceEntry> all;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  auto add = [&](double x, double y, double z, double r) {
    const ClearanceEntry e{x, y, z, r, static_cast<Index>(all.size())};
    all.push_back(e);
    trees.insert(root, e);
  };
  int blocked = 0, clear = 0;
  auto query = [&](double span) {
    const double x = span * unit(rng), y = span * unit(rng), z = span * unit(rng);
    const double radius = unit(rng) < 0.7 ? 0.001 + 0.004 * unit(rng) : 0.1 + 0.3 * unit(rng);
    const bool honour = unit(rng) < 0.8;
    const Index ignore = unit(rng) < 0.5 ? kNoIndex : static_cast<Index>(unit(rng) * all.size());
    const bool expected = bruteForceBlocks(all, x, y, z, radius, ignore, honour);
    ASSERT_EQ(trees.anyBlocks(root, x, y, z, radius, ignore, honour), expected)
        << "at " << x << " " << y << " " << z << " radius " << radius << " after " << all.size() << " samples";
    ASSERT_FALSE(trees.anyBlocks(other, x, y, z, radius, ignore, honour));
    (expected ? blocked : clear) += 1;
  };
  for (int i = 0; i < 4000; ++i) {
    add(0.05 * unit(rng), 0.05 * unit(rng), 0.05 * unit(rng), 0.002 + 0.002 * unit(rng));
    if (i % 400 == 0) add(1.0 * unit(rng), 1.0 * unit(rng), 1.0 * unit(rng), 0.3);
    if (i % 20 == 0) add(0.5, 0.5, 0.5, 0.001);  // coincident: splitting must stop
    if (i % 9 == 0) {
      // Raise or lower a radius: a node's bound may go stale high, never low.
      ClearanceEntry& e = all[static_cast<std::size_t>(unit(rng) * all.size())];
      e.exclusion *= unit(rng) < 0.5 ? 3.0 : 0.5;
      trees.setExclusion(root, e.id, e.x, e.y, e.z, e.exclusion);
    }
    if (i % 5 == 0) query(i % 10 == 0 ? 0.06 : 1.0);
  }
  EXPECT_GE(blocked, 100);
  EXPECT_GE(clear, 100);
  EXPECT_GT(trees.nodeCount(), 100u) << "a crowded cell splits";
}

// Sample tests sit right on a box face: a query point whose distance to a
// sample equals the limit exactly must be clear, one a rounding step nearer
// must be blocked, even where the box test and the sample test meet.
TEST(ClearanceTrees, LimitsAreStrictAtBoxFaces) {
  ClearanceTrees trees;
  const Index root = trees.newTree();
  std::vector<ClearanceEntry> all;
  for (int i = 0; i < 200; ++i) {
    const ClearanceEntry e{0.1 * (i % 10), 0.1 * ((i / 10) % 10), 0.1 * (i / 100), 0.0, static_cast<Index>(i)};
    all.push_back(e);
    trees.insert(root, e);
  }
  for (const ClearanceEntry& q : all) {
    for (double radius : {0.05, 0.1, 0.25}) {
      const double beyond = q.x + radius;  // exactly the limit away along x when representable
      for (double x : {beyond, std::nextafter(beyond, 0.0), std::nextafter(beyond, 10.0)}) {
        EXPECT_EQ(trees.anyBlocks(root, x, q.y, q.z, radius, kNoIndex, true),
                  bruteForceBlocks(all, x, q.y, q.z, radius, kNoIndex, true));
        EXPECT_EQ(trees.anyBlocks(root, x, q.y, q.z, radius, q.id, false),
                  bruteForceBlocks(all, x, q.y, q.z, radius, q.id, false));
      }
    }
  }
  EXPECT_GT(trees.nodeCount(), 1u);
}

}  // namespace
}  // namespace cadmedial
