// loadModel stores the (u, v) curves OCCT would otherwise project again on
// every call for the edges of plane faces (BRep_Tool::CurveOnPlane), and
// they are the same curves: checked against a plain STEP read of the file.
#include <gtest/gtest.h>

#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Plane.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include "cadmedial/brep_io.hpp"
#include "model_fixtures.hpp"

namespace cadmedial {
namespace {

struct PlaneEdge {
  TopoDS_Edge edge;
  TopoDS_Face face;
};

// Every (edge, plane face) pair of the solids, in explorer order.
std::vector<PlaneEdge> planeEdges(const TopoDS_Shape& shape) {
  std::vector<PlaneEdge> out;
  for (TopExp_Explorer s(shape, TopAbs_SOLID); s.More(); s.Next())
    for (TopExp_Explorer f(s.Current(), TopAbs_FACE); f.More(); f.Next()) {
      const TopoDS_Face& face = TopoDS::Face(f.Current());
      if (Handle(Geom_Plane)::DownCast(BRep_Tool::Surface(face)).IsNull()) continue;
      for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) out.push_back({TopoDS::Edge(e.Current()), face});
    }
  return out;
}

// Pairs whose pcurve OCCT computes on demand (not stored in the edge).
int projectedOnDemand(const std::vector<PlaneEdge>& pairs) {
  int count = 0;
  for (const PlaneEdge& p : pairs) {
    double first, last;
    Standard_Boolean stored = Standard_False;
    const Handle(Geom2d_Curve) c = BRep_Tool::CurveOnSurface(p.edge, p.face, first, last, &stored);
    count += !c.IsNull() && !stored;
  }
  return count;
}

void expectStoredPlanePcurves(const std::string& path, int& missingBefore) {
  STEPControl_Reader reader;
  ASSERT_EQ(reader.ReadFile(path.c_str()), IFSelect_RetDone) << path;
  reader.TransferRoots();
  const std::vector<PlaneEdge> raw = planeEdges(reader.OneShape());
  const LoadedModel model = loadModel(path);
  TopoDS_Compound solids;
  BRep_Builder builder;
  builder.MakeCompound(solids);
  for (const TopoDS_Solid& s : model.solids) builder.Add(solids, s);
  const std::vector<PlaneEdge> loaded = planeEdges(solids);
  ASSERT_EQ(loaded.size(), raw.size()) << path;
  missingBefore += projectedOnDemand(raw);
  EXPECT_EQ(projectedOnDemand(loaded), 0) << path << ": every plane face's edge has its pcurve stored";
  for (std::size_t k = 0; k < raw.size(); ++k) {
    double f0, l0, f1, l1;
    const Handle(Geom2d_Curve) a = BRep_Tool::CurveOnSurface(raw[k].edge, raw[k].face, f0, l0);
    const Handle(Geom2d_Curve) b = BRep_Tool::CurveOnSurface(loaded[k].edge, loaded[k].face, f1, l1);
    ASSERT_EQ(a.IsNull(), b.IsNull()) << path << " pair " << k;
    if (a.IsNull()) continue;
    EXPECT_EQ(f0, f1) << path << " pair " << k;
    EXPECT_EQ(l0, l1) << path << " pair " << k;
    for (int i = 0; i <= 4; ++i) {
      const double t = f0 + (l0 - f0) * i / 4.0;
      EXPECT_EQ(a->Value(t).X(), b->Value(t).X()) << path << " pair " << k;
      EXPECT_EQ(a->Value(t).Y(), b->Value(t).Y()) << path << " pair " << k;
    }
  }
}

TEST(PlanePcurves, LoadedSolidsStoreTheProjectionOCCTWouldMakeOnDemand) {
  int missingBefore = 0;
  for (const std::string& name : test::bundledModelNames()) {
    const std::string path = test::bundledPath(test::bundledModel(name));
    if (path.size() > 5 && path.substr(path.size() - 5) == ".step") expectStoredPlanePcurves(path, missingBefore);
  }
  const std::string dir = test::publicModelsDir();
  if (!dir.empty()) expectStoredPlanePcurves(dir + "/bm2_ec_lever-A.stp", missingBefore);
  EXPECT_GT(missingBefore, 0) << "some input lacked plane pcurves (else this test shows nothing)";
}

}  // namespace
}  // namespace cadmedial
