// Which faces count as narrow (narrow_faces.hpp): two of a face's boundary
// edges that share no vertex, close to each other, with the boundary running
// far between them (at least twice their distance). Checked on shapes whose
// narrow places are known by construction: a step's riser and a hole next
// to a plate's side are narrow; a plain box, the L-shaped side of a step
// (its notch is as wide as the way round it) and the tread are not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBndLib.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <Bnd_Box.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "cadmedial/sampling.hpp"
#include "face_spacing_field.hpp"
#include "narrow_faces.hpp"
#include "solid_topology.hpp"

namespace cadmedial {
namespace {

using Sources = std::vector<std::vector<FaceSpacingField::Source>>;

struct Probe {
  SolidTopology topo;
  double h, floor;
  Sources sources;
};

Probe probe(const TopoDS_Shape& solid) {
  Probe p{buildSolidTopology(solid), defaultSpacing(solid), 0, {}};
  p.floor = p.h * SamplingParams{}.minSpacingFraction;
  p.sources = narrowFaceSources(p.topo, p.floor, p.h, FaceSpacingField::kWidthFraction);
  return p;
}

TopoDS_Shape firstSolid(const TopoDS_Shape& shape) {
  TopExp_Explorer solid(shape, TopAbs_SOLID);
  return solid.More() ? solid.Current() : TopoDS_Shape();
}

// The planar faces of the split solid whose box is [lo, hi] (to 1e-6).
std::vector<int> facesIn(const SolidTopology& topo, const gp_Pnt& lo, const gp_Pnt& hi) {
  std::vector<int> found;
  for (int f = 0; f < topo.faceCount(); ++f) {
    Bnd_Box box;
    BRepBndLib::AddOptimal(topo.face(f), box, false, false);
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    if (std::abs(x0 - lo.X()) < 1e-6 && std::abs(y0 - lo.Y()) < 1e-6 && std::abs(z0 - lo.Z()) < 1e-6 &&
        std::abs(x1 - hi.X()) < 1e-6 && std::abs(y1 - hi.Y()) < 1e-6 && std::abs(z1 - hi.Z()) < 1e-6)
      found.push_back(f);
  }
  return found;
}

TEST(NarrowFaces, PlainBoxHasNone) {
  const Probe p = probe(BRepPrimAPI_MakeBox(100, 60, 40).Shape());
  for (const auto& s : p.sources) EXPECT_TRUE(s.empty());
}

TEST(NarrowFaces, StepRiserIsNarrowAlongItsLengthAndNothingElseIs) {
  // A 100 × 100 × 50 block with a 0.5 mm step on half its top (h 3.75).
  BRepAlgoAPI_Fuse fuse(BRepPrimAPI_MakeBox(100, 100, 50).Shape(),
                        BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 50), 50, 100, 0.5).Shape());
  ShapeUpgrade_UnifySameDomain unify(fuse.Shape());
  unify.Build();
  const Probe p = probe(firstSolid(unify.Shape()));
  const std::vector<int> riser = facesIn(p.topo, gp_Pnt(50, 0, 50), gp_Pnt(50, 100, 50.5));
  ASSERT_EQ(riser.size(), 1u);
  // Along both long edges of the riser, a spacing of half its width
  // (0.25, above the floor h/16 = 0.234), points no farther apart than that
  // over its length, except within its width of the ends (where the way
  // round is short).
  const auto& s = p.sources[riser[0]];
  ASSERT_FALSE(s.empty());
  for (double z : {50.0, 50.5}) {
    std::vector<double> ys;
    for (const auto& q : s) {
      EXPECT_NEAR(q.point.X(), 50, 1e-7);
      if (std::abs(q.point.Z() - z) > 1e-7) continue;
      if (q.point.Y() > 1 && q.point.Y() < 99) EXPECT_NEAR(q.spacing, 0.25, 1e-6);
      ys.push_back(q.point.Y());
    }
    std::sort(ys.begin(), ys.end());
    ASSERT_GT(ys.size(), 2u) << z;
    EXPECT_LT(ys.front(), 0.5) << z;
    EXPECT_GT(ys.back(), 99.5) << z;
    double gap = 0;
    for (std::size_t k = 1; k < ys.size(); ++k) gap = std::max(gap, ys[k] - ys[k - 1]);
    EXPECT_LE(gap, 0.25 * 1.01) << z;
  }
  // Every other face: none (the sides are L-shaped, their notch's edges
  // joined by the 0.5 mm riser edge; the tread and floor are wide).
  std::size_t others = 0;
  for (int f = 0; f < p.topo.faceCount(); ++f)
    if (f != riser[0]) others += p.sources[f].size();
  EXPECT_EQ(others, 0u);
}

TEST(NarrowFaces, HoleNextToThePlateSideMakesTheFacesNarrowThere) {
  // A 100 × 60 × 10 plate; a hole of radius 10 whose rim passes 0.3 from
  // the side y = 0 at x = 50. The top and bottom faces have the rim and the
  // side as separate wires: narrow near x = 50 only.
  const TopoDS_Shape plate = BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(100, 60, 10).Shape(),
                                             BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(50, 10.3, 0), gp_Dir(0, 0, 1)), 10, 10)
                                                 .Shape())
                                 .Shape();
  const Probe p = probe(plate);
  const std::vector<int> top = facesIn(p.topo, gp_Pnt(0, 0, 10), gp_Pnt(100, 60, 10));
  ASSERT_EQ(top.size(), 1u);
  const auto& s = p.sources[top[0]];
  ASSERT_FALSE(s.empty());
  const double reach = p.h / FaceSpacingField::kWidthFraction;
  double finest = p.h;
  for (const auto& q : s) {
    // Only where the gap between the rim and the side is under the reach:
    // a point of the side at x is sqrt((x - 50)² + 10.3²) - 10 from the rim.
    EXPECT_LT(std::abs(q.point.X() - 50), std::sqrt(std::pow(10 + reach, 2) - 10.3 * 10.3) + 1e-6);
    finest = std::min(finest, q.spacing);
  }
  EXPECT_NEAR(finest, std::max(p.floor, 0.5 * 0.3), 1e-6);
}

}  // namespace
}  // namespace cadmedial
