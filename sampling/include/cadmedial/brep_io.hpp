// Reading CAD files into OCCT solids, with errors a user can act on.
#pragma once

#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>
#include <TopoDS_Solid.hxx>

namespace cadmedial {

// What a file held besides its closed solids (for messages and summaries).
struct ShapeCensus {
  int solids = 0;
  int closedSolids = 0;
  int shells = 0;
  int openShells = 0;
  int faces = 0;
  int looseShells = 0;  // shells not inside a solid
  int looseFaces = 0;   // faces not inside a shell
};

struct LoadedModel {
  std::string path;
  TopoDS_Shape shape;
  std::vector<TopoDS_Solid> solids;  // closed solids, in file order
  ShapeCensus census;
  std::vector<std::string> warnings;  // e.g. stray open shells that were ignored
};

// Reads .step/.stp/.iges/.igs/.brep (any case). Throws InputError with a
// one-line message and exit code: missing/unreadable/empty/corrupt file
// (kExitUnreadableInput) or no closed solid (kExitNoSolid, saying what was found).
LoadedModel loadModel(const std::string& path);

// Reads a shape from BREP text (as FreeCAD's exportBrepToString writes it).
TopoDS_Shape readBrepString(const std::string& brepText);

// Counts solids / shells / faces of a shape.
ShapeCensus takeCensus(const TopoDS_Shape& shape);

// Closed solids of a shape (a solid whose shells have no free edge). A solid
// BRepCheck rejects is replaced by its ShapeFix repair when that is one
// closed solid of the same area that passes BRepCheck, else kept as it is;
// either way a warning says so. A shape with no closed solid (IGES trimmed
// surfaces, a STEP surface model, loose faces) has its faces sewn
// (sewn_solids.hpp): each closed shell becomes a solid, a warning says so,
// and *sewing gets one clause on what the sewing did (also when nothing
// closed, for the caller's error message). A solid reaching coordinates
// beyond 2e100 (Precision::Infinite; a malformed file) is skipped with a
// warning; when that leaves none, the faces are not sewn but refused:
// InputError (kExitUnreadableInput). The solids' plane faces get their
// edges' (u, v) curves stored (the projection OCCT would otherwise make on
// every call): this edits the shape's edges, so pass a shape this call may
// change (one read from a file or BREP text), and not one another thread is
// reading; written out with BRepTools it then holds those curves too.
std::vector<TopoDS_Solid> closedSolidsOf(const TopoDS_Shape& shape, std::vector<std::string>* warnings = nullptr,
                                         std::string* sewing = nullptr);

}  // namespace cadmedial
