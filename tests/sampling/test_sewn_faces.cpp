// Files without a solid whose faces close up (IGES trimmed surfaces, STEP
// surface models, a solid's faces written one by one) are sewn into solids,
// checked against the exact solid they came from: volume, validity, which
// side is inside, a void kept as a void. Faces that do not close still give
// the documented no-solid error, now saying what the sewing did.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Pnt.hxx>

#include "cadmedial/brep_io.hpp"
#include "cadmedial/errors.hpp"
#include "model_fixtures.hpp"

namespace cadmedial {
namespace {
namespace fs = std::filesystem;

class SewnFaces : public test::ScratchDirTest {
 protected:
  // The faces of a shape, each copied on its own (no edge shared any more,
  // as in a file of trimmed surfaces), in a compound; `skip` leaves one out.
  static TopoDS_Compound looseFaces(const TopoDS_Shape& shape, int skip = -1) {
    BRep_Builder builder;
    TopoDS_Compound compound;
    builder.MakeCompound(compound);
    int index = 0;
    for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next(), ++index)
      if (index != skip) builder.Add(compound, BRepBuilderAPI_Copy(f.Current()).Shape());
    return compound;
  }
  std::string writeBrep(const TopoDS_Shape& shape, const std::string& name) {
    const std::string path = (dir_ / name).string();
    EXPECT_TRUE(BRepTools::Write(shape, path.c_str()));
    return path;
  }
  static double volumeOf(const TopoDS_Shape& shape) {
    GProp_GProps props;
    BRepGProp::VolumeProperties(shape, props);
    return props.Mass();
  }
  static TopAbs_State stateOf(const TopoDS_Shape& solid, const gp_Pnt& p) {
    BRepClass3d_SolidClassifier classifier(solid, p, 1e-7);
    return classifier.State();
  }
  static bool warnedOfSewing(const LoadedModel& model) {
    return !test::warningContaining(model.warnings, "sewn at tolerance").empty();
  }
};

TEST_F(SewnFaces, LooseFacesOfABoxBecomeTheBox) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(40, 30, 20).Shape();
  const LoadedModel model = loadModel(writeBrep(looseFaces(box), "box_faces.brep"));
  ASSERT_EQ(model.solids.size(), 1u);
  EXPECT_NEAR(volumeOf(model.solids[0]), 24000, 1e-6);  // positive: matter inside
  EXPECT_TRUE(BRepCheck_Analyzer(model.solids[0]).IsValid());
  EXPECT_EQ(stateOf(model.solids[0], gp_Pnt(20, 15, 10)), TopAbs_IN);
  EXPECT_EQ(stateOf(model.solids[0], gp_Pnt(50, 15, 10)), TopAbs_OUT);
  EXPECT_TRUE(warnedOfSewing(model));
}

TEST_F(SewnFaces, IgesTrimmedSurfacesBecomeTheSolid) {
  // IGES in faces mode (trimmed surfaces, no B-rep solid entity), as many
  // CAD systems write it; OCCT reads it back as loose faces.
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(gp_Pnt(-5, 2, 1), 40, 30, 20).Shape();
  IGESControl_Controller::Init();
  IGESControl_Writer writer("MM", 0);
  ASSERT_TRUE(writer.AddShape(box));
  writer.ComputeModel();
  const std::string path = (dir_ / "box_faces.igs").string();
  ASSERT_TRUE(writer.Write(path.c_str()));

  const LoadedModel model = loadModel(path);
  EXPECT_EQ(model.census.solids, 0);  // the file really has no solid
  ASSERT_EQ(model.solids.size(), 1u);
  EXPECT_NEAR(volumeOf(model.solids[0]), 24000, 1e-3);
  EXPECT_EQ(stateOf(model.solids[0], gp_Pnt(15, 17, 11)), TopAbs_IN);
  EXPECT_TRUE(warnedOfSewing(model));

  // And end to end: the axis is computed, with the warning on stderr.
  const fs::path out = dir_ / "out", err = dir_ / "stderr.txt";
  const std::string cmd = "timeout 120 " + std::string(CADMEDIAL_CLI) + " run '" + path + "' --no-oracle -o '" +
                          out.string() + "' >/dev/null 2>'" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_TRUE(fs::exists(out / "solid_0" / "medial.ply"));
  std::ifstream in(err);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("sewn at tolerance"), std::string::npos) << text;
}

TEST_F(SewnFaces, ABundledPartWrittenAsIgesSurfacesComesBackWhole) {
  // The flange (cylinders, fillets, holes) as FreeCAD's IGES export writes
  // any part: trimmed surfaces only. Sewn, it is the STEP flange again:
  // same volume and area, valid.
  const LoadedModel step = loadModel(std::string(CADMEDIAL_MODELS_DIR) + "/flange.step");
  ASSERT_EQ(step.solids.size(), 1u);
  IGESControl_Controller::Init();
  IGESControl_Writer writer("MM", 0);
  ASSERT_TRUE(writer.AddShape(step.solids[0]));
  writer.ComputeModel();
  const std::string path = (dir_ / "flange_faces.igs").string();
  ASSERT_TRUE(writer.Write(path.c_str()));

  const LoadedModel iges = loadModel(path);
  EXPECT_EQ(iges.census.solids, 0);
  ASSERT_EQ(iges.solids.size(), 1u);
  EXPECT_TRUE(BRepCheck_Analyzer(iges.solids[0]).IsValid());
  const double volume = volumeOf(step.solids[0]);
  EXPECT_NEAR(volumeOf(iges.solids[0]), volume, 1e-6 * volume);
  GProp_GProps a, b;
  BRepGProp::SurfaceProperties(step.solids[0], a);
  BRepGProp::SurfaceProperties(iges.solids[0], b);
  EXPECT_NEAR(b.Mass(), a.Mass(), 1e-6 * a.Mass());
}

TEST_F(SewnFaces, AClosedShellInsideAnotherIsItsVoid) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(40, 30, 20).Shape();
  const TopoDS_Shape ball = BRepPrimAPI_MakeSphere(gp_Pnt(20, 15, 10), 6).Shape();
  const TopoDS_Shape hollow = BRepAlgoAPI_Cut(box, ball).Shape();
  const double exact = 24000 - 4.0 / 3.0 * M_PI * 216;
  ASSERT_NEAR(volumeOf(hollow), exact, 1e-6 * exact);  // the fixture is what it says

  const LoadedModel model = loadModel(writeBrep(looseFaces(hollow), "hollow_faces.brep"));
  ASSERT_EQ(model.solids.size(), 1u);
  EXPECT_NEAR(volumeOf(model.solids[0]), exact, 1e-6 * exact);
  EXPECT_EQ(stateOf(model.solids[0], gp_Pnt(20, 15, 10)), TopAbs_OUT);  // in the void
  EXPECT_EQ(stateOf(model.solids[0], gp_Pnt(2, 2, 2)), TopAbs_IN);
  int shells = 0;
  for (TopExp_Explorer s(model.solids[0], TopAbs_SHELL); s.More(); s.Next()) ++shells;
  EXPECT_EQ(shells, 2);
}

TEST_F(SewnFaces, InwardFacesAndOverlappingBodiesGiveTheirOwnSolids) {
  // The box's faces all reversed (normals inward): still the box, matter inside.
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(40, 30, 20).Shape();
  const LoadedModel inward = loadModel(writeBrep(looseFaces(box.Reversed()), "inward.brep"));
  ASSERT_EQ(inward.solids.size(), 1u);
  EXPECT_NEAR(volumeOf(inward.solids[0]), 24000, 1e-6);
  EXPECT_EQ(stateOf(inward.solids[0], gp_Pnt(20, 15, 10)), TopAbs_IN);

  // Two boxes that overlap (a surface model of two bodies crossing): two
  // solids, neither made the other's void (a corner of the small one is
  // inside the big one, others are outside).
  const TopoDS_Shape big = BRepPrimAPI_MakeBox(40, 30, 20).Shape();
  const TopoDS_Shape small = BRepPrimAPI_MakeBox(gp_Pnt(30, 20, 10), 20, 20, 20).Shape();
  BRep_Builder builder;
  TopoDS_Compound both;
  builder.MakeCompound(both);
  builder.Add(both, looseFaces(big));
  builder.Add(both, looseFaces(small));
  const LoadedModel crossing = loadModel(writeBrep(both, "crossing.brep"));
  ASSERT_EQ(crossing.solids.size(), 2u);
  EXPECT_NEAR(volumeOf(crossing.solids[0]) + volumeOf(crossing.solids[1]), 24000 + 8000, 1e-6);
}

TEST_F(SewnFaces, FacesThatDoNotCloseAreStillNoSolid) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(40, 30, 20).Shape();
  const std::string path = writeBrep(looseFaces(box, 0), "open_box.brep");
  try {
    loadModel(path);
    ADD_FAILURE() << "a box without one face has no solid";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), kExitNoSolid);
    const std::string what = e.what();
    EXPECT_NE(what.find("sewn at tolerance"), std::string::npos) << what;
    EXPECT_NE(what.find("left open"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace cadmedial
