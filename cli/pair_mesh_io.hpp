// Files of the pair-mesh (`cadmedial run --pair-mesh`), each written atomically:
//   pairmesh.vtu        VTK XML unstructured grid (ParaView): tetrahedra with
//                       cell data `type` (0 face-vertex, 1 edge-edge,
//                       2 vertex-face) and `on_sheets` (1 if its medial simplex
//                       is on the CAD_MEDIAL inner sheets), point data
//                       `boundary` (1 for samples, 0 for Voronoi nodes);
//   pairmesh.node/.ele  TetGen: nodes with boundary marker, tetrahedra with
//                       the type as region attribute (0-based indices);
//   iso_<t>.ply         the iso-parametric surface at t.
// readPairMeshTetgen reads .node/.ele back (for `cadmedial eval`), rebuilding
// the boundary triangles from the Vertex-Face elements.
#pragma once

#include <string>

#include "cadmedial/pair_mesh.hpp"

namespace cadmedial {

void writePairMeshVtu(const std::string& path, const PairMesh& mesh);
void writePairMeshTetgen(const std::string& basePath, const PairMesh& mesh);  // basePath + ".node" / ".ele"
void writeIsoSurfacePly(const std::string& path, const IsoSurface& surface);
// "iso_0.5.ply" for t = 0.5.
std::string isoSurfaceFileName(double t);

// Throws InputError(kExitBadInput) on a missing or malformed file.
PairMesh readPairMeshTetgen(const std::string& basePath);

}  // namespace cadmedial
