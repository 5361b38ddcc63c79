// OBJ and Q-MAT/MATFP `.ma` forms of the inner medial axis (medial.ply is in
// medial_ply_io.hpp).
#pragma once

#include <ostream>

#include "cadmedial/polygon_complex.hpp"

namespace cadmedial {

// Wavefront OBJ: vertices, polygons grouped per sheet (`g sheet_<id>`); the
// medial radius is not part of OBJ and is written as a comment per vertex.
void writeMedialObj(std::ostream& out, const MedialComplex& complex);

// Plain-text medial mesh of Q-MAT/MATFP: "nv ne nf", then "v x y z r" lines,
// "e i j" lines (every distinct edge of the fan-triangulated polygons) and
// "f i j k" lines (0-based).
void writeMedialMa(std::ostream& out, const MedialComplex& complex);

// Both at once, as the CLI writes them: each vertex's numbers are formatted
// once for the two files' vertex lines.
void writeMedialObjAndMa(std::ostream& obj, std::ostream& ma, const MedialComplex& complex);

}  // namespace cadmedial
