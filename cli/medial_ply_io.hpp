// The medial mesh file `cadmedial run` writes per solid (OUTDIR/solid_<i>/medial.ply)
// and `cadmedial eval` reads: ASCII PLY, readable by MeshLab and ParaView.
//
//   element vertex N: property double x, y, z, radius   (medial radius)
//   element face M:   property list uchar int vertex_indices,
//                     property int sheet, property uchar provenance
//                     (0 Voronoi facet of a Delaunay edge, 1 convex-edge triangle,
//                      2 convex-edge fill triangle, 3 corner triangle, 4 short hole closed)
#pragma once

#include <istream>
#include <ostream>
#include <string>

#include "cadmedial/medial_evaluation.hpp"

namespace cadmedial {

// Doubles are written as the shortest text that reads back to the same
// double (std::to_chars), so a read gives back the same numbers. Throws
// std::invalid_argument if the mesh is inconsistent.
void writeMedialPly(std::ostream& out, const MedialMesh& mesh);

// Through writeFileAtomically (a killed run leaves no half-written file).
void writeMedialPlyFile(const std::string& path, const MedialMesh& mesh);

// Strict reader of exactly the layout above (comment / obj_info lines are
// allowed in the header). Anything else - missing or reordered properties,
// wrong counts, bad numbers, indices out of range, trailing data - throws
// InputError(kExitUnreadableInput) with "<name>: line <n>: <what>".
MedialMesh readMedialPly(std::istream& in, const std::string& name);
MedialMesh readMedialPlyFile(const std::string& path);

}  // namespace cadmedial
