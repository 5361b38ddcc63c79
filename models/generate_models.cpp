// cadmedial_generate_models: writes the bundled test models (STEP AP214, mm)
// into the directory given as argv[1].
//
// The STEP files in models/ are committed; this tool only regenerates them
// (target `regenerate_models`). Every model is built from OCCT primitives,
// booleans, fillets and chamfers with round dimensions, so that every property
// in models/EXPECTED.md can be derived by hand from the construction below.
// If you change a dimension here, re-derive EXPECTED.md / expected.json.

#include <APIHeaderSection_MakeHeader.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepFilletAPI_MakeChamfer.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRep_Tool.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Writer.hxx>
#include <ShapeFix_Shape.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fs = std::filesystem;

namespace {

const gp_Dir kZ(0, 0, 1);

// Vertical cylinder with its base centre at (x, y, z0).
TopoDS_Shape zCylinder(double x, double y, double z0, double radius, double height) {
  return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, z0), kZ), radius, height).Shape();
}

// Booleans leave faces split along the former tool boundaries (e.g. the
// flange's bottom face in two pieces); merge same-domain faces and edges so
// the face/edge counts are the ones a designer would count, then heal.
TopoDS_Shape cleanUp(const TopoDS_Shape& shape) {
  ShapeUpgrade_UnifySameDomain unify(shape, /*UnifyEdges=*/true, /*UnifyFaces=*/true,
                                     /*ConcatBSplines=*/false);
  unify.Build();
  ShapeFix_Shape fix(unify.Shape());
  fix.Perform();
  return fix.Shape();
}

TopoDS_Shape cut(const TopoDS_Shape& a, const TopoDS_Shape& b) {
  BRepAlgoAPI_Cut op(a, b);
  if (!op.IsDone()) throw std::runtime_error("boolean cut failed");
  return op.Shape();
}

TopoDS_Shape fuse(const TopoDS_Shape& a, const TopoDS_Shape& b) {
  BRepAlgoAPI_Fuse op(a, b);
  if (!op.IsDone()) throw std::runtime_error("boolean fuse failed");
  return op.Shape();
}

// The edge of `shape` whose midpoint is `mid` (used to pick edges for fillets
// and chamfers by geometry, independent of OCCT's internal edge order).
TopoDS_Edge edgeWithMidpoint(const TopoDS_Shape& shape, const gp_Pnt& mid) {
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  for (int i = 1; i <= edges.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(edges(i));
    gp_Pnt a = BRep_Tool::Pnt(TopExp::FirstVertex(e));
    gp_Pnt b = BRep_Tool::Pnt(TopExp::LastVertex(e));
    if (gp_Pnt((a.XYZ() + b.XYZ()) / 2).Distance(mid) < 1e-6) return e;
  }
  throw std::runtime_error("no edge with the requested midpoint");
}

// --- the models (dimensions in mm; see EXPECTED.md for the derived values) ---

// 40 x 30 x 20 box at the origin.
TopoDS_Shape makeBox() { return BRepPrimAPI_MakeBox(40, 30, 20).Shape(); }

// L profile in the XZ plane, extruded 30 along +Y. Base 60 x 10, upright leg
// 10 thick and 40 high; the inner edge at x = z = 10 is the one concave edge.
TopoDS_Shape makeLBracket() {
  BRepBuilderAPI_MakePolygon profile;
  for (auto [x, z] : std::vector<std::pair<double, double>>{
           {0, 0}, {60, 0}, {60, 10}, {10, 10}, {10, 40}, {0, 40}})
    profile.Add(gp_Pnt(x, 0, z));
  profile.Close();
  TopoDS_Face face = BRepBuilderAPI_MakeFace(profile.Wire(), /*OnlyPlane=*/true);
  return BRepPrimAPI_MakePrism(face, gp_Vec(0, 30, 0)).Shape();
}

// Cylinder R = 10, H = 30, axis Z.
TopoDS_Shape makeCylinder() { return zCylinder(0, 0, 0, 10, 30); }

// Plate 60 x 40 x 10 with a through-hole of radius 8 at its centre.
TopoDS_Shape makePlateHole() {
  TopoDS_Shape plate = BRepPrimAPI_MakeBox(60, 40, 10).Shape();
  return cleanUp(cut(plate, zCylinder(30, 20, -1, 8, 12)));
}

// Flange: disc R = 50, thickness 10; hub R = 25 up to z = 25; bore R = 12
// through disc and hub; 4 bolt holes R = 5 on pitch radius 37.5 at 0/90/180/270
// degrees. Genus 5 (bore + 4 bolt holes). The hub/disc junction circle is a
// concave edge.
TopoDS_Shape makeFlange() {
  TopoDS_Shape s = fuse(zCylinder(0, 0, 0, 50, 10), zCylinder(0, 0, 0, 25, 25));
  s = cut(s, zCylinder(0, 0, -1, 12, 27));
  const double pitch = 37.5;
  for (auto [x, y] : std::vector<std::pair<double, double>>{
           {pitch, 0}, {0, pitch}, {-pitch, 0}, {0, -pitch}})
    s = cut(s, zCylinder(x, y, -1, 5, 12));
  return cleanUp(s);
}

// Block 60 x 40 x 30; the vertical edge at x = y = 0 filleted with radius 5;
// the top edge at x = 60, z = 30 (along Y) chamfered with distance 4. The two
// modified edges share no vertex and no face.
TopoDS_Shape makeFilletChamferBlock() {
  TopoDS_Shape block = BRepPrimAPI_MakeBox(60, 40, 30).Shape();

  BRepFilletAPI_MakeFillet fillet(block);
  fillet.Add(5.0, edgeWithMidpoint(block, gp_Pnt(0, 0, 15)));
  fillet.Build();
  if (!fillet.IsDone()) throw std::runtime_error("fillet failed");
  TopoDS_Shape filleted = fillet.Shape();

  BRepFilletAPI_MakeChamfer chamfer(filleted);
  chamfer.Add(4.0, edgeWithMidpoint(filleted, gp_Pnt(60, 20, 30)));
  chamfer.Build();
  if (!chamfer.IsDone()) throw std::runtime_error("chamfer failed");
  return chamfer.Shape();
}

// Full torus, major radius 30, minor radius 10, axis Z.
TopoDS_Shape makeTorus() { return BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(0, 0, 0), kZ), 30, 10).Shape(); }

// Open-top tray: outer 60 x 40 x 20, walls and floor 2 thick (cavity
// [2,58] x [2,38] x [2,20]). The thin-feature stress test.
TopoDS_Shape makeThinWall() {
  TopoDS_Shape outer = BRepPrimAPI_MakeBox(60, 40, 20).Shape();
  TopoDS_Shape cavity = BRepPrimAPI_MakeBox(gp_Pnt(2, 2, 2), gp_Pnt(58, 38, 25)).Shape();
  return cleanUp(cut(outer, cavity));
}

// Exactly one valid solid, or an exception naming the model.
TopoDS_Shape checkedSolid(const std::string& name, const TopoDS_Shape& shape) {
  int solids = 0;
  TopoDS_Shape solid;
  for (TopExp_Explorer ex(shape, TopAbs_SOLID); ex.More(); ex.Next(), ++solids) solid = ex.Current();
  if (solids != 1)
    throw std::runtime_error(name + ": expected one solid, got " + std::to_string(solids));
  if (!BRepCheck_Analyzer(solid).IsValid()) throw std::runtime_error(name + ": invalid B-rep");
  return solid;
}

// Writes `shape` as STEP AP214 in mm. The header time stamp is fixed so that
// regenerating gives the same bytes; the file is written under a temporary
// name and renamed so a killed run never leaves a half-written model.
void writeStep(const TopoDS_Shape& shape, const std::string& name, const fs::path& dir) {
  STEPControl_Writer writer;
  Interface_Static::SetCVal("write.step.schema", "AP214IS");
  Interface_Static::SetCVal("write.step.unit", "MM");
  Interface_Static::SetCVal("xstep.cascade.unit", "MM");
  Interface_Static::SetCVal("write.step.product.name", name.c_str());
  if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone)
    throw std::runtime_error(name + ": STEP transfer failed");

  APIHeaderSection_MakeHeader header(writer.Model());
  header.SetName(new TCollection_HAsciiString((name + ".step").c_str()));
  header.SetTimeStamp(new TCollection_HAsciiString("2024-01-01T00:00:00"));
  header.SetAuthorValue(1, new TCollection_HAsciiString("cadmedial"));
  header.SetOrganizationValue(1, new TCollection_HAsciiString("cadmedial"));
  header.SetOriginatingSystem(new TCollection_HAsciiString("cadmedial_generate_models"));

  const fs::path target = dir / (name + ".step");
  const fs::path tmp = dir / (name + ".step.tmp");
  if (writer.Write(tmp.string().c_str()) != IFSelect_RetDone)
    throw std::runtime_error(name + ": cannot write " + tmp.string());
  fs::rename(tmp, target);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: " << argv[0] << " OUTPUT_DIR\n";
    return 2;
  }
  const std::vector<std::pair<std::string, std::function<TopoDS_Shape()>>> models = {
      {"box", makeBox},
      {"l_bracket", makeLBracket},
      {"cylinder", makeCylinder},
      {"plate_hole", makePlateHole},
      {"flange", makeFlange},
      {"fillet_chamfer_block", makeFilletChamferBlock},
      {"torus", makeTorus},
      {"thin_wall", makeThinWall},
  };
  try {
    const fs::path dir = argv[1];
    fs::create_directories(dir);
    // OCCT prints transfer statistics to stdout by default; keep output short.
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    STEPControl_Controller::Init();  // registers the write.step.* parameters
    for (const auto& [name, make] : models) {
      writeStep(checkedSolid(name, make()), name, dir);
      std::cout << "wrote " << (dir / (name + ".step")).string() << "\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "cadmedial_generate_models: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
