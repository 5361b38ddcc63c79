// FaceUVClassifier (face_uv_classifier.hpp) must answer exactly what
// BRepTopAdaptor_FClass2d answers on the whole face, while it sends points to
// per-wire classifiers: checked on faces with many holes (a perforated plate,
// holes whose boxes overlap, a drilled tube whose face is periodic in u), at
// random points, on the holes' boundaries and just off them.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box2d.hxx>
#include <Geom2d_Curve.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Ax2.hxx>

#include "face_uv_classifier.hpp"

namespace cadmedial {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTol = 1e-9;  // as the sampling code builds its classifiers

struct Hole {
  gp_Pnt base;
  gp_Dir axis;
  double radius;
};

TopoDS_Shape drilled(const TopoDS_Shape& stock, const std::vector<Hole>& holes, double length) {
  BRep_Builder builder;
  TopoDS_Compound tools;
  builder.MakeCompound(tools);
  for (const Hole& h : holes) builder.Add(tools, BRepPrimAPI_MakeCylinder(gp_Ax2(h.base, h.axis), h.radius, length).Shape());
  BRepAlgoAPI_Cut cut(stock, tools);
  EXPECT_TRUE(cut.IsDone());
  return cut.Shape();
}

int wireCount(const TopoDS_Face& face) {
  int n = 0;
  for (TopExp_Explorer ex(face, TopAbs_WIRE); ex.More(); ex.Next()) ++n;
  return n;
}

TopoDS_Face faceWithMostWires(const TopoDS_Shape& shape) {
  TopoDS_Face best;
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next())
    if (best.IsNull() || wireCount(TopoDS::Face(ex.Current())) > wireCount(best)) best = TopoDS::Face(ex.Current());
  return best;
}

// UV points that test the classifier where it could go wrong: uniform over
// the face's UV box (and a margin around it), on every edge's pcurve, and
// just off the pcurves on both sides at several distances.
std::vector<gp_Pnt2d> testPoints(const TopoDS_Face& face, int uniform, std::mt19937_64& rng) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  const double mu = 0.05 * (u1 - u0), mv = 0.05 * (v1 - v0);
  std::uniform_real_distribution<double> ru(u0 - mu, u1 + mu), rv(v0 - mv, v1 + mv), unit(0, 1);
  std::vector<gp_Pnt2d> points;
  for (int i = 0; i < uniform; ++i) points.emplace_back(ru(rng), rv(rng));
  for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
    double t0, t1;
    const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(TopoDS::Edge(ex.Current()), face, t0, t1);
    if (pcurve.IsNull()) continue;
    for (int k = 0; k < 24; ++k) {
      gp_Pnt2d q;
      gp_Vec2d d;
      pcurve->D1(t0 + (t1 - t0) * unit(rng), q, d);
      points.push_back(q);
      if (d.Magnitude() < 1e-300) continue;
      const gp_Vec2d normal = gp_Vec2d(-d.Y(), d.X()).Normalized();
      for (double offset : {1e-10, 1e-7, 1e-4, 1e-2, 0.3})
        for (double side : {-1.0, 1.0}) points.push_back(q.Translated(normal * (side * offset)));
    }
  }
  return points;
}

struct Tally {
  int in = 0, out = 0, on = 0, differ = 0;
};

Tally compare(const TopoDS_Face& face, const std::vector<gp_Pnt2d>& points) {
  const BRepTopAdaptor_FClass2d whole(face, kTol);
  const FaceUVClassifier split(face, kTol);
  EXPECT_TRUE(split.splitsWires()) << "the face with " << wireCount(face) << " wires is classified whole";
  Tally tally;
  for (const gp_Pnt2d& p : points) {
    const TopAbs_State expected = whole.Perform(p), got = split.Perform(p);
    if (expected != got) {
      if (++tally.differ <= 5)
        ADD_FAILURE() << "at uv (" << p.X() << ", " << p.Y() << "): whole face " << expected << ", split " << got;
    }
    (expected == TopAbs_IN ? tally.in : expected == TopAbs_OUT ? tally.out : tally.on)++;
  }
  return tally;
}

TEST(FaceUVClassifier, AgreesWithTheWholeFaceOnAPlateWith100Holes) {
  std::vector<Hole> holes;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) holes.push_back({gp_Pnt(10 + 9 * i, 10 + 9 * j, -2), gp::DZ(), 1.5});
  const TopoDS_Face top = faceWithMostWires(drilled(BRepPrimAPI_MakeBox(100, 100, 5).Shape(), holes, 10));
  ASSERT_EQ(wireCount(top), 101);
  std::mt19937_64 rng(1);
  const Tally t = compare(top, testPoints(top, 20000, rng));
  EXPECT_EQ(t.differ, 0);
  // The points reach every state, so agreement says something.
  EXPECT_GT(t.in, 1000);
  EXPECT_GT(t.out, 1000);
  EXPECT_GT(t.on, 100);
}

TEST(FaceUVClassifier, AgreesWhereTheBoxesOfTwoHolesOverlap) {
  // Holes r 3 at (20, 20) and (24.5, 24.5): 6.4 apart, so disjoint, but
  // their boxes overlap; the point goes to the whole face's test there.
  std::vector<Hole> holes = {{gp_Pnt(20, 20, -2), gp::DZ(), 3},
                             {gp_Pnt(24.5, 24.5, -2), gp::DZ(), 3},
                             {gp_Pnt(40, 10, -2), gp::DZ(), 2},
                             {gp_Pnt(10, 40, -2), gp::DZ(), 2},
                             {gp_Pnt(40, 40, -2), gp::DZ(), 4}};
  const TopoDS_Face top = faceWithMostWires(drilled(BRepPrimAPI_MakeBox(50, 50, 5).Shape(), holes, 10));
  ASSERT_EQ(wireCount(top), 6);
  std::mt19937_64 rng(2);
  const Tally t = compare(top, testPoints(top, 20000, rng));
  EXPECT_EQ(t.differ, 0);
  EXPECT_GT(t.out, 100);
  EXPECT_GT(t.on, 10);
}

TEST(FaceUVClassifier, AgreesOnAPeriodicFaceAlsoAPeriodAway) {
  // A tube R 20 with six radial holes: its outer cylindrical face has seven
  // wires and u is periodic; FClass2d moves u by whole periods, and so must
  // the box test (a point in a hole, given 2 pi further on, is still OUT).
  std::vector<Hole> holes;
  for (int k = 0; k < 6; ++k) {
    const double a = 2 * kPi * (k + 0.3) / 6;
    holes.push_back({gp_Pnt(0, 0, 10 + 8 * k), gp_Dir(std::cos(a), std::sin(a), 0), 2.5});
  }
  const TopoDS_Shape tube = BRepAlgoAPI_Cut(BRepPrimAPI_MakeCylinder(20, 70).Shape(),
                                            BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -1), gp::DZ()), 15, 72).Shape())
                                .Shape();
  const TopoDS_Face outer = faceWithMostWires(drilled(tube, holes, 30));
  ASSERT_GE(wireCount(outer), 7);
  std::mt19937_64 rng(3);
  std::vector<gp_Pnt2d> points = testPoints(outer, 10000, rng);
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n; ++i)
    for (double shift : {-2 * kPi, 2 * kPi}) points.emplace_back(points[i].X() + shift, points[i].Y());
  const Tally t = compare(outer, points);
  EXPECT_EQ(t.differ, 0);
  EXPECT_GT(t.out, 1000);
  EXPECT_GT(t.on, 100);
}

TEST(FaceUVClassifier, AFaceWithFewHolesIsClassifiedWhole) {
  const TopoDS_Face top = faceWithMostWires(
      drilled(BRepPrimAPI_MakeBox(50, 50, 5).Shape(), {{gp_Pnt(25, 25, -2), gp::DZ(), 3}}, 10));
  ASSERT_EQ(wireCount(top), 2);
  EXPECT_FALSE(FaceUVClassifier(top, kTol).splitsWires());
}

}  // namespace
}  // namespace cadmedial
