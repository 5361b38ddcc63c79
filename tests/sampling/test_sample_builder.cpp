// SampleBuilder's "is this spot clear?" against a brute-force scan, while
// its hash grid re-fits its cell size to the exclusion radii it is given:
// the cell size must change only the cost, never an answer.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sample_builder.hpp"

namespace cadmedial {
namespace {

bool bruteForceClear(const SampleSet& set, const std::vector<double>& exclusion, const gp_Pnt& p, double radius,
                     Index ignore, bool honourExclusion) {
  for (Index q = 0; q < set.points.size(); ++q) {
    if (q == ignore) continue;
    const double dx = set.points[q][0] - p.X(), dy = set.points[q][1] - p.Y(), dz = set.points[q][2] - p.Z();
    const double limit = honourExclusion ? std::max(radius, exclusion[q]) : radius;
    if (dx * dx + dy * dy + dz * dz < limit * limit) return false;
  }
  return true;
}

// Fine samples first (radii 0.01-0.02, as on a thread), then coarse ones
// (0.5-1): the first cells (start size 8) are far too large and get refitted
// smaller, then too small for the coarse radii and get refitted larger.
TEST(SampleBuilder, AnswersLikeABruteForceScanWhileTheCellsAreRefitted) {
  for (double startCell : {8.0, 0.001}) {
    SampleSet set;
    SampleBuilder builder(set, startCell);
    std::vector<double> exclusion;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<double> cellSizes;
    int queries = 0, clear = 0, blocked = 0;
    auto query = [&](double radius) {
      const gp_Pnt p(4 * unit(rng), 4 * unit(rng), 4 * unit(rng));
      const bool honour = unit(rng) < 0.8;
      const Index ignore = set.points.empty() || unit(rng) < 0.5 ? kNoIndex : static_cast<Index>(unit(rng) * set.points.size());
      const bool expected = bruteForceClear(set, exclusion, p, radius, ignore, honour);
      ASSERT_EQ(builder.isClear(p, radius, ignore, honour), expected) << "query " << queries << " start cell " << startCell;
      ++queries;
      (expected ? clear : blocked) += 1;
    };
    for (int phase = 0; phase < 2; ++phase) {
      const double lo = phase == 0 ? 0.01 : 0.5, hi = phase == 0 ? 0.02 : 1.0;
      for (int i = 0; i < 6000; ++i) {
        const double r = lo + (hi - lo) * unit(rng);
        // Clustered fine samples (a 0.3 cube) so that the spots are often taken.
        const double span = phase == 0 ? 0.3 : 4;
        const gp_Pnt p(span * unit(rng), span * unit(rng), span * unit(rng));
        builder.add(p, SampleKind::Face, 0, r);
        exclusion.push_back(r);
        if (i % 7 == 0) {
          const Index j = static_cast<Index>(unit(rng) * set.points.size());
          exclusion[j] *= 1.5;
          builder.setExclusion(j, exclusion[j]);
        }
        if (i % 20 == 0) query(lo + (hi - lo) * unit(rng));
        if (cellSizes.empty() || cellSizes.back() != builder.cellSize()) cellSizes.push_back(builder.cellSize());
      }
    }
    EXPECT_GE(cellSizes.size(), 3u) << "the grid was refitted at least twice (start cell " << startCell << ")";
    EXPECT_GE(clear, 20);
    EXPECT_GE(blocked, 20);
  }
}

}  // namespace
}  // namespace cadmedial
