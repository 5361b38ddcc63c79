// BallTree::minGap and hasGapAtMost against a scan of every ball, on trees large enough to be
// built in parallel (the build splits ranges of 4096 balls and more across
// threads into one pre-ordered node array; a misplaced subtree would lose or
// repeat balls and change answers).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "cadmedial/ball_tree.hpp"

namespace cadmedial {
namespace {

std::vector<BallTree::Ball> randomBalls(std::size_t n, std::mt19937& rng) {
  std::uniform_real_distribution<double> coord(-50, 50), radius(0, 3), unit(0, 1);
  std::vector<BallTree::Ball> balls;
  for (std::size_t i = 0; i < n; ++i) {
    // A third of them on a line and some repeated: ties and flat boxes.
    Vec3 c{coord(rng), coord(rng), coord(rng)};
    if (i % 3 == 0) c = {coord(rng), 0, 0};
    if (i % 50 == 1 && !balls.empty()) c = balls.back().centre;
    balls.push_back({c, radius(rng)});
  }
  return balls;
}

double scanMinGap(const std::vector<BallTree::Ball>& balls, const Vec3& p, double skipWithin) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& b : balls) {
    const double d = BallTree::distance(p, b.centre);
    if (d < skipWithin) continue;
    best = std::min(best, d - b.radius);
  }
  return best;
}

TEST(BallTree, MinGapEqualsAScanOfEveryBall) {
  std::mt19937 rng(7);
  for (std::size_t n : {1u, 9u, 5000u, 40000u}) {
    const std::vector<BallTree::Ball> balls = randomBalls(n, rng);
    const BallTree tree(balls);
    std::uniform_real_distribution<double> coord(-60, 60);
    for (int q = 0; q < 300; ++q) {
      const Vec3 p = q % 4 == 0 ? balls[q % balls.size()].centre : Vec3{coord(rng), coord(rng), coord(rng)};
      const double noStop = -std::numeric_limits<double>::infinity();
      EXPECT_EQ(tree.minGap(p, noStop), scanMinGap(balls, p, -1)) << n << " balls, query " << q;
      EXPECT_EQ(tree.minGap(p, noStop, 2.0), scanMinGap(balls, p, 2.0)) << n << " balls, query " << q;
      // With a stop value the answer is only known to be at most it.
      const double exact = scanMinGap(balls, p, 0.5), stopAt = exact + (q % 2 ? 0.25 : -0.25);
      EXPECT_EQ(tree.minGap(p, stopAt, 0.5) <= stopAt, exact <= stopAt) << n << " balls, query " << q;
      // The yes/no search prunes by the limit itself: same answers, at the
      // limit exactly too (a gap equal to it counts).
      // (A finite limit: with every ball skipped, minGap's +inf is "at most" an
      // infinite one, while no ball has a gap.)
      for (const double limit : {stopAt, exact, std::nextafter(exact, -1e300)}) {
        if (!std::isfinite(limit)) continue;
        EXPECT_EQ(tree.hasGapAtMost(p, limit, 0.5), exact <= limit) << n << " balls, query " << q;
        EXPECT_EQ(tree.hasGapAtMost(p, limit), scanMinGap(balls, p, -1) <= limit) << n << " balls, query " << q;
      }
    }
  }
}

TEST(BallTree, EmptyTreeHasNoGap) {
  const BallTree tree({});
  EXPECT_EQ(tree.minGap({0, 0, 0}, 0), std::numeric_limits<double>::infinity());
  EXPECT_FALSE(tree.hasGapAtMost({0, 0, 0}, 1e300));
}

}  // namespace
}  // namespace cadmedial
