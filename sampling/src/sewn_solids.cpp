#include "sewn_solids.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Shell.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepGProp.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Vertex.hxx>

namespace cadmedial {

namespace {

// A closed shell with the solid it bounds on its own (oriented outward).
struct ClosedShell {
  TopoDS_Shell shell;
  TopoDS_Solid alone;
  double volume = 0;
  int container = -1;  // the smallest other shell enclosing it
  int depth = 0;       // how many shells enclose it
};

bool isClosed(const TopoDS_Shell& shell) {
  try {
    return BRepCheck_Shell(shell).Closed() == BRepCheck_NoError;
  } catch (const Standard_Failure&) {
    return false;
  }
}

// The solid a closed shell bounds, with matter inside it; null if OCCT cannot orient it.
TopoDS_Solid solidOf(const TopoDS_Shell& shell) {
  try {
    BRepBuilderAPI_MakeSolid make(shell);
    if (!make.IsDone()) return {};
    TopoDS_Solid solid = make.Solid();
    if (!BRepLib::OrientClosedSolid(solid)) return {};
    return solid;
  } catch (const Standard_Failure&) {
    return {};
  }
}

// The shell of a one-shell solid, with the orientation it has in it.
TopoDS_Shape orientedShell(const TopoDS_Solid& solid) {
  TopExp_Explorer e(solid, TopAbs_SHELL);
  return e.Current();
}

double volumeOf(const TopoDS_Shape& solid) {
  GProp_GProps props;
  BRepGProp::VolumeProperties(solid, props);
  return props.Mass();
}

// Whether shell a lies inside the solid of shell b: one of a's vertices is
// strictly inside (shells from one sewing do not cross; a vertex on b's
// surface, where they touch, does not count).
bool inside(const ClosedShell& a, const ClosedShell& b, double tolerance) {
  BRepClass3d_SolidClassifier classifier(b.alone);
  for (TopExp_Explorer v(a.shell, TopAbs_VERTEX); v.More(); v.Next()) {
    classifier.Perform(BRep_Tool::Pnt(TopoDS::Vertex(v.Current())), tolerance);
    if (classifier.State() == TopAbs_IN) return true;
    if (classifier.State() == TopAbs_OUT) return false;
  }
  return false;
}

}  // namespace

std::vector<TopoDS_Solid> solidsSewnFromFaces(const TopoDS_Shape& shape, SewingOutcome* outcome) {
  SewingOutcome local;
  SewingOutcome& out = outcome ? *outcome : local;
  out = SewingOutcome{};
  Bnd_Box box;
  for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) {
    ++out.faces;
    BRepBndLib::Add(f.Current(), box);
  }
  if (out.faces == 0 || box.IsVoid()) return {};
  const double diagonal = std::sqrt(box.SquareExtent());
  out.tried = true;

  std::vector<ClosedShell> closed;
  for (double fraction : {1e-6, 1e-4}) {
    out.tolerance = fraction * diagonal;
    closed.clear();
    out.openShells = 0;
    try {
      BRepBuilderAPI_Sewing sewing(out.tolerance);
      for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) sewing.Add(f.Current());
      sewing.Perform();
      const TopoDS_Shape sewn = sewing.SewedShape();
      std::vector<TopoDS_Shell> shells;
      for (TopExp_Explorer s(sewn, TopAbs_SHELL); s.More(); s.Next()) shells.push_back(TopoDS::Shell(s.Current()));
      // The sewing leaves a face that joins no other on its own, outside any
      // shell; one closed by itself (a sphere, a torus) is a shell of one face.
      for (TopExp_Explorer f(sewn, TopAbs_FACE, TopAbs_SHELL); f.More(); f.Next()) {
        BRep_Builder builder;
        TopoDS_Shell shell;
        builder.MakeShell(shell);
        builder.Add(shell, f.Current());
        shells.push_back(shell);
      }
      for (const TopoDS_Shell& shell : shells) {
        const TopoDS_Solid solid = isClosed(shell) ? solidOf(shell) : TopoDS_Solid();
        if (solid.IsNull()) {
          ++out.openShells;
          continue;
        }
        closed.push_back({shell, solid, std::abs(volumeOf(solid))});
      }
    } catch (const Standard_Failure&) {
      closed.clear();
    }
    if (!closed.empty()) break;
  }
  out.closedShells = static_cast<int>(closed.size());
  if (closed.empty()) return {};

  // Nesting: a shell's container is the smallest shell around it; shells at
  // odd depth are voids of their container (at even depth, a solid of their
  // own inside a void). Quadratic in the shells, which are few; past 100
  // each closed shell is taken as a solid of its own.
  if (closed.size() <= 100) {
    for (std::size_t a = 0; a < closed.size(); ++a)
      for (std::size_t b = 0; b < closed.size(); ++b) {
        if (a == b || !(closed[b].volume > closed[a].volume) || !inside(closed[a], closed[b], out.tolerance)) continue;
        ++closed[a].depth;
        if (closed[a].container < 0 || closed[b].volume < closed[closed[a].container].volume)
          closed[a].container = static_cast<int>(b);
      }
  }
  std::vector<TopoDS_Solid> solids;
  for (std::size_t a = 0; a < closed.size(); ++a) {
    if (closed[a].depth % 2 == 1) continue;  // a void, added to its container below
    std::vector<std::size_t> voids;
    for (std::size_t b = 0; b < closed.size(); ++b)
      if (closed[b].depth % 2 == 1 && closed[b].container == static_cast<int>(a)) voids.push_back(b);
    if (voids.empty()) {
      solids.push_back(closed[a].alone);
      continue;
    }
    // The outer shell as its solid alone orients it, each void's the other
    // way round (matter outside it); kept when the volume says both agree.
    try {
      BRep_Builder builder;
      TopoDS_Solid solid;
      builder.MakeSolid(solid);
      builder.Add(solid, orientedShell(closed[a].alone));
      double volume = closed[a].volume;
      for (std::size_t b : voids) {
        builder.Add(solid, orientedShell(closed[b].alone).Reversed());
        volume -= closed[b].volume;
      }
      if (std::abs(volumeOf(solid) - volume) <= 1e-6 * closed[a].volume) {
        solids.push_back(solid);
        out.voids += static_cast<int>(voids.size());
        continue;
      }
    } catch (const Standard_Failure&) {
    }
    // Not orientable with its voids: the outer shell alone, voids as solids.
    solids.push_back(closed[a].alone);
    for (std::size_t b : voids) solids.push_back(closed[b].alone);
  }
  return solids;
}

std::string describeSewing(const SewingOutcome& o) {
  std::ostringstream s;
  s << "sewn at tolerance " << o.tolerance << ": " << o.faces << " face(s) closed " << o.closedShells
    << " shell(s)";
  if (o.voids > 0) s << " (" << o.voids << " of them void(s))";
  if (o.openShells > 0) s << ", " << o.openShells << " left open";
  return s.str();
}

}  // namespace cadmedial
