// The evaluation's plain mesh form (MedialMesh, what medial.ply holds) of
// core's medial complex.
#pragma once

// CGAL (core) before OCCT (sampling): OCCT's Handle macro breaks CGAL.
#include "cadmedial/polygon_complex.hpp"
#include "cadmedial/medial_evaluation.hpp"

namespace cadmedial {

inline MedialMesh toMedialMesh(const MedialComplex& c) {
  MedialMesh mesh;
  mesh.vertices = c.vertices;
  mesh.radius = c.radius;
  mesh.polygonOffsets = c.polygonOffsets;
  mesh.polygonVertices = c.polygonVertices;
  mesh.sheet.assign(c.sheet.begin(), c.sheet.end());
  mesh.provenance.reserve(c.provenance.size());
  for (PolygonProvenance p : c.provenance) mesh.provenance.push_back(static_cast<MedialProvenance>(p));
  return mesh;
}

}  // namespace cadmedial
