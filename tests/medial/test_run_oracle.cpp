// The run's check of the inner/outer walk against the exact solid
// (`cadmedial run` without --no-oracle, the Python module's CheckInside).
// It asks ExactOracle::inside, which decides by the normal at the nearest
// point and calls OCCT's classifier only where that point is not smooth:
// BRepClass3d_SolidClassifier on every centroid took 81 s on this ellipsoid
// (one B-spline face, 6.8 k facets) and 111 s on NIST CTC-01, for a
// pipeline of 0.1 s and 6 s (2026-12-04).
#include <gtest/gtest.h>

#include "cadmedial/medial.hpp"
// OCCT after CGAL (OCCT's Handle macro).
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_GTransform.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <TopExp_Explorer.hxx>
#include <gp_Ax2.hxx>
#include <gp_GTrsf.hxx>

#include "cadmedial/sampling.hpp"
#include "solid_run.hpp"

namespace cadmedial {
namespace {

TopoDS_Shape firstSolid(const TopoDS_Shape& shape) {
  TopExp_Explorer solid(shape, TopAbs_SOLID);
  return solid.More() ? solid.Current() : TopoDS_Shape();
}

// A sphere of radius 10 stretched to semi-axes 30, 15, 10: OCCT turns its
// face into a B-spline surface.
TopoDS_Shape ellipsoid() {
  gp_GTrsf stretch;
  stretch.SetValue(1, 1, 3.0);
  stretch.SetValue(2, 2, 1.5);
  return firstSolid(BRepBuilderAPI_GTransform(BRepPrimAPI_MakeSphere(10).Shape(), stretch, true).Shape());
}

TopoDS_Shape plateWithHole() {
  const TopoDS_Shape plate = BRepPrimAPI_MakeBox(60, 40, 10).Shape();
  const TopoDS_Shape hole = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(30, 20, 0), gp_Dir(0, 0, 1)), 8, 10).Shape();
  return firstSolid(BRepAlgoAPI_Cut(plate, hole).Shape());
}

// minOuter: how many facets the walk labels outer at least (the plate's
// hole and faces have bounded outer facets; the convex ellipsoid few).
void expectTheExactSideAgreesWithTheWalk(const TopoDS_Shape& solid, std::size_t minOuter) {
  ASSERT_FALSE(solid.IsNull());
  const SolidResult run = runSolid(solid, SamplingParams{}, MedialParams::cad(), /*withOracle=*/true,
                                   /*pairMesh=*/false, {});
  const MedialResult& m = run.medial;
  std::size_t outer = 0;
  for (std::uint8_t isOuter : m.labels.facetOuter) outer += isOuter;
  const std::size_t bounded = m.counts.oracleChecked;
  std::printf("%zu samples, %zu facets checked (%zu outer labels), %zu disagreements, %zu of %zu forced; "
              "check %.2f s, pipeline %.2f s\n",
              run.sampled.samples.size(), bounded, outer, m.counts.oracleDisagreements,
              m.counts.oracleForcedDisagreements, m.counts.oracleForcedChecked, m.times.oracle, m.times.total);
  // Both sides are asked about (an oracle that always said "inside", or
  // "outside", would disagree on one of them), and every facet agrees.
  EXPECT_GE(outer, minOuter);
  EXPECT_GT(bounded, outer + 1000);
  EXPECT_EQ(m.counts.oracleDisagreements, 0u);
  EXPECT_LE(m.counts.oracleForcedDisagreements, m.counts.oracleForcedChecked / 1000);
}

TEST(RunOracle, AgreesWithTheWalkOnABSplineEllipsoid) { expectTheExactSideAgreesWithTheWalk(ellipsoid(), 20); }

TEST(RunOracle, AgreesWithTheWalkOnAPlateWithAHole) { expectTheExactSideAgreesWithTheWalk(plateWithHole(), 1000); }

}  // namespace
}  // namespace cadmedial
