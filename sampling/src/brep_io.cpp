// OCC_CATCH_SIGNALS below is a setjmp only with this defined before OCCT's
// headers (occt_signals.hpp).
#define OCC_CONVERT_SIGNALS
#include "cadmedial/brep_io.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepLib.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <Bnd_Box.hxx>
#include <Precision.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Message_Messenger.hxx>
#include <OSD_Signal.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_ErrorHandler.hxx>
#include <ShapeFix_Shape.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>

#include "cadmedial/errors.hpp"
#include "occt_signals.hpp"
#include "sewn_solids.hpp"

namespace cadmedial {
namespace fs = std::filesystem;

namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// OCCT prints translation chatter on stdout; our stdout is for results.
void silenceOcctMessages() {
  static bool done = false;
  if (done) return;
  done = true;
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_Printer));
}

[[noreturn]] void unreadable(const std::string& path, const std::string& why) {
  throw InputError(kExitUnreadableInput, path + ": " + why);
}

// Entities whose translation failed (a misspelt or malformed entity that a
// shape refers to, a crash in the translator caught as a signal): the
// shapes that needed them are missing from the result.
int failedTranslations(const XSControl_Reader& reader) {
  const Handle(XSControl_WorkSession) session = reader.WS();
  if (session.IsNull() || session->TransferReader().IsNull()) return 0;
  const Handle(Transfer_TransientProcess) process = session->TransferReader()->TransientProcess();
  if (process.IsNull()) return 0;
  int failed = 0;
  Interface_CheckIterator checks = process->CheckList(false);
  for (checks.Start(); checks.More(); checks.Next()) failed += checks.Value()->HasFailed();
  return failed;
}

std::string translationFailures(int failed) {
  return std::to_string(failed) + " entit" + (failed == 1 ? "y" : "ies") + " could not be translated";
}

// Translates every root; a shape missing for failed entities is a warning
// when something was translated, the error otherwise.
TopoDS_Shape transferRoots(XSControl_Reader& reader, const std::string& path, const std::string& format,
                           std::vector<std::string>& warnings) {
  reader.TransferRoots();
  TopoDS_Shape shape = reader.OneShape();
  const int failed = failedTranslations(reader);
  if (shape.IsNull())
    unreadable(path, format + " file holds no geometry that could be translated" +
                         (failed > 0 ? " (" + translationFailures(failed) + ")" : ""));
  if (failed > 0) warnings.push_back(translationFailures(failed) + ": the shapes that use them are missing");
  return shape;
}

// Each reader sets up its OCC_CATCH_SIGNALS after its locals, so a crash
// caught there unwinds through them (the reader and its model are freed).
TopoDS_Shape readStep(const std::string& path, std::vector<std::string>& warnings) {
  STEPControl_Reader reader;
  OCC_CATCH_SIGNALS
  Interface_Static::SetCVal("xstep.cascade.unit", "MM");
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
    unreadable(path, "not a readable STEP file (syntax error or truncated)");
  if (reader.NbRootsForTransfer() == 0) unreadable(path, "STEP file holds no shape to transfer");
  return transferRoots(reader, path, "STEP", warnings);
}

TopoDS_Shape readIges(const std::string& path, std::vector<std::string>& warnings) {
  IGESControl_Reader reader;
  OCC_CATCH_SIGNALS
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
    unreadable(path, "not a readable IGES file (syntax error or truncated)");
  return transferRoots(reader, path, "IGES", warnings);
}

TopoDS_Shape readBrepFile(const std::string& path) {
  TopoDS_Shape shape;
  BRep_Builder builder;
  OCC_CATCH_SIGNALS
  if (!BRepTools::Read(shape, path.c_str(), builder) || shape.IsNull())
    unreadable(path, "not a readable BREP file");
  return shape;
}

std::string describeCensus(const ShapeCensus& c) {
  if (c.faces == 0) return "found nothing (no faces)";
  std::ostringstream s;
  s << "found ";
  if (c.solids > 0) s << c.solids << " solid(s) without a closed shell, ";
  s << c.shells << " shell(s) (" << c.openShells << " open), " << c.faces << " face(s)";
  return s.str();
}

}  // namespace

ShapeCensus takeCensus(const TopoDS_Shape& shape) {
  ShapeCensus c;
  TopTools_IndexedMapOfShape solids, shells, faces;
  TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  TopExp::MapShapes(shape, TopAbs_SHELL, shells);
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  c.solids = solids.Extent();
  c.shells = shells.Extent();
  c.faces = faces.Extent();
  for (int i = 1; i <= shells.Extent(); ++i)
    if (!BRep_Tool::IsClosed(shells(i))) ++c.openShells;
  for (TopExp_Explorer e(shape, TopAbs_SHELL, TopAbs_SOLID); e.More(); e.Next()) ++c.looseShells;
  for (TopExp_Explorer e(shape, TopAbs_FACE, TopAbs_SHELL); e.More(); e.Next()) ++c.looseFaces;
  return c;
}

namespace {

bool hasOnlyClosedShells(const TopoDS_Solid& solid) {
  bool closed = true, hasFace = false;
  for (TopExp_Explorer s(solid, TopAbs_SHELL); s.More(); s.Next()) {
    hasFace = true;
    if (!BRep_Tool::IsClosed(s.Current())) closed = false;
  }
  return closed && hasFace;
}

// A solid BRepCheck rejects can send OCCT's own algorithms into endless
// loops: a shelled, filleted box with a misoriented sub-shape kept
// BRepTopAdaptor_FClass2d::Perform busy for 15 minutes while its corners
// were classified. ShapeFix mends the common faults (orientation, wires,
// tolerances). Its result is used only when BRepCheck accepts it, it is one
// closed solid with nothing beside it, and its area is the original's (no
// face lost); otherwise the original is kept. A warning says which. ShapeFix
// works on a copy: it edits shared sub-shapes in place.
bool isValidShape(const TopoDS_Shape& shape) {
  try {
    return BRepCheck_Analyzer(shape, Standard_True, Standard_True).IsValid();
  } catch (const Standard_Failure&) {
    return false;
  }
}

// Sum of the faces' unsigned areas: a misoriented face counts negatively in
// the shape's own surface properties (the hollowed box: 20 730 against 23 480
// after the repair), which is what the repair fixes.
double areaOf(const TopoDS_Shape& shape) {
  double sum = 0;
  for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) {
    GProp_GProps props;
    BRepGProp::SurfaceProperties(f.Current(), props);
    sum += std::abs(props.Mass());
  }
  return sum;
}

int faceCount(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  return faces.Extent();
}

TopoDS_Solid repairedIfInvalid(const TopoDS_Solid& solid, int index, std::vector<std::string>* warnings) {
  if (isValidShape(solid)) return solid;
  const std::string which = "solid " + std::to_string(index);
  try {
    ShapeFix_Shape fix(BRepBuilderAPI_Copy(solid).Shape());
    fix.Perform();
    const TopoDS_Shape result = fix.Shape();
    TopExp_Explorer e(result, TopAbs_SOLID);
    if (e.More()) {
      const TopoDS_Solid fixed = TopoDS::Solid(e.Current());
      e.Next();
      const double area = areaOf(solid);
      const bool alone = !e.More() && faceCount(result) == faceCount(fixed);
      const bool sameArea = std::abs(areaOf(fixed) - area) <= 1e-6 * std::abs(area);
      if (alone && sameArea && hasOnlyClosedShells(fixed) && isValidShape(fixed)) {
        if (warnings) warnings->push_back(which + ": not a valid B-rep (BRepCheck); repaired with ShapeFix");
        return fixed;
      }
    }
  } catch (const Standard_Failure&) {
    // fall through: keep the original
  }
  if (warnings)
    warnings->push_back(which + ": not a valid B-rep (BRepCheck) and ShapeFix could not mend it; "
                                "the axis may be wrong, or OCCT may not finish on it");
  return solid;
}

// A solid reaching past what OCCT treats as infinite (Precision::Infinite,
// 2e100), or with a coordinate that is not a number: only a malformed file
// gives one (a STEP point at 1e300), squared lengths overflow, and OCCT's
// point-in-face tests on it had not finished after 5 minutes.
bool reachesInfinity(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box, /*useTriangulation=*/false);
  for (TopExp_Explorer v(shape, TopAbs_VERTEX); v.More(); v.Next()) box.Add(BRep_Tool::Pnt(TopoDS::Vertex(v.Current())));
  if (box.IsVoid()) return false;
  if (box.IsOpen()) return true;
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  for (double c : {x0, y0, z0, x1, y1, z1})
    if (!(std::abs(c) < Precision::Infinite())) return true;
  return false;
}

// STEP files often give a plane face's edges no curve in the plane's (u, v)
// (OCCT's reader drops them), and OCCT then projects the 3D curve again on
// every BRep_Tool::CurveOnSurface call (BRep_Tool::CurveOnPlane); the
// sampling asks thousands of times (vertex classification, spacings,
// triplets, face reconstruction: a tenth of the lever's sampling time).
// BRepLib stores that same projection once. The solids are the caller's own
// (read from a file or BREP text; brep_io.hpp says so). Run after a solid's
// validity check, which so sees it as read (unless an earlier solid shares
// its edges).
void storePlanePcurves(const TopoDS_Solid& solid) {
  for (TopExp_Explorer f(solid, TopAbs_FACE); f.More(); f.Next()) {
    const TopoDS_Face& face = TopoDS::Face(f.Current());
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
      try {
        BRepLib::BuildPCurveForEdgeOnPlane(TopoDS::Edge(e.Current()), face);
      } catch (const Standard_Failure&) {
        // an edge OCCT cannot project keeps being projected on demand, as before
      }
    }
  }
}

}  // namespace

std::vector<TopoDS_Solid> closedSolidsOf(const TopoDS_Shape& shape, std::vector<std::string>* warnings,
                                         std::string* sewing) {
  std::vector<TopoDS_Solid> result;
  int index = 0;
  for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next(), ++index) {
    const TopoDS_Solid& solid = TopoDS::Solid(e.Current());
    if (reachesInfinity(solid)) {
      if (warnings)
        warnings->push_back("solid " + std::to_string(index) +
                            " skipped: it reaches coordinates beyond 2e100 (what OCCT treats as infinite)");
    } else if (hasOnlyClosedShells(solid)) {
      result.push_back(repairedIfInvalid(solid, index, warnings));
      storePlanePcurves(result.back());
    } else if (warnings) {
      warnings->push_back("solid " + std::to_string(index) + " skipped: its shell is not closed");
    }
  }
  if (!result.empty()) return result;
  // No closed solid: the faces may still close up (surface models), unless
  // they reach past infinity (sewing a skipped solid's faces would make it
  // again). Sewn from faces inside finite bounds, a solid stays inside them.
  if (reachesInfinity(shape))
    throw InputError(kExitUnreadableInput,
                     "no closed solid within bounds: the shape reaches coordinates beyond 2e100, what OCCT treats "
                     "as infinite (a malformed file)");
  SewingOutcome outcome;
  const std::vector<TopoDS_Solid> sewn = solidsSewnFromFaces(shape, &outcome);
  if (!outcome.tried) return result;
  if (sewing) *sewing = describeSewing(outcome);
  if (!sewn.empty() && warnings)
    warnings->push_back("no closed solid in the input; its faces were " + describeSewing(outcome) + ", made into " +
                        std::to_string(sewn.size()) + " solid(s)");
  for (std::size_t k = 0; k < sewn.size(); ++k) {
    result.push_back(repairedIfInvalid(sewn[k], static_cast<int>(k), warnings));
    storePlanePcurves(result.back());
  }
  return result;
}

TopoDS_Shape readBrepString(const std::string& brepText) {
  silenceOcctMessages();
  TopoDS_Shape shape;
  BRep_Builder builder;
  std::istringstream in(brepText);
  try {
    catchingOcctSignals([&] {
      OCC_CATCH_SIGNALS
      BRepTools::Read(shape, in, builder);
    });
  } catch (const Standard_Failure& f) {
    throw InputError(kExitUnreadableInput, std::string("BREP text could not be read: ") + f.GetMessageString());
  }
  if (shape.IsNull()) throw InputError(kExitUnreadableInput, "BREP text holds no shape");
  return shape;
}

LoadedModel loadModel(const std::string& path) {
  silenceOcctMessages();
  std::error_code ec;
  if (!fs::exists(path, ec)) unreadable(path, "no such file");
  if (fs::is_directory(path, ec)) unreadable(path, "is a directory, not a file");
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe) unreadable(path, "cannot be opened (permission?)");
  }
  if (fs::file_size(path, ec) == 0) unreadable(path, "empty file");

  const std::string ext = lowerExtension(path);
  LoadedModel model;
  model.path = path;
  try {
    catchingOcctSignals([&] {
      if (ext == ".step" || ext == ".stp")
        model.shape = readStep(path, model.warnings);
      else if (ext == ".iges" || ext == ".igs")
        model.shape = readIges(path, model.warnings);
      else if (ext == ".brep" || ext == ".brp")
        model.shape = readBrepFile(path);
      else
        unreadable(path, "unknown extension '" + ext + "' (expected .step .stp .iges .igs .brep)");
    });
  } catch (const OSD_Signal& crash) {
    unreadable(path, std::string("the OCCT reader crashed on this file (") + crash.DynamicType()->Name() +
                         "): it is malformed or uses what OCCT cannot read");
  } catch (const Standard_Failure& f) {
    unreadable(path, std::string("reader failed: ") + f.GetMessageString());
  }

  model.census = takeCensus(model.shape);
  std::string sewing;
  try {
    model.solids = closedSolidsOf(model.shape, &model.warnings, &sewing);
  } catch (const InputError& e) {
    throw InputError(e.code(), path + ": " + e.what());
  }
  if (model.solids.empty())
    throw InputError(kExitNoSolid, path + ": no closed solid; " + describeCensus(model.census) +
                                       (sewing.empty() ? "" : "; " + sewing));
  if (!sewing.empty()) return model;  // every face was sewn: none was ignored
  if (model.census.looseShells > 0)
    model.warnings.push_back(std::to_string(model.census.looseShells) +
                             " shell(s) outside any solid were ignored");
  if (model.census.looseFaces > 0)
    model.warnings.push_back(std::to_string(model.census.looseFaces) + " face(s) outside any shell were ignored");
  return model;
}

}  // namespace cadmedial
