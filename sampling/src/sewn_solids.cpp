#include "sewn_solids.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepCheck_Shell.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepGProp.hxx>
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

// A closed shell oriented so that the matter is inside it, and its solid alone.
struct ClosedShell {
  TopoDS_Shape shell;  // with the orientation it has in `alone`
  TopoDS_Solid alone;
  double volume = 0;   // > 0
  Bnd_Box box;
  int valid = -1;      // BRepCheck accepts `alone` (1) or not (0), asked only of shells whose box nests
  int container = -1;  // the smallest other shell enclosing it
  int depth = 0;       // how many shells enclose it
};

double volumeOf(const TopoDS_Shape& solid) {
  GProp_GProps props;
  BRepGProp::VolumeProperties(solid, props);
  return props.Mass();
}

// The solid a shell bounds, oriented by the sign of its volume (a closed,
// consistently oriented shell's volume is the enclosed volume, negative
// when the faces point inward), or null when the shell is open, its faces
// are not oriented alike, or it encloses nothing.
TopoDS_Solid solidOf(const TopoDS_Shell& shell) {
  try {
    BRepCheck_Shell check(shell);
    if (check.Closed() != BRepCheck_NoError || check.Orientation() != BRepCheck_NoError) return {};
    BRep_Builder builder;
    TopoDS_Solid solid;
    builder.MakeSolid(solid);
    builder.Add(solid, shell);
    const double volume = volumeOf(solid);
    if (!std::isfinite(volume) || volume == 0) return {};
    if (volume < 0) solid.Reverse();
    return solid;
  } catch (const Standard_Failure&) {
    return {};
  }
}

// The shells of a sewing's result. A face that joins no other is left
// outside any shell; one closed by itself (a sphere, a torus) is a shell of
// one face.
std::vector<TopoDS_Shell> shellsOf(const TopoDS_Shape& sewn) {
  std::vector<TopoDS_Shell> shells;
  for (TopExp_Explorer s(sewn, TopAbs_SHELL); s.More(); s.Next()) shells.push_back(TopoDS::Shell(s.Current()));
  for (TopExp_Explorer f(sewn, TopAbs_FACE, TopAbs_SHELL); f.More(); f.Next()) {
    BRep_Builder builder;
    TopoDS_Shell shell;
    builder.MakeShell(shell);
    builder.Add(shell, f.Current());
    shells.push_back(shell);
  }
  return shells;
}

struct Pass {
  std::vector<ClosedShell> closed;
  int openShells = 0;
};

Pass sewAt(const TopoDS_Shape& shape, double tolerance) {
  Pass pass;
  BRepBuilderAPI_Sewing sewing(tolerance);
  for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) sewing.Add(f.Current());
  sewing.Perform();
  for (const TopoDS_Shell& shell : shellsOf(sewing.SewedShape())) {
    const TopoDS_Solid solid = solidOf(shell);
    if (solid.IsNull()) {
      ++pass.openShells;
      continue;
    }
    ClosedShell c;
    c.alone = solid;
    c.shell = TopExp_Explorer(solid, TopAbs_SHELL).Current();
    c.volume = std::abs(volumeOf(solid));
    BRepBndLib::Add(solid, c.box);
    pass.closed.push_back(c);
  }
  return pass;
}

bool boxInside(const Bnd_Box& a, const Bnd_Box& b) {
  double a0[3], a1[3], b0[3], b1[3];
  a.Get(a0[0], a0[1], a0[2], a1[0], a1[1], a1[2]);
  b.Get(b0[0], b0[1], b0[2], b1[0], b1[1], b1[2]);
  for (int k = 0; k < 3; ++k)
    if (a0[k] < b0[k] || a1[k] > b1[k]) return false;
  return true;
}

// Whether BRepCheck accepts a shell's solid (the classifier can hang on
// others), asked once and only of shells in a nesting test.
bool isValid(ClosedShell& c) {
  if (c.valid < 0) {
    try {
      c.valid = BRepCheck_Analyzer(c.alone).IsValid() ? 1 : 0;
    } catch (const Standard_Failure&) {
      c.valid = 0;
    }
  }
  return c.valid == 1;
}

// Whether shell a may lie inside shell b: smaller, its box inside b's, both solids valid.
bool mayNest(ClosedShell& a, ClosedShell& b) {
  return b.volume > a.volume && boxInside(a.box, b.box) && isValid(a) && isValid(b);
}

// Whether every vertex of a that is not on b's surface (where they touch)
// is inside b, at least one of them: shells that cross (overlapping bodies
// of a surface model) are not nested.
bool verticesInside(const ClosedShell& a, BRepClass3d_SolidClassifier& inB, double tolerance) {
  bool anyIn = false;
  for (TopExp_Explorer v(a.shell, TopAbs_VERTEX); v.More(); v.Next()) {
    inB.Perform(BRep_Tool::Pnt(TopoDS::Vertex(v.Current())), tolerance);
    const TopAbs_State state = inB.State();
    if (state == TopAbs_IN) anyIn = true;
    else if (state != TopAbs_ON) return false;
  }
  return anyIn;
}

}  // namespace

std::vector<TopoDS_Solid> solidsSewnFromFaces(const TopoDS_Shape& shape, SewingOutcome* outcome) {
  SewingOutcome local;
  SewingOutcome& out = outcome ? *outcome : local;
  out = SewingOutcome{};
  try {
    Bnd_Box box;
    for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) {
      ++out.faces;
      BRepBndLib::Add(f.Current(), box);
    }
    if (out.faces == 0 || box.IsVoid() || box.IsOpen()) return {};  // nothing to sew, or unbounded faces
    const double diagonal = std::sqrt(box.SquareExtent());
    if (!std::isfinite(diagonal) || !(diagonal > 0)) return {};
    out.tried = true;

    // The finer tolerance first; the coarser one when shells stay open
    // there, keeping the pass that leaves fewer open (a sphere face closes
    // by itself at any tolerance while the rest may need the coarser one).
    Pass best;
    for (double fraction : {1e-6, 1e-4}) {
      const double tolerance = fraction * diagonal;
      Pass pass;
      try {
        pass = sewAt(shape, tolerance);
      } catch (const Standard_Failure&) {
        continue;
      }
      if (out.tolerance == 0 || pass.openShells < best.openShells ||
          (pass.openShells == best.openShells && pass.closed.size() > best.closed.size())) {
        best = std::move(pass);
        out.tolerance = tolerance;
      }
      if (best.openShells == 0 && !best.closed.empty()) break;
    }
    std::vector<ClosedShell>& closed = best.closed;
    out.closedShells = static_cast<int>(closed.size());
    out.openShells = best.openShells;
    if (closed.empty()) return {};

    // Nesting: a shell's container is the smallest shell around it, its
    // depth how many enclose it. Odd depth: a void of its container; even
    // depth: a solid of its own (inside a void, or outside everything).
    for (std::size_t b = 0; b < closed.size(); ++b) {
      std::unique_ptr<BRepClass3d_SolidClassifier> inB;  // built once, only when some box fits in b's
      for (std::size_t a = 0; a < closed.size(); ++a) {
        if (a == b || !mayNest(closed[a], closed[b])) continue;
        if (!inB) inB = std::make_unique<BRepClass3d_SolidClassifier>(closed[b].alone);
        if (!verticesInside(closed[a], *inB, out.tolerance)) continue;
        ++closed[a].depth;
        if (closed[a].container < 0 || closed[b].volume < closed[closed[a].container].volume)
          closed[a].container = static_cast<int>(b);
      }
    }
    // A void needs a container one level up; an inconsistent nesting (the
    // container's depth is not one less) leaves the shell a solid of its own.
    auto isVoid = [&](std::size_t a) {
      const int c = closed[a].container;
      return closed[a].depth % 2 == 1 && c >= 0 && closed[c].depth == closed[a].depth - 1;
    };
    std::vector<TopoDS_Solid> solids;
    for (std::size_t a = 0; a < closed.size(); ++a) {
      if (isVoid(a)) continue;  // added to its container below
      BRep_Builder builder;
      TopoDS_Solid solid;
      builder.MakeSolid(solid);
      builder.Add(solid, closed[a].shell);
      for (std::size_t b = 0; b < closed.size(); ++b)
        if (isVoid(b) && closed[b].container == static_cast<int>(a)) {
          builder.Add(solid, closed[b].shell.Reversed());  // matter outside it
          ++out.voids;
        }
      solids.push_back(solid);
    }
    return solids;
  } catch (const Standard_Failure&) {
    return {};
  }
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
