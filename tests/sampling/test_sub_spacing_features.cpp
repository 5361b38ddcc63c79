// Features smaller than the finest spacing (h / 16): a pin of radius 0.05 on
// a 200 mm part. The sampling cannot follow them, and says so in a warning,
// but every face must still be triangulated and every edge keep enough
// samples for its faces: a circle of one step left its face with no boundary
// loop and the face triangulation crashed (2026-12-06, a needle and a pin).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <gp_Ax2.hxx>

#include "cadmedial/sampling.hpp"
#include "model_fixtures.hpp"

namespace cadmedial {
namespace {

constexpr double kPinRadius = 0.05;

// Samples of edges on a circle of the pin (their points share one z) are
// never more than a quarter turn apart (chord ≤ √2 r): the circles are split
// in halves (solid_topology.hpp) and each half has two steps at least.
// Returns how many such edges there are.
int expectCircleChordsWithinAQuarterTurn(const SampleSet& set) {
  int circleEdges = 0;
  for (const EdgeInfo& edge : set.edges) {
    if (edge.samples.size() < 2) continue;
    const double z = set.points[edge.samples.front()][2];
    const bool flat = std::all_of(edge.samples.begin(), edge.samples.end(),
                                  [&](Index s) { return std::abs(set.points[s][2] - z) < 1e-9; });
    if (!flat || edge.length > 2 * M_PI * kPinRadius * 1.001) continue;
    ++circleEdges;
    for (std::size_t k = 0; k + 1 < edge.samples.size(); ++k) {
      const Vec3 &a = set.points[edge.samples[k]], &b = set.points[edge.samples[k + 1]];
      const double chord = std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
      EXPECT_LE(chord, std::sqrt(2.0) * kPinRadius * (1 + 1e-9)) << "edge of length " << edge.length;
    }
  }
  return circleEdges;
}

void expectEveryFaceTriangulated(const SolidSampling& s) {
  EXPECT_EQ(s.report.facesFailed, 0);
  EXPECT_EQ(s.report.surface.boundaryEdges, 0u);
  const std::set<int> faces(s.samples.triangleFace.begin(), s.samples.triangleFace.end());
  EXPECT_EQ(static_cast<int>(faces.size()), s.samples.faceCount);
}

TEST(SubSpacingFeatures, NeedleFacesAreAllTriangulatedAndItsHalfCirclesKeepTwoSteps) {
  const TopoDS_Shape needle = BRepPrimAPI_MakeCylinder(kPinRadius, 200).Shape();
  const SolidSampling s = sampleSolid(needle);
  expectEveryFaceTriangulated(s);
  EXPECT_GE(expectCircleChordsWithinAQuarterTurn(s.samples), 2);
  // The wall is thinner, and the circles tighter, than the finest spacing
  // follows, and the run says so.
  EXPECT_NE(test::warningContaining(s.report.warnings, "thinner than"), "");
  const std::string curve = test::warningContaining(s.report.warnings, "an edge curved to radius 0.05 ");
  ASSERT_NE(curve, "");
  // At the spacing it suggests (8 chords a turn) the circles are followed.
  const std::size_t at = curve.find("--spacing ");
  ASSERT_NE(at, std::string::npos) << curve;
  SamplingParams finer;
  finer.spacing = std::stod(curve.substr(at + 10));
  EXPECT_NEAR(finer.spacing, 16 * 0.8 * kPinRadius, 0.01);
  const SolidSampling fine = sampleSolid(needle, finer);
  EXPECT_EQ(test::warningContaining(fine.report.warnings, "an edge curved"), "");
  EXPECT_TRUE(fine.report.surface.closedManifold());
}

TEST(SubSpacingFeatures, CirclesTheSpacingFollowsAreNotWarnedAbout) {
  const SolidSampling s = sampleSolid(BRepPrimAPI_MakeCylinder(10, 20).Shape());
  EXPECT_EQ(test::warningContaining(s.report.warnings, "an edge curved"), "");
  EXPECT_TRUE(s.report.warnings.empty());
}

TEST(SubSpacingFeatures, PinOnALargePlateIsSampledWithoutLosingAFace) {
  BRepAlgoAPI_Fuse fuse(BRepPrimAPI_MakeBox(200, 200, 10).Shape(),
                        BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(100, 100, 10), gp_Dir(0, 0, 1)), kPinRadius, 1).Shape());
  ASSERT_TRUE(fuse.IsDone());
  const SolidSampling s = sampleSolid(fuse.Shape());
  expectEveryFaceTriangulated(s);
  EXPECT_GE(expectCircleChordsWithinAQuarterTurn(s.samples), 2);
}

}  // namespace
}  // namespace cadmedial
