// ExactOracle against OCCT's own reference (BRepExtrema_DistShapeShape) on
// random points, against hand-known distances at degenerate points, and its
// speed (printed, so the README numbers can be rerun).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <GC_MakeCircle.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Compound.hxx>

#include "cadmedial/brep_io.hpp"
#include "cadmedial/exact_oracle.hpp"

namespace cadmedial {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string modelPath(const std::string& file) { return std::string(CADMEDIAL_MODELS_DIR) + "/" + file; }

// The faces as a compound: DistShapeShape then measures the distance to the
// boundary even for points inside (with a solid it may report 0 there).
TopoDS_Shape facesOf(const TopoDS_Shape& solid) {
  BRep_Builder builder;
  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  for (TopExp_Explorer ex(solid, TopAbs_FACE); ex.More(); ex.Next()) builder.Add(compound, ex.Current());
  return compound;
}

double referenceDistance(const TopoDS_Shape& faces, const gp_Pnt& p) {
  BRepExtrema_DistShapeShape dss(BRepBuilderAPI_MakeVertex(p).Vertex(), faces);
  EXPECT_TRUE(dss.IsDone());
  return dss.Value();
}

// Uniform points in the bounding box grown by 20 % on every side.
std::vector<gp_Pnt> randomPoints(const ExactOracle& oracle, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-0.2, 1.2);
  const gp_Pnt lo = oracle.boxMin(), hi = oracle.boxMax();
  std::vector<gp_Pnt> points;
  for (int i = 0; i < count; ++i)
    points.emplace_back(lo.X() + unit(rng) * (hi.X() - lo.X()), lo.Y() + unit(rng) * (hi.Y() - lo.Y()),
                        lo.Z() + unit(rng) * (hi.Z() - lo.Z()));
  return points;
}

// ExactOracle::meshSide, where it decides, says what the classifier says:
// on the random points of the grown box and on points 0.2 % to 2 % of the
// diagonal off the boundary in random directions, where the mesh and the
// exact surface are closest to disagreeing, and 0.5 % to 5 % off every
// vertex of the solid. It decides for most points
// farther than 2 % of the diagonal (the run's walk check counts on that).
void expectMeshSideAgreesWithOcct(ExactOracle& oracle, BRepClass3d_SolidClassifier& classifier,
                                  const std::string& label, int count) {
  std::vector<gp_Pnt> points = randomPoints(oracle, count, 11);
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> offset(0.002, 0.02), coordinate(-1.0, 1.0);
  for (const gp_Pnt& q : oracle.sampleBoundary(count, 17)) {
    gp_Vec dir(coordinate(rng), coordinate(rng), coordinate(rng));
    if (dir.Magnitude() < 1e-3) continue;
    points.push_back(q.Translated(dir.Normalized() * offset(rng) * oracle.diagonal()));
  }
  // Around every vertex of the solid, where the nearest mesh point is a
  // mesh vertex or edge and the pseudo-normal's weights matter (sharp
  // corners, saddles where convex and concave edges meet).
  TopTools_IndexedMapOfShape vertices;
  TopExp::MapShapes(oracle.solid(), TopAbs_VERTEX, vertices);
  std::uniform_real_distribution<double> cornerOffset(0.005, 0.05);
  const int stride = std::max(1, vertices.Extent() / 100);  // at most ~100 vertices a part
  for (int v = 1; v <= vertices.Extent(); v += stride)
    for (int k = 0; k < 6; ++k) {
      gp_Vec dir(coordinate(rng), coordinate(rng), coordinate(rng));
      if (dir.Magnitude() < 1e-3) continue;
      points.push_back(BRep_Tool::Pnt(TopoDS::Vertex(vertices(v)))
                           .Translated(dir.Normalized() * cornerOffset(rng) * oracle.diagonal()));
    }
  int decided = 0, far = 0, farDecided = 0;
  for (const gp_Pnt& p : points) {
    const int side = oracle.meshSide(p, 2.0);
    const bool isFar = oracle.distance(p) > 0.02 * oracle.diagonal();
    far += isFar;
    if (side == 0) continue;
    ++decided;
    farDecided += isFar;
    classifier.Perform(p, 1e-9 * oracle.diagonal());
    EXPECT_EQ(side < 0, classifier.State() == TopAbs_IN)
        << label << ": meshSide " << side << " at " << p.X() << " " << p.Y() << " " << p.Z();
  }
  EXPECT_GE(farDecided, 0.9 * far) << label;
  std::printf("%s: meshSide decided %d of %zu points, %d of %d far ones\n", label.c_str(), decided, points.size(),
              farDecided, far);
}

// Distance to 1e-7 x diagonal, and the inside test equal to
// BRepClass3d_SolidClassifier's (away from the boundary, where both may differ
// by their tolerances).
void expectAgreesWithOcct(const TopoDS_Shape& solid, const std::string& label, int count) {
  ExactOracle oracle(solid);
  const TopoDS_Shape faces = facesOf(solid);
  BRepClass3d_SolidClassifier classifier(solid);
  const double tol = 1e-7 * oracle.diagonal();
  double worst = 0;
  for (const gp_Pnt& p : randomPoints(oracle, count, 7)) {
    const double ref = referenceDistance(faces, p);
    const BoundaryPoint closest = oracle.closestPoint(p);
    EXPECT_NEAR(closest.distance, ref, tol) << label << " at " << p.X() << " " << p.Y() << " " << p.Z();
    EXPECT_NEAR(p.Distance(closest.point), closest.distance, 1e-12 * oracle.diagonal());
    worst = std::max(worst, std::abs(closest.distance - ref));
    if (ref > 1e-6 * oracle.diagonal()) {
      classifier.Perform(p, 1e-9 * oracle.diagonal());
      EXPECT_EQ(oracle.inside(p, 1e-9 * oracle.diagonal()), classifier.State() != TopAbs_OUT)
          << label << " at " << p.X() << " " << p.Y() << " " << p.Z();
    }
  }
  std::printf("%s: %d points, max |oracle - DistShapeShape| = %.3g (%.3g x diagonal)\n", label.c_str(), count, worst,
              worst / oracle.diagonal());
  expectMeshSideAgreesWithOcct(oracle, classifier, label, count);
}

void expectAgreesWithDistShapeShape(const std::string& path, int count) {
  const LoadedModel model = loadModel(path);
  ASSERT_EQ(model.solids.size(), 1u);
  expectAgreesWithOcct(model.solids[0], std::filesystem::path(path).filename().string(), count);
}

TEST(ExactOracle, AgreesWithDistShapeShapeOnBox) { expectAgreesWithDistShapeShape(modelPath("box.step"), 300); }
TEST(ExactOracle, AgreesWithDistShapeShapeOnCylinder) {
  expectAgreesWithDistShapeShape(modelPath("cylinder.step"), 300);
}
TEST(ExactOracle, AgreesWithDistShapeShapeOnTorus) { expectAgreesWithDistShapeShape(modelPath("torus.step"), 300); }
TEST(ExactOracle, AgreesWithDistShapeShapeOnFlange) { expectAgreesWithDistShapeShape(modelPath("flange.step"), 150); }
TEST(ExactOracle, AgreesWithDistShapeShapeOnFilletChamferBlock) {
  expectAgreesWithDistShapeShape(modelPath("fillet_chamfer_block.step"), 150);
}

// B-spline faces: a loft from a circle (r 20, z 0) to a square turned 45°
// (side 30, z 40) and to a smaller circle (r 8, z 70). On such faces the
// oracle takes the Newton projection from the mesh foot and searches the
// whole face only where that finds no extremum inside it (a global search at
// every query kept eval busy for over 15 minutes on a part with variable
// fillets); the distances and sides must still be OCCT's.
TEST(ExactOracle, AgreesWithDistShapeShapeOnBSplineLoft) {
  BRepOffsetAPI_ThruSections loft(true, false);
  loft.AddWire(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(0, 0, 0), gp::DZ()), 20))));
  BRepBuilderAPI_MakePolygon square;
  for (int k = 0; k < 4; ++k)
    square.Add(gp_Pnt(15 * std::sqrt(2.0) * std::cos(M_PI / 2 * k), 15 * std::sqrt(2.0) * std::sin(M_PI / 2 * k), 40));
  square.Close();
  loft.AddWire(square.Wire());
  loft.AddWire(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(0, 0, 70), gp::DZ()), 8))));
  loft.Build();
  ASSERT_TRUE(loft.IsDone());
  int splineFaces = 0;
  for (TopExp_Explorer ex(loft.Shape(), TopAbs_FACE); ex.More(); ex.Next())
    splineFaces += BRepAdaptor_Surface(TopoDS::Face(ex.Current())).GetType() == GeomAbs_BSplineSurface;
  ASSERT_GT(splineFaces, 0);
  expectAgreesWithOcct(loft.Shape(), "B-spline loft", 300);
}

// A box 60 x 40 x 30 with every edge rounded from r 1.5 to r 5: B-spline
// fillet faces, whose closest point from inside the box is often on their
// boundary. There the oracle searches the face by Newton from its mesh
// triangles near the query, not by OCCT's global search (ExactOracle::query);
// the distances and sides must still be OCCT's.
TEST(ExactOracle, AgreesWithDistShapeShapeOnVariableFillets) {
  BRepPrimAPI_MakeBox box(60, 40, 30);
  BRepFilletAPI_MakeFillet fillet(box.Shape());
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(box.Shape(), TopAbs_EDGE, edges);
  for (int i = 1; i <= edges.Extent(); ++i) fillet.Add(1.5, 5, TopoDS::Edge(edges(i)));
  fillet.Build();
  ASSERT_TRUE(fillet.IsDone());
  int splineFaces = 0;
  for (TopExp_Explorer ex(fillet.Shape(), TopAbs_FACE); ex.More(); ex.Next())
    splineFaces += BRepAdaptor_Surface(TopoDS::Face(ex.Current())).GetType() == GeomAbs_BSplineSurface;
  ASSERT_GE(splineFaces, 12);
  expectAgreesWithOcct(fillet.Shape(), "variable fillets", 400);
}

// Every closed solid of the public models (first two per file), when present.
TEST(ExactOracle, AgreesWithDistShapeShapeOnPublicModels) {
  const std::string dir = CADMEDIAL_PUBLIC_MODELS_DIR;
  if (!std::filesystem::exists(dir + "/MANIFEST.tsv")) GTEST_SKIP() << "public models not present";
  int solids = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string ext = entry.path().extension().string();
    if (ext == ".tsv" || ext == ".md") continue;
    LoadedModel model;
    try {
      model = loadModel(entry.path().string());
    } catch (const std::exception&) {
      continue;  // files without a closed solid are the sampling tests' business
    }
    for (std::size_t i = 0; i < model.solids.size() && i < 2; ++i, ++solids)
      expectAgreesWithOcct(model.solids[i], entry.path().filename().string() + " solid " + std::to_string(i), 40);
  }
  EXPECT_GT(solids, 10);
}

// Points where every boundary point of a face is equally far (analytic
// solvers give up there); the answer is known by hand (models/EXPECTED.md).
TEST(ExactOracle, DegeneratePointsHaveHandDistances) {
  {
    ExactOracle box(loadModel(modelPath("box.step")).solids[0]);  // [0,40]x[0,30]x[0,20]
    EXPECT_NEAR(box.distance(gp_Pnt(20, 15, 10)), 10, 1e-12);
    EXPECT_NEAR(box.distance(gp_Pnt(5, 5, 5)), 5, 1e-12);
    EXPECT_NEAR(box.distance(gp_Pnt(-3, -4, 10)), 5, 1e-12);  // closest to the vertical edge x = y = 0
  }
  {
    ExactOracle cyl(loadModel(modelPath("cylinder.step")).solids[0]);  // R 10, z 0..30, axis z
    EXPECT_NEAR(cyl.distance(gp_Pnt(0, 0, 15)), 10, 1e-9);
    EXPECT_NEAR(cyl.distance(gp_Pnt(0, 0, 5)), 5, 1e-9);
    EXPECT_NEAR(cyl.distance(gp_Pnt(0, 0, 40)), 10, 1e-9);
  }
  {
    ExactOracle torus(loadModel(modelPath("torus.step")).solids[0]);  // R 30, r 10, axis z
    for (double a : {0.0, 0.3, 1.0, 2.5, 4.0}) {
      const gp_Pnt core(30 * std::cos(a), 30 * std::sin(a), 0);
      EXPECT_NEAR(torus.distance(core), 10, 1e-9) << "core circle at angle " << a;
      const std::vector<BoundaryPoint> near = torus.nearPoints(core, 1e-6);
      ASSERT_FALSE(near.empty());
      EXPECT_NEAR(near.front().distance, 10, 1e-9);
    }
    EXPECT_NEAR(torus.distance(gp_Pnt(0, 0, 0)), 20, 1e-9);  // centre: the inner equator
  }
}

// Points whose closest boundary point is inside a seam or a tangent edge
// (not a face point: the medial facets over edge samples put many there):
// the normal of either face decides, as OCCT's classifier does, and the
// classifier is not asked.
void expectSmoothEdgeSidesByNormal(const TopoDS_Shape& solid, const std::vector<std::pair<gp_Pnt, gp_Vec>>& probes) {
  ExactOracle oracle(solid);
  BRepClass3d_SolidClassifier classifier(solid);
  int inner = 0, outer = 0;
  for (const auto& [onEdge, outward] : probes)
    for (double d : {-2.0, -0.5, -0.01, 0.01, 0.5, 2.0}) {
      const gp_Pnt p = onEdge.Translated(outward * d);
      classifier.Perform(p, 1e-9);
      const bool expected = classifier.State() == TopAbs_IN;
      double distance = 0;
      EXPECT_EQ(oracle.inside(p, 0, &distance), expected) << "at (" << p.X() << ", " << p.Y() << ", " << p.Z() << ")";
      EXPECT_NEAR(distance, std::abs(d), 1e-9);
      (expected ? inner : outer)++;
    }
  EXPECT_GT(inner, 0);
  EXPECT_GT(outer, 0);
  EXPECT_EQ(oracle.classifierQueries(), 0u);
}

TEST(ExactOracle, ASeamOrATangentEdgeDecidesTheSideByTheNormal) {
  {
    // The cylinder's seam (R 10, z 0..30): radial lines through it.
    const TopoDS_Shape cylinder = loadModel(modelPath("cylinder.step")).solids[0];
    std::vector<std::pair<gp_Pnt, gp_Vec>> probes;
    for (TopExp_Explorer faces(cylinder, TopAbs_FACE); faces.More(); faces.Next())
      for (TopExp_Explorer edges(faces.Current(), TopAbs_EDGE); edges.More(); edges.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(edges.Current());
        if (!BRep_Tool::IsClosed(edge, TopoDS::Face(faces.Current()))) continue;
        const BRepAdaptor_Curve curve(edge);
        for (double f : {0.25, 0.5, 0.75}) {
          const gp_Pnt q = curve.Value(curve.FirstParameter() + f * (curve.LastParameter() - curve.FirstParameter()));
          probes.emplace_back(q, gp_Vec(q.X(), q.Y(), 0).Normalized());
        }
      }
    ASSERT_FALSE(probes.empty()) << "the cylinder has no seam";
    expectSmoothEdgeSidesByNormal(cylinder, probes);
  }
  {
    // A box 40 x 30 x 20 with its edge x = 40, y = 30 rounded (r 5): the
    // fillet meets the face y = 30 tangentially along x = 35, the face
    // x = 40 along y = 25.
    BRepPrimAPI_MakeBox box(40, 30, 20);
    BRepFilletAPI_MakeFillet fillet(box.Shape());
    for (TopExp_Explorer edges(box.Shape(), TopAbs_EDGE); edges.More(); edges.Next()) {
      const BRepAdaptor_Curve curve(TopoDS::Edge(edges.Current()));
      const gp_Pnt mid = curve.Value(0.5 * (curve.FirstParameter() + curve.LastParameter()));
      if (std::abs(mid.X() - 40) < 1e-9 && std::abs(mid.Y() - 30) < 1e-9) fillet.Add(5, TopoDS::Edge(edges.Current()));
    }
    fillet.Build();
    ASSERT_TRUE(fillet.IsDone());
    const TopoDS_Shape rounded = fillet.Shape();
    expectSmoothEdgeSidesByNormal(rounded, {{gp_Pnt(35, 30, 5), gp_Vec(0, 1, 0)},
                                            {gp_Pnt(35, 30, 12), gp_Vec(0, 1, 0)},
                                            {gp_Pnt(40, 25, 8), gp_Vec(1, 0, 0)}});
  }
}

double largestAngleDeg(const gp_Pnt& v, const std::vector<BoundaryPoint>& near) {
  double best = 0;
  for (const BoundaryPoint& a : near)
    for (const BoundaryPoint& b : near) best = std::max(best, gp_Vec(v, a.point).Angle(gp_Vec(v, b.point)));
  return best * 180 / kPi;
}

// nearPoints finds both sides of a medial ball, also where the contact is a
// whole circle of one face, and only one side off the axis.
TEST(ExactOracle, NearPointsSeeEveryContactOfAMedialBall) {
  ExactOracle torus(loadModel(modelPath("torus.step")).solids[0]);
  for (double a : {0.0, 0.3, 1.0, 2.5, 4.0}) {
    const gp_Pnt core(30 * std::cos(a), 30 * std::sin(a), 0);
    const std::vector<BoundaryPoint> near = torus.nearPoints(core, 1e-6);
    for (const BoundaryPoint& b : near) EXPECT_NEAR(b.distance, 10, 1e-6);
    EXPECT_GT(largestAngleDeg(core, near), 90) << "core circle at angle " << a;
  }
  const gp_Pnt offCore(33, 0, 1);  // 3.2 from the core: one contact, even with slack 1
  EXPECT_LT(largestAngleDeg(offCore, torus.nearPoints(offCore, 1.0)), 10);

  ExactOracle box(loadModel(modelPath("box.step")).solids[0]);
  EXPECT_NEAR(largestAngleDeg(gp_Pnt(20, 15, 10), box.nearPoints(gp_Pnt(20, 15, 10), 1e-9)), 180, 1e-6);
  EXPECT_NEAR(largestAngleDeg(gp_Pnt(20, 4, 4), box.nearPoints(gp_Pnt(20, 4, 4), 1e-9)), 90, 1e-6);
  EXPECT_LT(largestAngleDeg(gp_Pnt(20, 15, 3), box.nearPoints(gp_Pnt(20, 15, 3), 1.0)), 1e-6);

  ExactOracle cylinder(loadModel(modelPath("cylinder.step")).solids[0]);
  EXPECT_GT(largestAngleDeg(gp_Pnt(0, 0, 15), cylinder.nearPoints(gp_Pnt(0, 0, 15), 1e-6)), 90);
}

// Queries per second of distance() and inside() on random points of the
// bounding box (single thread). Printed; the README quotes these.
void measureSpeed(const std::string& path, int count) {
  const LoadedModel model = loadModel(path);
  ASSERT_FALSE(model.solids.empty());
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  ExactOracle oracle(model.solids[0]);
  const auto t1 = Clock::now();
  const std::vector<gp_Pnt> points = randomPoints(oracle, count, 11);
  double sum = 0;
  for (const gp_Pnt& p : points) sum += oracle.distance(p);
  const auto t2 = Clock::now();
  int in = 0;
  for (const gp_Pnt& p : points) in += oracle.inside(p, 1e-6 * oracle.diagonal());
  const auto t3 = Clock::now();
  auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  std::printf("%s: %d faces, %zu mesh triangles, build %.2f s, distance %.0f queries/s, inside %.0f queries/s "
              "(%d of %d inside, mean distance %.3g)\n",
              std::filesystem::path(path).filename().c_str(), oracle.faceCount(), oracle.meshTriangles(),
              seconds(t0, t1), count / seconds(t1, t2), count / seconds(t2, t3), in, count, sum / count);
  // Accuracy on a few points of the same model (DistShapeShape is slow on big models).
  const TopoDS_Shape faces = facesOf(model.solids[0]);
  BRepClass3d_SolidClassifier classifier(model.solids[0]);
  for (int i = 0; i < 40; ++i) {
    const double ref = referenceDistance(faces, points[i]);
    EXPECT_NEAR(oracle.distance(points[i]), ref, 1e-7 * oracle.diagonal());
    classifier.Perform(points[i], 1e-6 * oracle.diagonal());
    if (ref > 1e-5 * oracle.diagonal()) {
      EXPECT_EQ(oracle.inside(points[i], 1e-6 * oracle.diagonal()), classifier.State() != TopAbs_OUT);
    }
  }
}

TEST(ExactOracleSpeed, Flange) { measureSpeed(modelPath("flange.step"), 20000); }

TEST(ExactOracleSpeed, NistCtc01) {
  const std::string path = std::string(CADMEDIAL_PUBLIC_MODELS_DIR) + "/nist_ctc_01_asme1_rd.stp";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "public models not present";
  measureSpeed(path, 5000);
}

}  // namespace
}  // namespace cadmedial
