// Solids made from loose faces: files without a solid in them (IGES trimmed
// surfaces without a B-rep solid entity, STEP surface models, a solid's
// faces exported one by one) whose faces close up once sewn.
#pragma once

#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>
#include <TopoDS_Solid.hxx>

namespace cadmedial {

struct SewingOutcome {
  bool tried = false;
  double tolerance = 0;   // the last tolerance tried (model units)
  int faces = 0;          // faces given to the sewing
  int closedShells = 0;   // closed shells it made (outer and void)
  int openShells = 0;     // shells it left open (ignored)
  int voids = 0;          // closed shells inside another, made its void
};

// Sews every face of the shape at 1e-6 of the faces' bounding-box diagonal,
// and at 1e-4 when shells stay open there (the pass leaving fewer open is
// kept), and makes a solid of each closed, consistently oriented shell,
// matter inside. A closed shell inside another (box inside, every vertex
// not on it inside) becomes that solid's void; shells that cross stay
// solids of their own. Nothing here throws; an empty result when no shell
// closes. The solids are not checked further here.
std::vector<TopoDS_Solid> solidsSewnFromFaces(const TopoDS_Shape& shape, SewingOutcome* outcome);

// One clause for messages: "sewn at tolerance T: N face(s) closed M shell(s), K left open".
std::string describeSewing(const SewingOutcome& outcome);

}  // namespace cadmedial
